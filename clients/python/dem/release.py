"""What gives way in a plate loading's stress release (Miyata et al. 2002,
3.2(3) and Fig. 32): the largest fall of the loading plate's stress after a
given stress, taken apart from the ParaView frames a run wrote around it
(dem_run --vtk-interval N, or output.vtk_interval).

For each frame from the peak to the trough: the plate's stress, how many of
the peak's strong contacts (normal force above the mean) have lost half
their force or more and at what height they lay, the fastest particle, and
the median particle speed. Then, from the peak to the trough: each
particle's displacement and rotation, by height.

    python3 -m dem.release RUN_DIR [--after-stress PA] [--period LX LY]
"""

import argparse
import csv
import os
import re
import sys
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass

import numpy as np


def read_vtp(path):
    """The arrays of a ParaView PolyData file (ASCII, as io/src/vtk_files.cpp
    writes them): its points as "points" and every numeric DataArray by name,
    shaped (n, components)."""
    root = ElementTree.parse(path).getroot()
    out = {}
    for array in root.iter("DataArray"):
        kind = array.get("type", "")
        if kind == "String" or array.get("format") != "ascii":
            continue
        values = np.array((array.text or "").split(), dtype=float)
        components = int(array.get("NumberOfComponents", "1"))
        if components > 1:
            values = values.reshape(-1, components)
        name = array.get("Name") or "points"
        out[name] = values
    points = root.find(".//Points/DataArray")
    if points is not None:
        out["points"] = np.array((points.text or "").split(), dtype=float).reshape(-1, 3)
    return out


def frame_cycles(run_dir):
    """The cycles of the run's particle frames, ascending."""
    found = []
    directory = os.path.join(run_dir, "vtk")
    if os.path.isdir(directory):
        for name in os.listdir(directory):
            match = re.fullmatch(r"particles_(\d+)\.vtp", name)
            if match:
                found.append(int(match.group(1)))
    return sorted(found)


def largest_release(cycles, stresses, after_stress):
    """(peak index, trough index, fraction released) of the largest fall of
    the stress from a running peak above after_stress; fraction 0 if none."""
    best = (0, 0, 0.0)
    peak = 0
    for k, stress in enumerate(stresses):
        if stress > stresses[peak]:
            peak = k
        if stresses[peak] > after_stress:
            fraction = (stresses[peak] - stress) / stresses[peak]
            if fraction > best[2]:
                best = (peak, k, fraction)
    return best


def contact_forces(contacts):
    """{(first, second, wall contact): (normal force, height of the point)}."""
    out = {}
    forces = np.atleast_1d(contacts.get("normal_force", np.zeros(0)))
    points = contacts.get("point")
    for k in range(forces.size):
        key = (int(contacts["first"][k]), int(contacts["second"][k]), int(contacts["wall_contact"][k]))
        out[key] = (float(forces[k]), float(points[k][2]) if points is not None else float("nan"))
    return out


def rotation_angles(q1, q2):
    """The angle (rad) of the rotation from orientation q1 to q2, row by row
    (unit quaternions w, x, y, z)."""
    cosine = np.abs(np.sum(q1 * q2, axis=1)).clip(0.0, 1.0)
    return 2.0 * np.arccos(cosine)


@dataclass
class FrameLine:
    cycle: int
    stress: float
    strong_lost: int
    lost_height: float  # median height of the lost contacts' points (nan: none)
    fastest_speed: float
    fastest_height: float
    median_speed: float


@dataclass
class Release:
    peak_cycle: int
    trough_cycle: int
    peak_stress: float
    trough_stress: float
    fraction: float
    first_frame: int
    last_frame: int
    frames: list
    strong_contacts: int
    strong_lost: int
    layers: list  # (z from, z to, mean dx, dy, dz, mean |d|, mean rotation rad, particles)
    median_rotation: float
    median_displacement: float


def take_apart(run_dir, after_stress=300e3, period=None, layer=0.25):
    """The anatomy of the largest release after after_stress (Pa) in a run
    directory with compression.csv and vtk/ frames; period (lx, ly) undoes
    the periodic cell's wrap in the displacements."""
    with open(os.path.join(run_dir, "compression.csv"), newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        raise ValueError(f"{run_dir}/compression.csv has no rows: the loading did not start")
    cycles = [int(r["cycle"]) for r in rows]
    stresses = [float(r["stress"]) for r in rows]
    peak, trough, fraction = largest_release(cycles, stresses, after_stress)
    if fraction <= 0.0:
        raise ValueError(f"no fall of the plate's stress after {after_stress:g} Pa in {run_dir}")
    frames = frame_cycles(run_dir)
    before = [f for f in frames if f <= cycles[peak]]
    after = [f for f in frames if f >= cycles[trough]]
    if not before or not after:
        raise ValueError(f"{run_dir}/vtk has no frames around cycles {cycles[peak]}-{cycles[trough]}: "
                         "run with --vtk-interval")
    first, last = before[-1], after[0]

    def load(kind, cycle):
        return read_vtp(os.path.join(run_dir, "vtk", f"{kind}_{cycle:010d}.vtp"))

    stress_at = dict(zip(cycles, stresses))
    particles0 = load("particles", first)
    forces0 = contact_forces(load("contacts", first))
    mean = np.mean([f for f, _ in forces0.values()]) if forces0 else 0.0
    strong = {key: value for key, value in forces0.items() if value[0] > mean}
    lines = []
    lost = []
    for cycle in [f for f in frames if first <= f <= last]:
        particles = load("particles", cycle)
        forces = contact_forces(load("contacts", cycle))
        lost = [key for key, (force, _) in strong.items() if key not in forces or forces[key][0] < 0.5 * force]
        heights = [strong[key][1] for key in lost]
        speeds = np.linalg.norm(particles["velocity"], axis=1)
        fastest = int(speeds.argmax())
        lines.append(FrameLine(cycle, stress_at.get(cycle, float("nan")), len(lost),
                               float(np.median(heights)) if heights else float("nan"), float(speeds[fastest]),
                               float(particles["points"][fastest, 2]), float(np.median(speeds))))
    particles1 = load("particles", last)
    order0, order1 = np.argsort(particles0["id"]), np.argsort(particles1["id"])
    if not np.array_equal(particles0["id"][order0], particles1["id"][order1]):
        raise ValueError(f"the particles of frames {first} and {last} differ (trimmed or added between them)")
    position0 = particles0["points"][order0]
    displacement = particles1["points"][order1] - position0
    if period is not None:
        for axis, length in enumerate(period):
            displacement[:, axis] -= length * np.round(displacement[:, axis] / length)
    rotation = rotation_angles(particles0["orientation"][order0], particles1["orientation"][order1])
    distance = np.linalg.norm(displacement, axis=1)
    layers = []
    z = position0[:, 2]
    for bottom in np.arange(np.floor(z.min() / layer) * layer, z.max() + layer, layer):
        inside = (z >= bottom) & (z < bottom + layer)
        if inside.any():
            d = displacement[inside]
            layers.append((bottom, bottom + layer, *d.mean(axis=0), distance[inside].mean(),
                           rotation[inside].mean(), int(inside.sum())))
    return Release(cycles[peak], cycles[trough], stresses[peak], stresses[trough], fraction, first, last, lines,
                   len(strong), len(lost), layers, float(np.median(rotation)), float(np.median(distance)))


def report(release, out=None):
    out = out or sys.stdout
    r = release
    print(f"largest release: {r.peak_stress / 1e3:.0f} kPa at cycle {r.peak_cycle} -> {r.trough_stress / 1e3:.0f} kPa "
          f"at cycle {r.trough_cycle} ({100 * r.fraction:.1f} %); frames {r.first_frame}-{r.last_frame}", file=out)
    print(f"strong contacts at the peak (normal force above the mean): {r.strong_contacts}, "
          f"lost half their force or more by the trough: {r.strong_lost}", file=out)
    print("cycle      stress kPa  strong lost  their median z m  fastest cm/s at z m  median cm/s", file=out)
    for line in r.frames:
        print(f"{line.cycle:<10d} {line.stress / 1e3:10.0f}  {line.strong_lost:11d}  {line.lost_height:16.2f}  "
              f"{100 * line.fastest_speed:12.1f} {line.fastest_height:6.2f}  {100 * line.median_speed:11.2f}", file=out)
    print(f"peak to trough: median displacement {1e3 * r.median_displacement:.2f} mm, "
          f"median rotation {np.degrees(r.median_rotation):.2f} deg", file=out)
    print("z from-to m   mean dx dy dz mm        mean |d| mm  rotation deg  particles", file=out)
    for bottom, top, dx, dy, dz, d, rotation, count in r.layers:
        print(f"{bottom:5.2f}-{top:5.2f}  {1e3 * dx:7.2f} {1e3 * dy:7.2f} {1e3 * dz:7.2f}  {1e3 * d:11.2f}  "
              f"{np.degrees(rotation):12.2f}  {count:9d}", file=out)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m dem.release", description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="a run's output directory: compression.csv and vtk/ frames")
    parser.add_argument("--after-stress", type=float, default=300e3,
                        help="the release's peak must lie above this stress, Pa (default 300e3)")
    parser.add_argument("--period", type=float, nargs=2, metavar=("LX", "LY"),
                        help="the periodic cell's lengths, to undo its wrap in the displacements")
    args = parser.parse_args(argv)
    try:
        report(take_apart(args.run_dir, args.after_stress, args.period))
    except (OSError, ValueError, KeyError) as error:
        print(f"dem.release: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
