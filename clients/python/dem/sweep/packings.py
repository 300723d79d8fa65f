"""One case over several random packings, judged as a whole (Miyata et al.
2002 3.2-3.3; docs/VALIDATION.md): a sweep of the case's packing seed run on
a backend, then ``dem_validate miyata-compression --runs`` over the tasks'
tables, whose verdict asks every figure of the seed to hold in most
packings.

    python3 -m dem.sweep packings cases/miyata/ellipsoids.case.txtpb --out out/miyata_3d --packings 5

Interrupted, the same command continues the sweep where it stopped.
"""

import subprocess
import time

from .. import cases as case_files
from .. import paths
from .backends import LocalBackend
from .directory import Sweep


def packing_seeds(case_seed, count):
    """The case's own seed, then 1, 2, ... (as dem_validate's --packings)."""
    seeds = [case_seed] if count > 0 else []
    seed = 1
    while len(seeds) < count:
        if seed != case_seed:
            seeds.append(seed)
        seed += 1
    return seeds


def first_packing_seed(case):
    for source in case.particles:
        if source.HasField("random_packing"):
            return source.random_packing.seed
    raise ValueError("the case has no random_packing whose seed could be varied")


def run_packings(case_file, directory, packings=5, *, backend=None, threads=1, domain=0, on_progress=print,
                 checkpoint_seconds=300.0):
    """Makes (or continues) the sweep and runs it; returns the sweep."""
    case = case_files.load_case_file(case_file)
    seeds = packing_seeds(first_packing_seed(case), packings)
    sweep = Sweep.create(directory, case_file, {"particles[0].random_packing.seed": seeds},
                         name=f"{case.name}_packings"[:59], domain=domain, threads=threads,
                         checkpoint_seconds=checkpoint_seconds)
    started = time.monotonic()
    sweep.run(backend or LocalBackend(), on_progress=on_progress)
    on_progress(f"{sweep.name}: {len(seeds)} packings in {time.monotonic() - started:.0f} s")
    return sweep


def judge(sweep, case_file, program=None):
    """dem_validate miyata-compression --runs over the tasks' tables; its exit code."""
    runs = [str(task.output_dir()) for task in sweep.status()]
    command = [str(program or paths.validate_program()), "miyata-compression", "--case", str(case_file), "--runs",
               *runs]
    return subprocess.call(command)


def main(args):
    backend = LocalBackend(workers=args.workers)
    sweep = run_packings(args.case, args.out, args.packings, backend=backend, threads=args.threads,
                         domain=args.domain)
    unfinished = [task.index for task in sweep.status() if task.state != "done"]
    if unfinished:
        print(f"{sweep.name}: tasks {unfinished} did not finish; run the command again to continue them")
        return 1
    return judge(sweep, args.case)
