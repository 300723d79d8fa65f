#!/usr/bin/python3
"""Two builds of bench_plate_compression at once, one thread each, each
pinned to its own core, the cores swapped every round; prints the ratio
of their rates (second / first) per round and the median.

On a shared 2-core guest a 100k run's rate drifts 5-15 % from one minute
to the next, so builds timed one after the other differ by more than most
changes do. Run together, both meet the same drift: the same build against
itself read 0.972-1.004 over four rounds, where two builds 1 % apart, run
one after the other, read 0.907-1.025 (docs/PERFORMANCE.md, item 21). The
two share the third-level cache and the memory bus, so this compares
builds; it does not replace the one-at-a-time rates of peer_comparison.py.

    /usr/bin/python3 bench/side_by_side.py OLD_BENCH NEW_BENCH [--case 100k] [--cycles 1000] [--rounds 8]
"""
import argparse
import os
import statistics
import subprocess
import sys

from peer_comparison import SIZES, bench_rate, case_file


def start(binary, case, cycles, core):
    command = ["taskset", "-c", str(core), binary, "--case", case, "--threads", "1", "--cycles", str(cycles)]
    return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def rate(process, binary):
    out, err = process.communicate()
    if process.returncode != 0 or "particle-steps/s" not in out:
        sys.exit(f"{binary} failed (exit {process.returncode}): {err.strip() or out.strip()}")
    return bench_rate(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("first", help="bench_plate_compression of the build to compare against")
    parser.add_argument("second", help="bench_plate_compression of the build under test")
    parser.add_argument("--case", default="100k", help="10k, 100k or a case file (default 100k)")
    parser.add_argument("--cycles", type=int, default=1000, help="timed cycles a run (default 1000)")
    parser.add_argument("--rounds", type=int, default=8, help="rounds, the cores swapped each (default 8)")
    args = parser.parse_args()
    if os.cpu_count() is None or os.cpu_count() < 2:
        sys.exit("side_by_side.py needs two cores")
    case = str(case_file(args.case)) if args.case in SIZES else args.case
    if not os.path.isfile(case):
        sys.exit(f"no case file {case}")
    for binary in (args.first, args.second):
        if not os.access(binary, os.X_OK):
            sys.exit(f"not an executable: {binary}")
    ratios = []
    for r in range(args.rounds):
        cores = (0, 1) if r % 2 == 0 else (1, 0)
        first = start(args.first, case, args.cycles, cores[0])
        second = start(args.second, case, args.cycles, cores[1])
        a, b = rate(first, args.first), rate(second, args.second)
        ratios.append(b / a)
        print(f"round {r}: first {a / 1e6:.2f} M (core {cores[0]}), second {b / 1e6:.2f} M (core {cores[1]}), "
              f"ratio {b / a:.4f}", flush=True)
    print(f"second / first: median {statistics.median(ratios):.4f}, min {min(ratios):.4f}, "
          f"max {max(ratios):.4f}, {len(ratios)} rounds")


if __name__ == "__main__":
    main()
