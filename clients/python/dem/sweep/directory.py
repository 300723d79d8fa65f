"""A sweep as a directory, which every backend and the task script share
(docs/SWEEPS.md):

    sweep.json            the definition: name, domain, parameters, each task's values
    sweep.conf            KEY=VALUE for scripts/slurm/dem_sweep_task.sh
    base.case.txtpb       the base case
    cases/NNNN.case.txtpb one case per task
    dem_sweep_task.sh     the task script, copied (every backend runs this copy)
    tasks/NNNN/           a task's task.status, task.lock, dem_server.log and
                          <case name>/ (tables, final.snapshot, checkpoints)
    logs/                 the task script's output (Slurm's slurm-<job>_<task>.out, local-NNNN.out)
    submissions.jsonl     one line per submission: backend, job, tasks
    summary.csv           the results' summary table (Sweep.results)

The directory is the sweep's whole state: a sweep interrupted anywhere -
the submitting script killed, tasks cancelled, a node lost - is continued
by opening it and running it again, which submits only the tasks that are
not done and not running (a running task holds its lock).
"""

import datetime
import fcntl
import hashlib
import json
import os
import pathlib
import re
import shutil
import time

from .. import _build_info, cases as case_files, paths
from ..errors import DemError
from .parameters import build_case, combinations, parameters_from

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,58}")
# A task's states: pending (never started), running (its lock is held),
# done, failed, stopped (ended before its programme's end: a signal, a
# stop command, a time limit), interrupted (says running but nobody holds
# its lock: the process was killed). Only done is finished.
STATES = ("pending", "running", "done", "failed", "stopped", "interrupted")


class TaskStatus:
    """What a task's directory says of it."""

    def __init__(self, sweep, index):
        self.index = index
        self.values = sweep.tasks[index]
        self.directory = sweep.task_dir(index)
        self.server = sweep.server_name(index)
        fields = _read_key_values(self.directory / "task.status")
        self.exit_code = int(fields["exit_code"]) if fields.get("exit_code", "").lstrip("-").isdigit() else None
        self.attempt = int(fields.get("attempt") or 0)
        self.host = fields.get("host", "")
        self.resumed = fields.get("resumed") == "yes"
        self.started = fields.get("started", "")
        self.ended = fields.get("ended", "")
        self.slurm_job = fields.get("slurm_job", "")
        self.error = fields.get("error", "")  # the task script's own error, before the server ran
        state = fields.get("state", "pending")
        locked = _lock_held(self.directory / "task.lock")
        if locked:
            state = "running"
        elif state == "running":
            state = "interrupted"
        self.state = state

    @property
    def finished(self):
        return self.state == "done"

    def output_dir(self):
        """tasks/NNNN/<case name>/: the server's tables and snapshots (None before it ran)."""
        if not self.directory.is_dir():
            return None
        found = sorted(p for p in self.directory.iterdir() if p.is_dir())
        return found[0] if found else None

    def log_tail(self, lines=10):
        """The last lines of the task's dem_server.log (or the task script's error)."""
        try:
            text = (self.directory / "dem_server.log").read_text(errors="replace")
        except OSError:
            return f"dem_sweep_task: {self.error}" if self.error else ""
        return "\n".join(text.rstrip().splitlines()[-lines:])

    def __repr__(self):
        code = f", exit {self.exit_code}" if self.exit_code is not None else ""
        return f"<task {self.index:04d} {self.values} {self.state}{code}>"


class Progress:
    """A sweep at one moment: each task's status, and for those running the
    live status their servers publish (when asked for)."""

    def __init__(self, sweep, statuses, live=None):
        self.sweep = sweep
        self.tasks = statuses
        self.live = live or {}  # index -> dem.Status
        self.counts = {state: sum(t.state == state for t in statuses) for state in STATES}

    @property
    def finished(self):
        return all(t.finished for t in self.tasks)

    def __str__(self):
        parts = [f"{n} {state}" for state, n in self.counts.items() if n]
        running = []
        for task in self.tasks:
            status = self.live.get(task.index)
            if task.state == "running" and status is not None:
                running.append(f"{task.index:04d} cycle {status.cycle}")
        if len(running) > 6:
            running = running[:6] + [f"{len(running) - 6} more"]
        text = f"{self.sweep.name}: {len(self.tasks)} tasks: " + ", ".join(parts)
        return text + (f" ({'; '.join(running)})" if running else "")


class Sweep:
    """A sweep directory (Sweep.create makes one, Sweep.open reads one)."""

    def __init__(self, directory):
        self.directory = pathlib.Path(directory).resolve()
        try:
            self.definition = json.loads((self.directory / "sweep.json").read_text())
        except FileNotFoundError:
            raise DemError(f"{self.directory} is not a sweep directory (no sweep.json)") from None
        self.conf = _read_key_values(self.directory / "sweep.conf")
        self.name = self.definition["name"]
        self.domain = int(self.definition["domain"])
        self.parameters = self.definition["parameters"]
        self.tasks = [task["values"] for task in self.definition["tasks"]]

    @classmethod
    def open(cls, directory):
        return cls(directory)

    @classmethod
    def create(cls, directory, base, parameters, *, name=None, domain=0, combine="grid", threads=1,
               telemetry_cycles=100, checkpoint_cycles=0, checkpoint_seconds=0.0, log_level="info",
               server_program=None, dds_config=None):
        """Writes a sweep: the base case (a dem.cases.Case, or a case file:
        its particle files are then found from its directory) with
        `parameters` ({path: values} or [dem.sweep.Parameter]) set to each
        combination of their values. Opening an existing directory of the
        same definition returns it as it stands (so a script that made a
        sweep continues it when run again); a different one is an error."""
        directory = pathlib.Path(directory).resolve()
        if isinstance(base, (str, os.PathLike)):
            base_file = pathlib.Path(base).resolve()
            base = case_files.load_case_file(base_file)
            _absolute_particle_files(base, base_file.parent)
        else:
            _absolute_particle_files(base, pathlib.Path.cwd())
        name = name or re.sub(r"[^A-Za-z0-9_]", "_", directory.name)
        if not _NAME.fullmatch(name):
            raise ValueError(f"sweep name {name!r}: a letter, then letters, digits or underscores (at most 59), "
                             "as its servers are named <name>_NNNN")
        if not 0 <= domain <= 232:
            raise ValueError(f"domain {domain}: DDS domain ids are 0 to 232")
        parameters = parameters_from(parameters)
        values = combinations(parameters, combine)
        cases = [build_case(base, parameters, v) for v in values]
        base_text = case_files.to_text(base)
        definition = {
            "format": 1,
            "name": name,
            "domain": domain,
            "combine": combine,
            "base_case_sha256": hashlib.sha256(base_text.encode()).hexdigest(),
            "parameters": [p.describe() for p in parameters],
            "tasks": [{"index": i, "values": v} for i, v in enumerate(values)],
        }
        conf = {
            "name": name,
            "domain": domain,
            "tasks": len(values),
            "server_program": pathlib.Path(server_program or paths.server_program()).resolve(),
            "dds_config": dds_config if dds_config is not None else paths.use_loopback(),
            "threads": threads,
            "telemetry_cycles": telemetry_cycles,
            "checkpoint_cycles": checkpoint_cycles,
            "checkpoint_seconds": _number_text(checkpoint_seconds),
            "log_level": log_level,
        }
        existing = directory / "sweep.json"
        if existing.exists():
            old = json.loads(existing.read_text())
            same = {k: v for k, v in old.items() if k not in ("created", "dem_version")} == definition
            if not same:
                raise DemError(f"{directory} holds another sweep ({old.get('name')}, {len(old.get('tasks', []))} "
                               "tasks, other parameters or another base case): choose another directory")
            for index, case in enumerate(cases):  # the cases as written, unless a user mended one since
                if not (directory / "cases" / f"{index:04d}.case.txtpb").exists():
                    case_files.save_case_file(case, directory / "cases" / f"{index:04d}.case.txtpb")
            return cls(directory)
        for sub in ("cases", "tasks", "logs"):
            (directory / sub).mkdir(parents=True, exist_ok=True)
        (directory / "base.case.txtpb").write_text(base_text)
        for index, case in enumerate(cases):
            case_files.save_case_file(case, directory / "cases" / f"{index:04d}.case.txtpb")
        script = directory / "dem_sweep_task.sh"
        shutil.copyfile(paths.sweep_task_script(), script)
        script.chmod(0o755)
        (directory / "sweep.conf").write_text(
            "# Read by dem_sweep_task.sh (docs/SWEEPS.md); written by dem.sweep.\n"
            + "".join(f"{key}={value}\n" for key, value in conf.items()))
        definition["created"] = datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")
        definition["dem_version"] = _build_info.VERSION
        # sweep.json last: a directory without it is not a sweep yet.
        _write_atomically(existing, json.dumps(definition, indent=1) + "\n")
        return cls(directory)

    # --- where things are ---------------------------------------------------
    def task_dir(self, index):
        return self.directory / "tasks" / f"{index:04d}"

    def case_file(self, index):
        return self.directory / "cases" / f"{index:04d}.case.txtpb"

    def case(self, index):
        return case_files.load_case_file(self.case_file(index))

    def server_name(self, index):
        """The name of the task's server on the sweep's DDS domain."""
        return f"{self.name}_{index:04d}"

    @property
    def task_script(self):
        return self.directory / "dem_sweep_task.sh"

    @property
    def dds_config(self):
        return self.conf.get("dds_config", "")

    # --- state -------------------------------------------------------------
    def status(self, tasks=None):
        """Each task's TaskStatus (all, or those of the indices given)."""
        indices = range(len(self.tasks)) if tasks is None else tasks
        return [TaskStatus(self, self._index(i)) for i in indices]

    def unfinished(self):
        """The tasks to run: not done, and not running now."""
        return [t.index for t in self.status() if t.state not in ("done", "running")]

    def failed(self):
        """The tasks that failed (TaskStatus; .log_tail() says why)."""
        return [t for t in self.status() if t.state == "failed"]

    def progress(self, live=False):
        """A Progress; live: with the running servers' own status over DDS."""
        statuses = self.status()
        found = {}
        if live and any(t.state == "running" for t in statuses):
            from ..client import list_servers
            prefix = self.name + "_"
            for server, status in list_servers(self.domain, dds_config=self.dds_config, discovery=0.5):
                if server.startswith(prefix) and server[len(prefix):].isdigit() and status is not None:
                    found[int(server[len(prefix):])] = status
        return Progress(self, statuses, found)

    # --- running -----------------------------------------------------------
    def submit(self, backend, tasks=None):
        """Hands tasks (default: the unfinished ones, less those the backend
        still holds from an earlier submission) to a backend; returns its
        handle (.done(), .cancel()), or None when there is nothing to run."""
        if tasks is None:
            held = set(backend.active(self))
            tasks = [i for i in self.unfinished() if i not in held]
        tasks = sorted({self._index(i) for i in tasks})
        if not tasks:
            return None
        handle = backend.submit(self, tasks)
        with open(self.directory / "submissions.jsonl", "a") as log:
            log.write(json.dumps({"time": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
                                  "backend": backend.kind, "job": getattr(handle, "job", None),
                                  "tasks": tasks}) + "\n")
        return handle

    def wait(self, handle, on_progress=None, poll=2.0, live=True, timeout=None):
        """Waits until the handle's tasks have ended and no task of the sweep
        runs; on_progress(Progress) whenever the picture changes. Returns
        the last Progress. Ctrl-C cancels what the backend can cancel (local
        tasks stop with a final snapshot; Slurm jobs are left running)."""
        deadline = None if timeout is None else time.monotonic() + timeout
        shown = None
        try:
            while True:
                ended = handle is None or handle.done()
                progress = self.progress(live=live and not ended)
                summary = str(progress)
                if on_progress is not None and summary != shown:
                    on_progress(progress)
                    shown = summary
                if ended and not progress.counts["running"]:
                    if hasattr(handle, "check"):
                        handle.check()
                    return progress
                if deadline is not None and time.monotonic() > deadline:
                    raise TimeoutError(f"sweep {self.name} still running after {timeout} s: {summary}")
                time.sleep(poll)
        except KeyboardInterrupt:
            if handle is not None:
                handle.interrupted()
            raise

    def run(self, backend, tasks=None, *, wait=True, on_progress=print, poll=2.0, live=True, timeout=None):
        """submit, then (wait=True) wait; returns the Progress at the end (or
        the handle when not waiting)."""
        handle = self.submit(backend, tasks)
        if not wait:
            return handle
        return self.wait(handle, on_progress=on_progress, poll=poll, live=live, timeout=timeout)

    def results(self, plate=None, write_summary=True):
        """The tables of every task gathered (dem.sweep.Results)."""
        from .results import Results
        results = Results(self, plate=plate)
        if write_summary:
            results.write_summary(self.directory / "summary.csv")
        return results

    def submissions(self):
        """The submissions so far (submissions.jsonl), oldest first."""
        try:
            lines = (self.directory / "submissions.jsonl").read_text().splitlines()
        except FileNotFoundError:
            return []
        return [json.loads(line) for line in lines if line.strip()]

    def _index(self, index):
        index = int(index)
        if not 0 <= index < len(self.tasks):
            raise IndexError(f"sweep {self.name} has tasks 0 to {len(self.tasks) - 1}, not {index}")
        return index

    def __repr__(self):
        return f"<dem.sweep.Sweep {self.name} at {self.directory}: {len(self.tasks)} tasks>"


def _number_text(value):
    """0 for 0.0, 2.5 for 2.5: what the task script reads."""
    return int(value) if float(value) == int(value) else float(value)


def _read_key_values(path):
    try:
        lines = pathlib.Path(path).read_text().splitlines()
    except FileNotFoundError:
        return {}
    pairs = (line.split("=", 1) for line in lines if "=" in line and not line.lstrip().startswith("#"))
    return {key.strip(): value for key, value in pairs}


def _lock_held(path):
    """Whether a task's script (or its server) holds task.lock. The probe
    takes a shared lock for an instant; the script waits a few seconds for
    its own, so a probe never makes a task fail to start."""
    try:
        descriptor = os.open(path, os.O_RDONLY)
    except FileNotFoundError:
        return False
    try:
        fcntl.flock(descriptor, fcntl.LOCK_SH | fcntl.LOCK_NB)
    except BlockingIOError:
        return True
    finally:
        os.close(descriptor)
    return False


def _absolute_particle_files(case, directory):
    """Particle files named relative to the case file, made absolute (the
    sweep's cases live elsewhere)."""
    for source in case.particles:
        if source.WhichOneof("source") == "csv_file" and source.csv_file.path:
            path = pathlib.Path(source.csv_file.path)
            if not path.is_absolute():
                source.csv_file.path = str((directory / path).resolve())


def _write_atomically(path, text):
    temporary = path.with_name(path.name + ".tmp")
    temporary.write_text(text)
    temporary.replace(path)
