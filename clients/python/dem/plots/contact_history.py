"""The force at one contact against the calculation cycles: the nine-disc
test's contact C (Cundall & Strack 1979, Figs. 6 and 7: the normal force
for different damping and loading speeds; Fig. 9: normal and shear forces
under distortion)."""

import numpy as np

from .figure import finish, new_axes


def plot_contact_force_history(curves, *, start_cycle=0, ylabel="normal force at contact C", ax=None, png=None,
                               title=None, marks=()):
    """One line per curve: ``curves`` maps a label to (cycles, forces).
    ``start_cycle`` drops the cycles before it (Fig. 6 starts at 40, where
    the walls stop); ``marks`` are cycles drawn as dotted verticals (the
    end of loading, the start of distortion)."""
    figure, ax = new_axes(ax)
    for label, (cycles, forces) in curves.items():
        cycles, forces = np.asarray(cycles), np.asarray(forces)
        keep = cycles >= start_cycle
        ax.plot(cycles[keep], forces[keep], linewidth=1.2, label=label)
    for cycle in marks:
        ax.axvline(cycle, color="0.5", linestyle=":", linewidth=1)
    ax.set_xlabel("calculation cycles")
    ax.set_ylabel(ylabel)
    ax.ticklabel_format(axis="y", style="sci", scilimits=(0, 0))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    if title:
        ax.set_title(title, fontsize="medium")
    return finish(figure, png)
