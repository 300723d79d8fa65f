"""The bending moment a caisson's bottom slab takes from the rubble's
contact forces, estimated statistically (Miyata et al. 2002, 3.3(2) and
Fig. 36, after Miyata et al. 1999): the forces' amplitudes from the
probability density of f = F/<F> measured on a plate, their positions from
the contacts measured there, and the slab's largest moment over many draws.

The slab model, stated because the seed does not give one: a one-way slab,
simply supported on two opposite edges a span L apart, that carries the
plate's contacts as point loads at their positions along the span (in 3D
the loads are spread across the slab's width W, so the moment is per unit
width; 2D forces are per unit depth already). Its moment at x is
    M(x) = R_A x - sum_{x_i < x} P_i (x - x_i),  R_A = sum_i P_i (L - x_i) / L,
largest at one of the loads. The design code's reaction is uniform (the
seed's "linearly distributed reaction force" under a centric load): the
same total load W_tot spread evenly gives M = q L^2 / 8 with q = W_tot /
(L W), so the ratio M_max / (q L^2 / 8) says how much the discrete forces
raise the moment above the design's.

Each Monte Carlo trial takes one measured snapshot's contact positions,
draws a force amplitude f for each contact from a density (the measured
one: the pooled f of the plate's snapshots, resampled; or the q-model,
eq. 62, or Mueth's fit, eq. 61), scales them so they carry that snapshot's
total load, and keeps the ratio.
"""

import dataclasses

import numpy as np

from .force_distribution import mueth_density


def maximum_moments(span, positions, loads):
    """The largest moment of a simply supported strip of length ``span``
    (supports at 0 and span) under point loads ``loads`` (..., n) at
    ``positions`` (n,) in [0, span]: an array of the leading shape. Loads
    push the same way (compressive), so the moment is >= 0 and largest at
    a load."""
    positions = np.asarray(positions, dtype=float)
    loads = np.asarray(loads, dtype=float)
    if positions.size == 0:
        return np.zeros(loads.shape[:-1])
    order = np.argsort(positions, kind="stable")
    x = positions[order]
    p = loads[..., order]
    reaction = np.sum(p * (span - x), axis=-1, keepdims=True) / span
    # At load j: R_A x_j - sum_{i<j} P_i (x_j - x_i), with the sums of the
    # loads before j (prefix sums without j itself: its arm is 0).
    before = np.cumsum(p, axis=-1) - p
    moment_before = np.cumsum(p * x, axis=-1) - p * x
    moments = reaction * x - (x * before - moment_before)
    return moments.max(axis=-1)


def uniform_moment(total_load, span, width=1.0):
    """q L^2 / 8 for the same load spread evenly: q = total / (span x width)."""
    return total_load / (span * width) * span ** 2 / 8.0


def moment_ratio(span, positions, loads, width=1.0):
    """M_max over the uniform load's moment, for each row of loads."""
    loads = np.asarray(loads, dtype=float)
    total = loads.sum(axis=-1)
    return maximum_moments(span, positions, loads) / width / uniform_moment(total, span, width)


@dataclasses.dataclass
class PlateLoads:
    """One measured snapshot of a plate: where its contacts are along the
    span (m, from the first support) and their normal forces (N)."""
    positions: np.ndarray
    forces: np.ndarray


def sample_q_model(rng, size, neighbours=3):
    """f drawn from the q-model, eq. (62): a Gamma density of shape N and mean 1."""
    return rng.gamma(neighbours, 1.0 / neighbours, size)


def sample_mueth(rng, size, f_max=20.0, points=20001):
    """f drawn from Mueth et al.'s fit, eq. (61), by inverting its
    cumulative distribution on a fine grid (the density normalised over
    [0, f_max]; beyond f = 20 it holds less than 1e-12 of the mass)."""
    f = np.linspace(0.0, f_max, points)
    density = mueth_density(f)
    cumulative = np.concatenate([[0.0], np.cumsum(0.5 * (density[1:] + density[:-1]) * np.diff(f))])
    cumulative /= cumulative[-1]
    return np.interp(rng.random(size), cumulative, f)


def monte_carlo_ratios(snapshots, span, width=1.0, *, density="measured", trials=10000, seed=2002):
    """M_max / (q L^2 / 8) of ``trials`` draws. Each picks a snapshot (a
    PlateLoads) at random, keeps its positions and its total load, and
    draws each contact's f from ``density``: "measured" (the pooled f = F /
    <F> of every snapshot given, resampled), "q-model" (eq. 62, N = 3),
    "mueth" (eq. 61) or "equal" (every f = 1: the positions alone)."""
    snapshots = [s for s in snapshots if len(s.forces) > 0]
    if not snapshots:
        raise ValueError("no snapshot with contacts to draw the loads from")
    rng = np.random.default_rng(seed)
    pooled = np.concatenate([s.forces / s.forces.mean() for s in snapshots])
    chosen = rng.integers(len(snapshots), size=trials)
    ratios = np.empty(trials)
    for k, snapshot in enumerate(snapshots):
        rows = np.flatnonzero(chosen == k)
        if rows.size == 0:
            continue
        shape = (rows.size, len(snapshot.forces))
        if density == "measured":
            f = rng.choice(pooled, size=shape)
        elif density == "q-model":
            f = sample_q_model(rng, shape)
        elif density == "mueth":
            f = sample_mueth(rng, shape)
        elif density == "equal":
            f = np.ones(shape)
        else:
            raise ValueError(f'unknown density "{density}" (measured, q-model, mueth or equal)')
        loads = f * (snapshot.forces.sum() / f.sum(axis=-1, keepdims=True))
        ratios[rows] = moment_ratio(span, snapshot.positions, loads, width)
    return ratios
