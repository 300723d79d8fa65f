#!/usr/bin/python3
"""The communication a domain decomposition of the dense benchmark would
need (docs/SCALING.md), counted on its packings (../shared/bench/): the
footprint cut into px x py columns (the bed is periodic in x and y, one
layer of about 35 or 70 particles high), and for each rank - its particles,
the ghosts within the halo width h of its sides, the contacts that cross its
sides (touching: overlap > 0; rows: gap below the contact tolerance, what
the contact table keeps) and the distinct ghosts those rows name - averaged
over the ranks. The packing's contacts stand in for the run's: the
benchmark's measured contacts per particle at step 2200 (4.78 at 10k, 5.02
at 100k) differ from the packing's by under 1%.

    /usr/bin/python3 bench/halo_estimate.py ../shared/bench/packing_N10000.csv 1x2 2x2 4x4
    options: --tolerance 4e-4 (the benchmark's skin), --csv FILE
"""

import argparse
import csv
import sys

import numpy as np


def read_packing(path):
    extent, rows = {}, []
    with open(path) as source:
        for line in source:
            if line.startswith("#"):
                for axis in "xy":
                    if line.startswith(f"# {axis}_extent"):
                        extent[axis] = tuple(float(v) for v in line.split("=")[1].split()[:2])
            elif line.strip() and not line.startswith("x"):
                rows.append(line)
    data = np.loadtxt(rows, delimiter=",")
    return data[:, :3], data[:, 3], extent


def pairs_within(position, radius, reach, period):
    """Every pair (i < j) whose gap (centre distance less both radii) is
    below `reach`, with nearest images in x and y: a cell list in numpy."""
    n = len(position)
    cell = 2 * radius.max() + reach
    counts = np.array([max(int(period[0] // cell), 1), max(int(period[1] // cell), 1), 0])
    cells = np.stack([np.floor(position[:, 0] / (period[0] / counts[0])).astype(int) % counts[0],
                      np.floor(position[:, 1] / (period[1] / counts[1])).astype(int) % counts[1],
                      np.floor(position[:, 2] / cell).astype(int)], axis=1)
    cells[:, 2] -= cells[:, 2].min()
    counts[2] = cells[:, 2].max() + 1
    key = (cells[:, 0] * counts[1] + cells[:, 1]) * counts[2] + cells[:, 2]
    order = np.argsort(key, kind="stable")
    key_sorted = key[order]
    found = []
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            for dz in (-1, 0, 1):
                z = cells[:, 2] + dz
                nkey = (((cells[:, 0] + dx) % counts[0]) * counts[1] + (cells[:, 1] + dy) % counts[1]) * counts[2] + z
                start = np.searchsorted(key_sorted, nkey, side="left")
                stop = np.searchsorted(key_sorted, nkey, side="right")
                stop[(z < 0) | (z >= counts[2])] = start[(z < 0) | (z >= counts[2])]
                size = stop - start
                i = np.repeat(np.arange(n), size)
                within = np.arange(size.sum()) - np.repeat(np.cumsum(size) - size, size)
                j = order[np.repeat(start, size) + within]
                found.append(i[j > i] * n + j[j > i])
    # Neighbour cells repeat when a periodic axis has fewer than 3 cells: each pair once.
    unique = np.unique(np.concatenate(found))
    first, second = unique // n, unique % n
    delta = position[second] - position[first]
    for axis in (0, 1):
        delta[:, axis] -= period[axis] * np.round(delta[:, axis] / period[axis])
    gap = np.linalg.norm(delta, axis=1) - radius[first] - radius[second]
    keep = gap < reach
    return first[keep], second[keep], gap[keep]


def column(position, lower, width, count):
    return np.floor((position - lower) / width).astype(int) % count


def estimate(position, radius, extent, px, py, tolerance, pairs):
    period = (extent["x"][1] - extent["x"][0], extent["y"][1] - extent["y"][0])
    halo = 2 * radius.max() + tolerance  # the broad phase's reach: one cell
    width = (period[0] / px, period[1] / py)
    rank_x = column(position[:, 0], extent["x"][0], width[0], px)
    rank_y = column(position[:, 1], extent["y"][0], width[1], py)
    rank = rank_x * py + rank_y
    ranks = px * py
    owned = np.bincount(rank, minlength=ranks)
    # Ghosts of rank r: particles of other ranks within `halo` of r's column (periodic in x and y).
    ghosts = np.zeros(ranks)
    for r in range(ranks):
        rx, ry = divmod(r, py)
        near = np.ones(len(position), bool)
        for axis, (index, count) in enumerate(((rx, px), (ry, py))):
            if count == 1:
                continue
            low = extent["xy"[axis]][0] + index * width[axis]
            offset = (position[:, axis] - low) % period[axis]  # 0 .. period from the column's low side
            near &= (offset < width[axis] + halo) | (offset > period[axis] - halo)
        ghosts[r] = np.count_nonzero(near & (rank != r))
    first, second, gap = pairs
    crossing = rank[first] != rank[second]
    touching = gap < 0
    # Distinct ghosts a rank's crossing rows name (each row is seen by both ranks).
    named = 0
    for r in range(ranks):
        mine_first = crossing & (rank[first] == r)
        mine_second = crossing & (rank[second] == r)
        named += np.unique(np.concatenate([second[mine_first], first[mine_second]])).size
    return {
        "ranks": ranks, "layout": f"{px}x{py}", "owned": owned.mean(), "ghosts": ghosts.mean(),
        "named_ghosts": named / ranks, "pairs_touching": np.count_nonzero(touching),
        "crossing_touching": np.count_nonzero(crossing & touching) / ranks * 2,
        "rows": len(first), "crossing_rows": np.count_nonzero(crossing) / ranks * 2, "halo": halo,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("packing")
    parser.add_argument("layouts", nargs="+", help="PXxPY, e.g. 2x2")
    parser.add_argument("--tolerance", type=float, default=4e-4, help="contact tolerance (skin), m")
    parser.add_argument("--csv", help="write the table here too")
    args = parser.parse_args()
    position, radius, extent = read_packing(args.packing)
    period = (extent["x"][1] - extent["x"][0], extent["y"][1] - extent["y"][0])
    pairs = pairs_within(position, radius, args.tolerance, period)
    n = len(position)
    touching = np.count_nonzero(pairs[2] < 0)
    print(f"{args.packing}: {n} particles; {touching} touching pairs ({2 * touching / n:.3f} contacts per particle); "
          f"{len(pairs[0])} rows within {args.tolerance:g} m ({len(pairs[0]) / n:.2f} per particle)")
    rows = [estimate(position, radius, extent, *map(int, layout.split("x")), args.tolerance, pairs)
            for layout in args.layouts]
    print(f"{'layout':>6} {'owned':>8} {'ghosts':>8} {'named':>8} {'x-touch':>8} {'x-rows':>8}   (per rank)")
    for row in rows:
        print(f"{row['layout']:>6} {row['owned']:8.0f} {row['ghosts']:8.0f} {row['named_ghosts']:8.0f} "
              f"{row['crossing_touching']:8.0f} {row['crossing_rows']:8.0f}")
    if args.csv:
        with open(args.csv, "w", newline="") as out:
            writer = csv.DictWriter(out, list(rows[0]))
            writer.writeheader()
            writer.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
