"""Randall's (1989) Fig. 6.35, the "equivalent space lattice": lines
joining the centres of contacting particles at 0.1 % deviator strain, the
contacts broken since the start of the shear dashed and grey, the ones
formed since then thick and dark, from the two states ``dem_validate
randall-shear --out DIR`` keeps (at_100_kPa/ and strain_0.1_percent/, each
a particles.csv and a contacts.csv).
"""

import numpy as np

from .figure import finish, new_axes


def _bonds(contacts):
    """The particle-particle contacts as pairs of ids, smaller first."""
    return {tuple(sorted((int(c["first"]), int(c["second"])))) for c in contacts if c["second_kind"] == "particle"}


def plot_contact_lattice(particles_before, contacts_before, particles_after, contacts_after, *, png=None,
                         title=None):
    """Rows of particles.csv and contacts.csv at the start of the shear and
    later; the lines are drawn between the later centres (the broken ones
    between the earlier)."""
    from matplotlib.collections import LineCollection

    before = {int(p["id"]): (float(p["x"]), float(p["y"])) for p in particles_before}
    after = {int(p["id"]): (float(p["x"]), float(p["y"])) for p in particles_after}
    old, new = _bonds(contacts_before), _bonds(contacts_after)
    kept, broken, formed = old & new, old - new, new - old
    figure, ax = new_axes(None, size=(7.0, 7.0))
    for bonds, centres, style in (
            (kept, after, dict(colors="0.35", linewidths=0.8)),
            (broken, before, dict(colors="0.65", linewidths=1.0, linestyles="dashed")),
            (formed, after, dict(colors="black", linewidths=2.4))):
        segments = [(centres[a], centres[b]) for a, b in bonds if a in centres and b in centres]
        if segments:
            ax.add_collection(LineCollection(segments, **style))
    x = np.array([c[0] for c in after.values()])
    y = np.array([c[1] for c in after.values()])
    if len(x):
        ax.set_xlim(x.min(), x.max())
        ax.set_ylim(y.min(), y.max())
    ax.set_aspect("equal")
    ax.set_xlabel("x, m (extension)")
    ax.set_ylabel("y, m (compression)")
    ax.set_title(title or f"contact lattice at 0.1 % (Randall Fig. 6.35): {len(kept)} kept, {len(broken)} broken "
                 f"(dashed), {len(formed)} new (thick)", fontsize="small")
    return finish(figure, png)
