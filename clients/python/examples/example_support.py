"""What the example scripts share: their common options, and the server they
drive - one they start themselves (a dem_server of this build on loopback,
stopped at the end) or, with --server, one already running."""

import argparse
import contextlib
import pathlib
import sys
import time

import dem
from dem import paths


def argument_parser(description, out, domain, telemetry_cycles=100):
    parser = argparse.ArgumentParser(description=description,
                                     formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path(out), help="directory for CSV and PNG files")
    parser.add_argument("--domain", type=int, default=domain, help="DDS domain id")
    parser.add_argument("--server", default=None,
                        help="drive this running dem_server instead of starting one (examples that have it "
                             "read a case file need it started with --read-dir covering the file)")
    parser.add_argument("--telemetry-cycles", type=int, default=telemetry_cycles,
                        help="telemetry interval of the server started here")
    return parser


def case_path(name):
    """A case of the repository by its path under cases/."""
    return paths.cases_dir() / name


@contextlib.contextmanager
def service(args, name, read_dirs=()):
    """A Client of the server the example drives; the one started here may
    also read cases from ``read_dirs`` (beside the current directory and the
    repository's cases/)."""
    dem.use_loopback()
    if args.server:
        with dem.Client(args.server, args.domain, timeout=20) as client:
            yield client
        return
    args.out.mkdir(parents=True, exist_ok=True)
    # The example's own scratch directory: a second run replaces the first's output.
    with dem.ServerProcess(name, args.domain, args.out / "server", telemetry_cycles=args.telemetry_cycles,
                           overwrite=True, read_dirs=[pathlib.Path.cwd(), paths.cases_dir(), *read_dirs]) as server:
        with server.connect() as client:
            yield client


class Stopwatch:
    def __init__(self):
        self.start = time.monotonic()

    def __str__(self):
        return f"{time.monotonic() - self.start:.1f} s"


def say(*words):
    print(*words, flush=True)


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    return 1
