"""Randall's (1989) Fig. 6.22: the constant-volume shear with the continuum
strain rate under mass-proportional damping, one curve per CON1 value
(``dem_validate randall-shear --case ... --con1 0.99,0.8,... --out DIR``
writes DIR/con1.csv, one row a run, and each run's randall.csv and
perturbation.csv in the directory the row names).

Four panels against the deviator strain: sin(phi) and the isotropic stress
(s = (sigma_1 + sigma_2) / 2) in the case's first region, as Fig. 6.22
draws them; the out-of-balance to contact force ratio Delta F / F (the
figure Randall quotes, "50-75%" for CON1 below 0.5); and the perturbation
velocities' RMS over the continuum field's ("just under 20% at 0.5% ... just
over 5% at 2%" for CON1 0.2-0.8).
"""

import pathlib

import numpy as np

from .granular import _label, read_rows


def _first_region(rows):
    """The rows of randall.csv's first region (the measurement circle)."""
    region = rows[0]["region"] if rows else None
    return [r for r in rows if r["region"] == region]


def plot_con1_sweep(directory, *, png=None, title=None):
    """Fig. 6.22 from a dem_validate --con1 directory: each CON1 value a
    colour, its packings drawn alike (the first labelled)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from .figure import finish

    directory = pathlib.Path(directory)
    runs = read_rows(directory / "con1.csv")
    figure = Figure(figsize=(10, 7.5), dpi=100, layout="constrained")
    FigureCanvasAgg(figure)
    axes = figure.subplots(2, 2)
    colours = {}
    for run in runs:
        con1 = float(run["con1"])
        first = con1 not in colours
        colours.setdefault(con1, f"C{len(colours)}")
        label = f"CON1 = {con1:g}" if first else None
        style = {"color": colours[con1], "linewidth": 1.2 if first else 0.7, "alpha": 1.0 if first else 0.5}
        series = _first_region(read_rows(directory / run["directory"] / "randall.csv"))
        strain = 100 * np.array([float(r["deviator_strain"]) for r in series])
        s1 = np.array([float(r["stress_1"]) for r in series])
        s2 = np.array([float(r["stress_2"]) for r in series])
        axes[0, 0].plot(strain, [float(r["sin_phi"]) for r in series], label=label, **style)
        axes[0, 1].plot(strain, (s1 + s2) / 2e3, label=label, **style)
        perturbation = read_rows(directory / run["directory"] / "perturbation.csv")
        p_strain = 100 * np.array([float(r["deviator_strain"]) for r in perturbation])
        axes[1, 0].plot(p_strain, [100 * float(r["out_of_balance"]) for r in perturbation], label=label, **style)
        axes[1, 1].plot(p_strain, [100 * float(r["perturbation_ratio"]) for r in perturbation], label=label, **style)
    region = read_rows(directory / runs[0]["directory"] / "randall.csv")[0]["region"] if runs else ""
    _label(axes[0, 0], "deviator strain, %", rf"$\sin\phi$ ({region})", "a) evolution of sin φ (Fig. 6.22)")
    _label(axes[0, 1], "deviator strain, %", f"s = (σ1 + σ2) / 2, kPa ({region})",
           "b) evolution of isotropic stress (Fig. 6.22)")
    _label(axes[1, 0], "deviator strain, %", "ΔF / F, %",
           "out of balance to contact force (Randall: 50-75 % for CON1 < 0.5)")
    axes[1, 1].axhline(100, color="0.5", linestyle=":", linewidth=0.8)
    axes[1, 1].set_yscale("log")
    _label(axes[1, 1], "deviator strain, %", "perturbation / field velocity RMS, %",
           "perturbation velocities (Randall: ~20 % at 0.5 %, ~5 % at 2 %)")
    figure.suptitle(title or "constant-volume shear with the continuum strain rate: mass-proportional damping CON1",
                    fontsize="medium")
    return finish(figure, png)
