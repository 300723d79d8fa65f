"""The non-dimensional local angle of reflection psi_2 against that of
incidence psi_1 for oblique impacts of a sphere on a wall (Randall 1989,
Fig. 5.10, after Maw et al. 1976, Fig. 5.6), with the regime boundaries
psi_1 = 1 and 4 chi - 1 and the rigid-body prediction."""

import numpy as np

from ..impact import rigid_body_psi2
from .figure import finish, new_axes


def plot_psi2_against_psi1(psi1, psi2, chi, *, psi1_max=None, ax=None, png=None, title=None,
                           label="simulated (service)"):
    """psi_2 against psi_1 up to ``psi1_max`` (default 3 (4 chi - 1), the
    three regimes and some way beyond, as Maw's and Randall's figures)."""
    figure, ax = new_axes(ax)
    psi1, psi2 = np.asarray(psi1, dtype=float), np.asarray(psi2, dtype=float)
    top = psi1_max if psi1_max is not None else 3.0 * (4.0 * chi - 1.0)
    shown = np.isfinite(psi1) & np.isfinite(psi2) & (psi1 <= top)
    ax.plot(psi1[shown], psi2[shown], "o-", markersize=4, linewidth=1, label=label)
    line = np.linspace(0.0, top, 200)
    # Rigid-body theory, restitution 1 (Randall 1989, 5.4).
    ax.plot(line, [rigid_body_psi2(p, chi) for p in line], "k--", linewidth=1, label="rigid-body theory")
    # The regimes (Randall 5.3.2): stick at first below psi_1 = 1, sliding
    # then sticking up to 4 chi - 1, sliding throughout beyond.
    for boundary, text in ((1.0, r"$\psi_1 = 1$"), (4.0 * chi - 1.0, r"$\psi_1 = 4\chi - 1$")):
        ax.axvline(boundary, color="0.5", linestyle=":", linewidth=1)
        ax.annotate(text, (boundary, 1.0), xycoords=("data", "axes fraction"), xytext=(3, -12),
                    textcoords="offset points", fontsize="small", color="0.3")
    ax.axhline(0.0, color="0.7", linewidth=0.8)
    ax.set_xlim(0.0, top)
    ax.set_xlabel(r"$\psi_1$ (incidence), eq. (5.15)")
    ax.set_ylabel(r"$\psi_2$ (reflection of the contact point)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="lower right")
    ax.set_title(title or rf"oblique impact of a sphere on a wall, $\chi$ = {chi:.4f}", fontsize="medium")
    return finish(figure, png)
