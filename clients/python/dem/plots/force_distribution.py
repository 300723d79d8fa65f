"""The probability density of the normalised contact force f = F/<F> on a
plate, as bars, with the q-model (Miyata et al. 2002, eq. 62, N = 3) and the
fit of Mueth et al. (eq. 61) overlaid - Miyata's Fig. 35."""

import numpy as np

from ..force_distribution import mueth_density, q_model_density
from .figure import finish, new_axes


def plot_force_distribution(distributions, *, bin_width=0.25, f_max=None, q_neighbours=3, ax=None, png=None,
                            title=None):
    """Bars of P(f) for each ForceDistribution in ``distributions`` (one
    plate, or several side by side), and the two model densities."""
    figure, ax = new_axes(ax)
    distributions = [d for d in distributions if d.f.size]
    if not distributions:
        raise ValueError("no contacts in any distribution to plot")
    top = f_max or max(bin_width * np.ceil(d.f.max() / bin_width) for d in distributions)
    width = bin_width / len(distributions)
    for k, distribution in enumerate(distributions):
        edges, density = distribution.histogram(bin_width, top)
        ax.bar(edges[:-1] + k * width, density, width=width, align="edge", alpha=0.6, edgecolor="black",
               linewidth=0.5,
               label=f"{distribution.plate} ({distribution.f.size} contacts, {distribution.snapshots} snapshots)")
    f = np.linspace(0.0, top, 400)
    # Miyata et al. 2002, eq. (62): the q-model, N = 3.
    ax.plot(f, q_model_density(f, q_neighbours), "k:", linewidth=2, label=f"q-model, eq. (62), N = {q_neighbours}")
    # Miyata et al. 2002, eq. (61): Mueth et al. (1998), a = 3, b = 0.75, beta = 1.5.
    ax.plot(f, mueth_density(f), "k-", linewidth=2, label="Mueth et al., eq. (61)")
    ax.set_xlim(0.0, top)
    ax.set_xlabel("normalised contact force f = F / <F>")
    ax.set_ylabel("probability density P(f)")
    ax.legend(fontsize="small")
    ax.grid(True, alpha=0.3)
    if title:
        ax.set_title(title, fontsize="medium")
    return finish(figure, png)
