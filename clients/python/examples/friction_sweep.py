#!/usr/bin/python3
"""Miyata's uniaxial compression case CS swept over the friction
coefficient: a dem.sweep of the case, one task per friction (both materials,
rock and plate, so particle-particle and particle-plate contacts alike),
each run to the end of its programme by a one-shot dem_server - sample
rained and settled, trimmed, the plate lowered until it carries 900 kPa -
then the family of stress-settlement curves and the final measures.

The tasks run on a backend: local processes (default), a Slurm job array
(--backend slurm: the sweep directory must be on a file system the nodes
share) or a Dask cluster (--backend dask --scheduler ADDRESS). While they
run, `demctl --domain DOMAIN monitor --sweep cs_friction` follows every
server. Running the script again continues the sweep in --out where it
stopped: only tasks not done run (docs/SWEEPS.md).

Writes to --out:
  sweep/                          the sweep directory (cases, tasks' tables, summary.csv)
  stress_settlement_family.png    the loading plate's stress against settlement, one curve per friction
  final_measures.png              settlement at the end and the final state's secant stiffness against friction
  curves.csv                      the curves: friction, settlement, stress
"""

import csv
import pathlib
import sys

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

import dem
import dem.sweep
from dem.plots import plot_final_measure, plot_stress_settlement_family, save_png


def main():
    import argparse
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument("--case", default=str(dem.paths.cases_dir() / "miyata" / "cs.case.txtpb"),
                        help="the base case (cases/miyata/cs_reduced.case.txtpb runs in seconds)")
    parser.add_argument("--frictions", type=float, nargs="+", default=[0.2, 0.35, 0.51, 0.7],
                        help="the friction coefficients swept")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("out/python/friction_sweep"))
    parser.add_argument("--name", default="cs_friction", help="the sweep's name: its servers are NAME_NNNN")
    parser.add_argument("--domain", type=int, default=205, help="DDS domain of the tasks' servers")
    parser.add_argument("--backend", choices=("local", "slurm", "dask"), default="local")
    parser.add_argument("--workers", type=int, help="local: tasks at a time (default: the cores)")
    parser.add_argument("--sbatch-option", action="append", default=[], help="slurm: an sbatch option (repeat)")
    parser.add_argument("--scheduler", help="dask: the scheduler's address")
    args = parser.parse_args()

    sweep = dem.sweep.Sweep.create(args.out / "sweep", args.case, {"material[*].friction": args.frictions},
                                   name=args.name, domain=args.domain)
    print(f"{sweep}; follow it with: demctl --domain {args.domain} monitor --sweep {args.name}", flush=True)
    if args.backend == "local":
        backend = dem.sweep.LocalBackend(workers=args.workers)
    elif args.backend == "slurm":
        backend = dem.sweep.SlurmBackend(options=args.sbatch_option)
    else:
        if not args.scheduler:
            parser.error("--backend dask needs --scheduler")
        backend = dem.sweep.DaskBackend(args.scheduler)
    progress = sweep.run(backend, on_progress=lambda p: print(p, flush=True), poll=1.0)

    results = sweep.results()
    for task in sweep.failed():
        print(f"task {task.index:04d} (friction {task.values['friction']}) failed:\n  "
              + task.log_tail(5).replace("\n", "\n  "), file=sys.stderr)
    case_name = sweep.case(0).name
    plot_stress_settlement_family(results, png=args.out / "stress_settlement_family.png",
                                  title=f"{case_name}: the loading plate, swept over friction")
    figure = Figure(figsize=(10, 4), layout="constrained")
    FigureCanvasAgg(figure)
    left, right = figure.subplots(1, 2)
    plot_final_measure(results, "settlement", ax=left, unit="m", label="settlement at the end")
    plot_final_measure(results, "stiffness_final", ax=right, unit="Pa/m",
                       label="secant stiffness, final state")
    figure.suptitle(f"{case_name}: final measures against friction", fontsize="medium")
    save_png(figure, args.out / "final_measures.png")
    with open(args.out / "curves.csv", "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["friction", "settlement", "stress"])
        for i in range(len(results)):
            for settlement, stress in zip(*results.curve(i)):
                writer.writerow([sweep.tasks[i]["friction"], repr(float(settlement)), repr(float(stress))])
    for row in results.rows():
        print(f"friction {row['friction']:<5}: {row['state']:<7} settlement {row['settlement']:.4f} m at "
              f"{row['stress'] / 1e3:.0f} kPa; final state's stiffness {row['stiffness_final'] / 1e6:.2f} MPa/m")
    print(f"wrote {args.out}: stress_settlement_family.png, final_measures.png, curves.csv, sweep/summary.csv")
    return 0 if progress.finished else 1


if __name__ == "__main__":
    sys.exit(main())
