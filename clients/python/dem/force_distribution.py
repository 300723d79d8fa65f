"""The distribution of the normalised contact force on a plate (Miyata et al.
2002, 3.3, Fig. 35): f = F / <F>, each contact's normal force over the mean
on that plate at that moment, pooled over several snapshots; and the two
densities the seed compares it with.
"""

import math

import numpy as np


def q_model_density(f, n=3):
    """The q-model's P(f) (Liu et al. 1995; Coppersmith et al. 1996) with n
    underlying neighbours - Miyata et al. 2002, eq. (62), used with N = 3:
    P(f) = N^N / (N-1)! f^(N-1) exp(-N f). A Gamma density of mean 1."""
    f = np.asarray(f, dtype=float)
    return n ** n / math.factorial(n - 1) * f ** (n - 1) * np.exp(-n * f)


def mueth_density(f, a=3.0, b=0.75, beta=1.5):
    """The fit of Mueth, Jaeger & Nagel (1998) to glass-bead packs -
    Miyata et al. 2002, eq. (61): P(f) = a (1 - b exp(-f^2)) exp(-beta f),
    with the seed's a = 3, b = 0.75, beta = 1.5."""
    f = np.asarray(f, dtype=float)
    return a * (1.0 - b * np.exp(-f ** 2)) * np.exp(-beta * f)


def normalised_forces(normal_forces):
    """f = F / <F> for the contacts on one plate at one moment (Miyata 3.3)."""
    forces = np.asarray(normal_forces, dtype=float)
    if forces.size == 0:
        return forces
    mean = forces.mean()
    if not mean > 0:
        raise ValueError(f"the mean contact force on the plate is {mean}; f = F/<F> needs it > 0")
    return forces / mean


class ForceDistribution:
    """Normalised contact forces on a plate, pooled over snapshots (the seed:
    10 snapshots between 400 and 600 kPa)."""

    def __init__(self, plate):
        self.plate = plate
        self.snapshots = 0
        self.f = np.empty(0)

    def add_snapshot(self, normal_forces):
        """Adds one moment's contacts on the plate (their normal forces, N)."""
        f = normalised_forces(normal_forces)
        if f.size == 0:
            return
        self.f = np.concatenate([self.f, f])
        self.snapshots += 1

    def histogram(self, bin_width=0.25, f_max=None):
        """(edges, probability density): contacts in each class [f, f + width)
        over (all contacts x width), so the bars integrate to 1."""
        if self.f.size == 0:
            raise ValueError(f"no contacts on {self.plate} to make a distribution of")
        top = f_max if f_max is not None else bin_width * math.ceil(self.f.max() / bin_width + 1e-12)
        edges = np.arange(0.0, top + 0.5 * bin_width, bin_width)
        counts, edges = np.histogram(self.f, bins=edges)
        return edges, counts / (self.f.size * bin_width)
