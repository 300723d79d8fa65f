"""A small run directory of Miyata's plate loading analyses written by hand
in the columns docs/CASES.md gives ("The files"), for the figure tests:
six discs between a bottom plate at y = 0 and a loading plate, loaded to
900 kPa through the three states, with one stress drop."""

import csv
import math

import numpy as np

TRANSITION_STRESS, FINAL_STRESS = 50e3, 250e3


def write(path, header, rows):
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(header)
        writer.writerows(rows)


def loading_curve():
    """(cycle, settlement, stress, loading contacts) per output row: 300
    rows 100 cycles apart, no contact for the first 10, then 1 kPa per mm
    to 50 kPa, 3.4 kPa per mm to 250 kPa, 3.6 kPa per mm beyond, and a
    drop of 10 % at row 100."""
    rows = []
    for k in range(1, 301):
        settlement = 0.001 * k
        if k <= 10:
            stress = 0.0
        elif k <= 60:
            stress = 1e3 * (k - 10)
        elif k <= 120:
            stress = 50e3 + 200e3 / 60 * (k - 60)
        else:
            stress = 250e3 + 3.6e3 * (k - 120)
        if k == 101:
            stress *= 0.9
        rows.append((100 * k, settlement, stress, min(k // 10, 12)))
    return rows


# Snapshots of plate_contacts.csv: (index, target stress, row of the curve,
# for_contacts, for_distribution).
SNAPSHOTS = ((0, 0.0, 1, 1, 0), (1, 50e3, 60, 1, 0), (2, 250e3, 120, 1, 0), (3, 400e3, 162, 1, 1),
             (4, 450e3, 176, 0, 1), (5, 500e3, 190, 0, 1), (6, 900e3, 300, 1, 0))

# The discs: id, x, y (m), radius 0.15 m.
DISCS = ((0, 0.15, 0.15), (1, 0.45, 0.15), (2, 0.75, 0.15), (3, 0.30, 0.41), (4, 0.60, 0.41), (5, 0.45, 0.67))


def rotation(disc, snapshot):
    """The accumulated angle (rad) of a disc at a snapshot: disc 5, under
    the plate, turns 0.5 rad by 50 kPa and 0.2 more by 250 kPa; disc 3
    turns 0.1 rad by 50 kPa and 0.4 more by 250 kPa; the rest stay."""
    turns = {5: (0.0, 0.5, 0.7), 3: (0.0, 0.1, 0.5)}
    return 1.0 + turns.get(disc, (0.0, 0.0, 0.0))[min(snapshot, 2)]


def plate_forces(snapshot):
    """{plate: [(particle, x, normal force N)]} at a snapshot: the loading
    plate touches disc 5 from 50 kPa on and discs 3, 4 from 400 kPa."""
    scale = SNAPSHOTS[snapshot][1] or 1.0
    top = [] if snapshot == 0 else [(5, 0.45, 0.2 * scale)]
    if snapshot >= 3:
        top += [(3, 0.30, 0.1 * scale), (4, 0.60, 0.05 * scale)]
    bottom = [(0, 0.15, 0.1 * scale + 500), (1, 0.45, 0.3 * scale + 500), (2, 0.75, 0.05 * scale + 500)]
    return {"top": top, "bottom": bottom}


def f_of(forces):
    mean = np.mean([f for _, _, f in forces])
    return [f / mean for _, _, f in forces]


def write_run(directory, *, assembly=True, summaries=True):
    """The files; ``assembly`` False leaves out particles_at_stress.csv and
    contacts_at_stress.csv (a run of an older dem), ``summaries`` False the
    files written at the end."""
    directory.mkdir(parents=True, exist_ok=True)
    curve = loading_curve()
    write(directory / "compression.csv",
          ["stage", "cycle", "time", "settlement", "stress", "loading_contacts", "bottom_stress", "bottom_contacts",
           "contact_ratio"],
          [(2, c, 1e-4 * c, s, p, n, p + 2e3, 20, n / 20) for c, s, p, n in curve])
    write(directory / "assembly.csv",
          ["cycle", "time", "kinetic_energy", "kinetic_to_elastic", "unbalanced_force", "sliding_fraction",
           "inertial_number"],
          [(c, 1e-4 * c, 1.0, math.inf if c < 1100 else 1e-3 * (1 + c / 1e4), 2e-3 + c / 1e7,
            0.05 + c / 1e6, 1e-4 * (1 + c / 1e4)) for c in range(0, 30001, 100)])
    rows = []
    for index, target, row, for_contacts, for_distribution in SNAPSHOTS:
        cycle, _, stress, _ = curve[row - 1]
        for plate, forces in plate_forces(index).items():
            for (particle, x, force), f in zip(forces, f_of(forces) if forces else []):
                y = curve[row - 1][1] if plate == "top" else 0.0
                rows.append((index, target, cycle, stress, plate, particle, x, y, force, 0.1 * force, f, 50,
                             "initial", for_contacts, for_distribution))
    write(directory / "plate_contacts.csv",
          ["snapshot", "target_stress", "cycle", "stress", "plate", "particle", "x", "y", "normal_force",
           "shear_force", "f", "formed_cycle", "formed_in", "for_contacts", "for_distribution"], rows)
    if assembly:
        write_assembly(directory, curve)
    if summaries:
        write_summaries(directory, curve)


def write_assembly(directory, curve):
    particles, contacts = [], []
    for index, target, row, for_contacts, _ in SNAPSHOTS:
        if not for_contacts:
            continue
        cycle, settlement, stress, _ = curve[row - 1]
        lead = (index, target, cycle, stress)
        for disc, x, y in DISCS:
            particles.append(lead + (disc, x, y, 0.15, 0.0, 0.0, 0.0, rotation(disc, index), "rock", 0.15, 0.15, 2))
        # The pairs of the pile, their forces growing with the stress.
        for first, second, force in ((0, 3, 1.0), (1, 3, 2.0), (1, 4, 3.0), (3, 5, 4.0), (4, 5, 5.0)):
            a, b = np.array(DISCS[first][1:]), np.array(DISCS[second][1:])
            normal = (b - a) / np.linalg.norm(b - a)
            point = 0.5 * (a + b)
            contacts.append(lead + (first, "particle", second, *point, *normal, 1e-3, force * (1 + stress / 1e3),
                                    0.0, 0.0, 0.0, 0.0, 0.0, 0, 10, 0.0, 0.0))
        for plate, forces in plate_forces(index).items():
            for particle, x, force in forces:
                y = settlement if plate == "top" else 0.0
                ny = 1.0 if plate == "top" else -1.0
                contacts.append(lead + (particle, "wall", plate, x, y, 0.0, ny, 1e-3, force, 0.0, 0.0, 0.0, 0.0,
                                        0.0, 0, 10, 0.0, 0.0))
    write(directory / "particles_at_stress.csv",
          ["snapshot", "target_stress", "cycle", "stress", "id", "x", "y", "radius", "vx", "vy", "angular_velocity",
           "rotation", "material", "a", "b", "n"], particles)
    write(directory / "contacts_at_stress.csv",
          ["snapshot", "target_stress", "cycle", "stress", "first", "second_kind", "second", "x", "y", "nx", "ny",
           "overlap", "normal_force", "shear_force", "tangential_x", "tangential_y", "normal_damping",
           "shear_damping", "sliding", "formed_cycle", "force_x", "force_y"], contacts)


# What the summaries say, for the tests to find in the figures.
LOAD_BY_FORMATION = {("top", "initial"): (0.6, 0.4), ("top", "transition"): (0.3, 0.3),
                     ("top", "final"): (0.1, 0.3), ("bottom", "initial"): (0.5, 0.4),
                     ("bottom", "transition"): (0.35, 0.3), ("bottom", "final"): (0.15, 0.3)}
STATE_ROWS = {"initial": (1100, 50, 1e3, 50e3, 0.011, 0.060, 1e6, 0.99, 1, 5, 1e-4),
              "transition": (6100, 60, 50e3, 250e3, 0.061, 0.120, 3.33e6, 0.999, 6, 12, 3e-5),
              "final": (12100, 180, 253.6e3, 898e3, 0.121, 0.300, 3.6e6, 1.0, 12, 12, 0.0)}
DECAY = {"top": (1.8, 0.4), "bottom": (1.3, 0.3)}


def write_summaries(directory, curve):
    write(directory / "compression_states.csv",
          ["state", "first_cycle", "samples", "stress_from", "stress_to", "settlement_from", "settlement_to",
           "secant_stiffness", "tangent_stiffness", "r_squared", "loading_contacts_from", "loading_contacts_to",
           "contact_rate"],
          [(state, first, samples, s0, s1, d0, d1, (s1 - s0) / (d1 - d0), k, r2, n0, n1, rate)
           for state, (first, samples, s0, s1, d0, d1, k, r2, n0, n1, rate) in STATE_ROWS.items()])
    peak, trough = curve[99], curve[100]
    write(directory / "stress_drops.csv",
          ["state", "peak_cycle", "trough_cycle", "peak_settlement", "peak_stress", "trough_stress", "relative_drop"],
          [("transition", peak[0], trough[0], peak[1], peak[2], trough[2], 1 - trough[2] / peak[2])])
    header = ["plate", "group", "contacts", "contact_share", "load", "load_share", "first_formed_cycle",
              "last_formed_cycle", "stress"]
    write(directory / "load_by_formation.csv", header,
          [(plate, group, 3, contacts, 1e5 * load, load, 100, 200, 898e3)
           for (plate, group), (load, contacts) in LOAD_BY_FORMATION.items()])
    header[1] = "state"
    write(directory / "load_by_state.csv", header,
          [(plate, group, 3, contacts, 1e5 * load, load, 100, 200, 898e3)
           for (plate, group), (load, contacts) in LOAD_BY_FORMATION.items()])
    rows = []
    for plate in ("top", "bottom"):
        pooled = np.concatenate([f_of(plate_forces(s[0])[plate]) for s in SNAPSHOTS if s[4]])
        counts, edges = np.histogram(pooled, bins=np.arange(0.0, 3.01, 0.25))
        for k, count in enumerate(counts):
            inside = (pooled >= edges[k]) & (pooled < edges[k + 1])
            share = pooled[inside].sum() / pooled.sum()
            rows.append((plate, edges[k], edges[k + 1], count, count / (pooled.size * 0.25), share, share / 0.25,
                         0.0, 0.0))
    write(directory / "force_distribution.csv",
          ["plate", "f_low", "f_high", "contacts", "probability_density", "load_share", "load_density", "q_model",
           "mueth"], rows)
    write(directory / "force_tail.csv",
          ["plate", "snapshots", "contacts", "mean_force", "tail_from", "tail_contacts", "decay_rate",
           "decay_rate_error", "excess_cv", "q_model_decay_rate", "mueth_decay_rate"],
          [(plate, 3, 9, 1e5, 1.0, 3, beta, error, 1.0, 1.89, 1.39) for plate, (beta, error) in DECAY.items()])
