"""python3 -m dem.sweep: a sweep directory from a shell (docs/SWEEPS.md).

    python3 -m dem.sweep status DIR            each task's state; failed tasks with their log's end
    python3 -m dem.sweep run DIR --backend local [--workers N] [--tasks 2,5-7]
    python3 -m dem.sweep run DIR --backend slurm [--sbatch-option=--time=1:00:00 ...] [--no-wait]
    python3 -m dem.sweep run DIR --backend dask --scheduler tcp://HOST:8786
    python3 -m dem.sweep results DIR           writes DIR/summary.csv and prints it
    python3 -m dem.sweep packings CASE --out DIR [--packings 5] [--workers N] [--threads T]
                                               a Miyata case over packings, judged by dem_validate

run submits the tasks not done (or those of --tasks) and waits, printing
progress. Exit codes: 0 every task done, 1 some failed or are unfinished,
2 bad arguments or not a sweep directory.
"""

import argparse
import sys

from ..errors import DemError
from .backends import DaskBackend, LocalBackend, SlurmBackend
from .directory import Sweep
from . import packings as packings_command


def task_list(text):
    """"2,5-7" -> [2, 5, 6, 7]"""
    tasks = []
    for part in text.split(","):
        first, _, last = part.partition("-")
        tasks += list(range(int(first), int(last or first) + 1))
    return tasks


def print_status(sweep):
    statuses = sweep.status()
    names = [p["name"] for p in sweep.parameters]
    print(f"sweep {sweep.name} ({sweep.directory}), domain {sweep.domain}: {len(statuses)} tasks")
    print(f"{'task':>4}  {'  '.join(f'{n:>10}' for n in names)}  {'state':<11} {'exit':>4} {'tries':>5}  server")
    for task in statuses:
        values = "  ".join(f"{str(task.values[n]):>10}" for n in names)
        code = "" if task.exit_code is None else task.exit_code
        print(f"{task.index:>4}  {values}  {task.state:<11} {code:>4} {task.attempt:>5}  {task.server}")
    for task in statuses:
        if task.state == "failed":
            print(f"\ntask {task.index:04d} failed (exit {task.exit_code}); {task.directory}/dem_server.log ends:")
            print("  " + task.log_tail(8).replace("\n", "\n  "))
    return 0 if all(t.finished for t in statuses) else 1


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m dem.sweep", description=__doc__.splitlines()[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    status = commands.add_parser("status", help="each task's state")
    status.add_argument("directory")
    run = commands.add_parser("run", help="submit the unfinished tasks (or --tasks) and wait")
    run.add_argument("directory")
    run.add_argument("--backend", choices=("local", "slurm", "dask"), default="local")
    run.add_argument("--tasks", type=task_list, help="these tasks only, e.g. 2,5-7 (a resubmission)")
    run.add_argument("--workers", type=int, help="local: tasks at a time (default: cores / threads)")
    run.add_argument("--sbatch-option", action="append", default=[], help="slurm: an sbatch option (repeat)")
    run.add_argument("--max-running", type=int, help="slurm: tasks running at once (--array=...%%N)")
    run.add_argument("--scheduler", help="dask: the scheduler's address")
    run.add_argument("--no-wait", action="store_true", help="submit and return")
    run.add_argument("--poll", type=float, default=2.0, help="seconds between progress checks")
    results = commands.add_parser("results", help="gather the tables; write and print summary.csv")
    results.add_argument("directory")
    results.add_argument("--plate", help="the loading plate (default: the case's)")
    packings = commands.add_parser("packings", help="a plate loading case over packings, run and judged")
    packings.add_argument("case")
    packings.add_argument("--out", required=True, help="the sweep's directory (made, or continued)")
    packings.add_argument("--packings", type=int, default=5)
    packings.add_argument("--workers", type=int, help="packings at a time (default: cores / threads)")
    packings.add_argument("--threads", type=int, default=1, help="threads of each packing's server")
    packings.add_argument("--domain", type=int, default=0, help="the DDS domain of the tasks' servers")
    args = parser.parse_args(argv)
    if args.command == "packings":
        try:
            return packings_command.main(args)
        except (DemError, ValueError) as error:
            print(f"dem.sweep: {error}", file=sys.stderr)
            return 2

    try:
        sweep = Sweep.open(args.directory)
    except DemError as error:
        print(f"dem.sweep: {error}", file=sys.stderr)
        return 2
    if args.command == "status":
        return print_status(sweep)
    if args.command == "results":
        found = sweep.results(plate=args.plate)
        print((sweep.directory / "summary.csv").read_text(), end="")
        return 0 if all(state == "done" for state in found.states) else 1

    if args.no_wait and args.backend != "slurm":
        parser.error("--no-wait is for --backend slurm (local tasks and Dask futures end with this process)")
    if args.backend == "local":
        backend = LocalBackend(workers=args.workers)
    elif args.backend == "slurm":
        backend = SlurmBackend(options=args.sbatch_option, max_running=args.max_running)
    else:
        if not args.scheduler:
            parser.error("--backend dask needs --scheduler")
        backend = DaskBackend(args.scheduler)
    handle = sweep.submit(backend, args.tasks)
    if handle is None:
        print(f"sweep {sweep.name}: nothing to run")
    elif args.no_wait:
        print(f"sweep {sweep.name}: submitted" + (f" as job {handle.job}" if getattr(handle, "job", None) else ""))
        return 0
    else:
        sweep.wait(handle, on_progress=print, poll=args.poll)
    return print_status(sweep)


if __name__ == "__main__":
    sys.exit(main())
