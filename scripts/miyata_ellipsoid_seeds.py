#!/usr/bin/env python3
"""Runs a Miyata 3D ellipsoid case (cases/miyata/ellipsoids_reduced.case.txtpb
by default) with several packing seeds and variants of its loading, through
dem_validate, and prints judge_miyata's figures per run: how sturdy the case
is against the packing seed (issue 11; docs/VALIDATION.md, the 3D section).

  scripts/miyata_ellipsoid_seeds.py --seeds 1 2 3 4 5 6 \
      --variant base --variant 'alpha=0.3' --variant 'v=0.05,e=0.1'

A variant is comma-separated key=value overrides of the case text:
  v      the loading plate's speed, m/s
  alpha  local damping during loading (Miyata eq. 33)
  e      the contacts' restitution (all stages)
  L      the periodic cell's side, m (the packing box and plates follow)
  n      particles in the packing
  trim   the trimming height, m
  frac   the time step's fraction of the Rayleigh step (all stages)
  loadfrac  the loading stage's time step, fraction of the Rayleigh step
  z      the packing box's height, m
Runs go two at a time, niced; each one's CSV files stay in --out.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def substitute(text, pattern, replacement, what):
    new, n = re.subn(pattern, replacement, text, flags=re.S)
    if n == 0:
        sys.exit(f"the case has no {what} to change ({pattern})")
    return new


# The overrides that change one place of the case: key -> (pattern,
# replacement with {value} for the override's value, what it changes).
OVERRIDES = {
    "v": (r"velocity \{ z: -[0-9.e-]+ \}", "velocity {{ z: -{value} }}", "plate speed"),
    "alpha": (r'(name: "load".*?damping \{ local_alpha: )[0-9.]+', r"\g<1>{value}", "loading damping"),
    "e": (r"restitution: [0-9.]+", "restitution: {value}", "restitution"),
    "n": (r"count: \d+", "count: {value}", "particle count"),
    "trim": (r"trim \{ height: [0-9.]+ \}", "trim {{ height: {value} }}", "trim"),
    "frac": (r"time_step \{ fraction: [0-9.]+ \}", "time_step {{ fraction: {value} }}", "time step"),
    "loadfrac": (r'(name: "load".*?damping \{ local_alpha: [0-9.]+ \})',
                 r"\g<1>\n  time_step {{ fraction: {value} }}", "loading stage"),
    "z": (r"(max \{ x: [0-9.]+ y: [0-9.]+ z: )[0-9.]+", r"\g<1>{value}", "packing height"),
}


def variant_text(base, seed, overrides):
    text = substitute(base, r"seed: \d+", f"seed: {seed}", "packing seed")
    for key, value in overrides.items():
        if key in OVERRIDES:
            pattern, replacement, what = OVERRIDES[key]
            text = substitute(text, pattern, replacement.format(value=value), what)
        elif key == "L":
            L = float(value)
            text = substitute(text, r"max \{ x: [0-9.]+ y: [0-9.]+ z:", f"max {{ x: {L} y: {L} z:", "packing box")
            text = substitute(text, r"max \{ x: [0-9.]+ y: [0-9.]+ \}", f"max {{ x: {L} y: {L} }}", "period")
            text = substitute(text, r"h2: [0-9.]+", f"h2: {L + 0.5}", "wall extent h2")
            text = substitute(text, r"k2: [0-9.]+", f"k2: {L + 0.5}", "wall extent k2")
            text = substitute(text, r'(name: "top".*?point \{ x: 0 y: )[0-9.]+', rf"\g<1>{L}", "top wall point")
        else:
            sys.exit(f"unknown variant key {key}")
    return text


def parse_variant(spec):
    if spec == "base":
        return {}
    return dict(item.split("=", 1) for item in spec.split(","))


def run_one(exe, base, out_root, spec, seed):
    overrides = parse_variant(spec)
    name = re.sub(r"[^A-Za-z0-9.=_-]", "_", spec) + f"_s{seed}"
    directory = os.path.join(out_root, name)
    os.makedirs(directory, exist_ok=True)
    case = os.path.join(directory, "case.txtpb")
    with open(case, "w") as f:
        f.write(variant_text(base, seed, overrides))
    start = time.time()
    report = os.path.join(directory, "report.txt")
    with open(report, "w") as f:
        proc = subprocess.Popen([exe, "miyata-compression", "--case", case, "--out", directory], stdout=f,
                                stderr=subprocess.STDOUT, preexec_fn=lambda: os.nice(10))
        # The run's own CPU time: wait4 gives this child's usage alone.
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
    with open(report) as f:
        stdout = f.read()
    row = {"variant": spec, "seed": seed, "wall_s": time.time() - start, "cpu_s": usage.ru_utime + usage.ru_stime,
           "passed": proc.returncode == 0,
           "failed": "; ".join(line.split("FAIL", 1)[1].strip().split(":")[0] for line in stdout.splitlines()
                               if line.strip().startswith("FAIL"))}
    summary = os.path.join(directory, "miyata_summary.csv")
    if os.path.exists(summary):
        with open(summary) as f:
            row.update(next(csv.DictReader(f)))
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--case", default=os.path.join(ROOT, "cases/miyata/ellipsoids_reduced.case.txtpb"))
    parser.add_argument("--exe", default=os.path.join(ROOT, "build/tools/dem_validate/dem_validate"))
    parser.add_argument("--out", default="/tmp/miyata_seeds")
    parser.add_argument("--seeds", type=int, nargs="+", default=[2002, 1, 2, 3, 4, 5])
    parser.add_argument("--variant", action="append", default=None)
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    with open(args.case) as f:
        base = f.read()
    variants = args.variant or ["base"]
    jobs = [(spec, seed) for spec in variants for seed in args.seeds]
    print("variant | seed | pass | R2 final | softness | drops | largest drop | loading / bottom contacts | "
          "particles | cycles | CPU s | failed", flush=True)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for row in pool.map(lambda job: run_one(args.exe, base, args.out, *job), jobs):
            print(f"{row['variant']} | {row['seed']} | {'yes' if row['passed'] else 'NO'} | "
                  f"{float(row.get('final_r_squared', 'nan')):.4f} | {float(row.get('initial_softness', 'nan')):.0f} | "
                  f"{row.get('drops', '?')} | {100 * float(row.get('largest_drop', 'nan')):.0f}% | "
                  f"{row.get('loading_contacts', '?')} / {row.get('bottom_contacts', '?')} | "
                  f"{row.get('particles', '?')} | {row.get('cycles', '?')} | {row['cpu_s']:.1f} | {row['failed']}",
                  flush=True)


if __name__ == "__main__":
    main()
