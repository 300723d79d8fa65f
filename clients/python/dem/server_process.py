"""A dem_server process of this build, started and stopped from Python - for
examples and tests that drive a whole experiment on loopback.

    with dem.ServerProcess("press", domain=21, out="out/press") as server:
        with server.connect() as press:
            ...

Leaving the block stops the server with SIGTERM (it finishes its chunk of
cycles, writes its tables and exits 0; docs/SERVICE.md) and kills it if it
has not stopped within ``stop_timeout`` seconds.
"""

import os
import pathlib
import signal
import subprocess

from .client import Client
from .errors import DemError
from .paths import cases_dir, server_program, use_loopback


class ServerProcess:
    def __init__(self, name, domain, out, *, telemetry_cycles=100, threads=1, log_level="warn", log_file=None,
                 program=None, extra_arguments=(), stop_timeout=20.0, read_dirs=None, overwrite=False):
        self.name = name
        self.domain = domain
        self.out = pathlib.Path(out)
        self.log_file = pathlib.Path(log_file) if log_file else self.out / "dem_server.log"
        self.stop_timeout = stop_timeout
        self.arguments = [str(program or server_program()), "--name", name, "--domain", str(domain),
                          "--out", str(self.out), "--telemetry-cycles", str(telemetry_cycles),
                          "--threads", str(threads), "--log-level", log_level, *extra_arguments]
        # An earlier run's output in <out>/<case>/ is refused unless replaced (--overwrite).
        if overwrite:
            self.arguments.append("--overwrite")
        # The server reads cases by their path only from these (--read-dir):
        # by default the current directory and the repository's cases.
        for directory in read_dirs if read_dirs is not None else [pathlib.Path.cwd(), cases_dir()]:
            self.arguments += ["--read-dir", str(directory)]
        self.process = None
        self.exit_code = None

    def start(self):
        use_loopback()  # the server inherits CYCLONEDDS_URI
        self.out.mkdir(parents=True, exist_ok=True)
        self.log_file.parent.mkdir(parents=True, exist_ok=True)
        with open(self.log_file, "wb") as log:
            self.process = subprocess.Popen(self.arguments, stdout=log, stderr=subprocess.STDOUT,
                                            env=dict(os.environ, OMP_WAIT_POLICY="passive"))
        return self

    def connect(self, timeout=20.0, **options):
        """A Client of this server (connecting waits for it to come up)."""
        if self.process is None or self.process.poll() is not None:
            raise DemError(f"dem_server {self.name} is not running{self._log_tail()}")
        return Client(self.name, self.domain, timeout=timeout, **options)

    def stop(self):
        """SIGTERM, then SIGKILL after stop_timeout; returns the exit code."""
        if self.process is None:
            return None
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(self.stop_timeout)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.exit_code = self.process.returncode
        return self.exit_code

    def wait(self, timeout):
        """Waits for the process to end by itself (after a shutdown command)."""
        self.exit_code = self.process.wait(timeout)
        return self.exit_code

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.stop()

    def _log_tail(self):
        try:
            lines = self.log_file.read_text(errors="replace").strip().splitlines()[-5:]
        except OSError:
            return ""
        return (" (its log ends: " + " | ".join(lines) + ")") if lines else ""
