"""The quasi-static measures (docs/CASES.md, "Quasi-static measures") as
panels under a stress-settlement curve: assembly.csv's columns (and demctl
monitor's), each with the line that marks where a slow test stops being
quasi-static."""

import numpy as np

# The column, its label, log scale, and the reference line with what it marks.
QUASI_STATIC = (
    ("kinetic_to_elastic", "kinetic / elastic\nenergy", True, 1.0, "1: motion holds as much as the springs"),
    ("unbalanced_force", "unbalanced force\n(mean |ΣF| / mean F)", True, 1e-2, "1e-2"),
    ("sliding_fraction", "sliding fraction", False, 0.25, "25 %: Randall's largest"),
    ("inertial_number", "inertial number I", True, 1e-3, "1e-3: quasi-static below (GDR MiDi)"),
)


def draw_quasi_static_panels(axes, x, measures, columns=None):
    """One panel per measure of QUASI_STATIC (or of those `columns`) on
    `axes`, against x; a measure missing from `measures` (column -> values)
    says so."""
    shown_measures = [m for m in QUASI_STATIC if columns is None or m[0] in columns]
    for ax, (column, label, log, reference, meaning) in zip(axes, shown_measures):
        ax.set_ylabel(label, fontsize="small")
        if column not in measures:
            ax.text(0.5, 0.5, f"no {column} in the table (an older dem)", transform=ax.transAxes,
                    ha="center", va="center")
            continue
        y = np.asarray(measures[column], dtype=float)
        shown = np.isfinite(y) & ((y > 0) if log else np.ones_like(y, dtype=bool))
        ax.plot(np.asarray(x)[shown], y[shown], color="tab:purple", linewidth=0.9)
        ax.axhline(reference, color="0.3", linestyle=":", linewidth=1, label=meaning)
        if log:
            ax.set_yscale("log")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper right")
