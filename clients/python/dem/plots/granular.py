"""Randall's (1989) chapter 6 figures from the tables dem_validate writes
(randall.csv, roses.csv, obliquity.csv, hopper.csv) and dem_run's
regions.csv:

- plot_rose: the distribution of contact normals as a rose, plain,
  weighted to the normal force or of the sliding contacts (Figs. 6.15-6.17,
  6.36-6.41);
- plot_obliquity_histogram: contact force obliquities F_s / (mu F_n), the
  sliding contacts at -1 and +1 (Figs. 6.18-6.20);
- plot_shear_series: sin(phi), the tangential forces' share, the sliding
  contacts, the structural anisotropy and the coordination against the
  deviator strain (Figs. 6.24, 6.28-6.30);
- plot_stress_path: t = (sigma_1 - sigma_2) / 2 against s = (sigma_1 +
  sigma_2) / 2 (Fig. 6.27), and the isotropic stress against the deviator
  strain (Fig. 6.25);
- plot_discharge: particles discharged from a hopper against time (6.2);
- plot_velocity_field: each particle's velocity as an arrow, from a
  particles.csv (Fig. 6.31 at 0.005 % deviator strain; the hopper's flow
  patterns, Fig. 6.2);

The centripetal compaction's Figs. 6.4-6.8 are in randall_centripetal.py,
the contact stresses of Figs. 6.42-6.43 in randall_contact_stresses.py,
the contact lattice of Fig. 6.35 in randall_lattice.py; randall.py draws
them all from a dem_validate output directory (``python3 -m dem.plots
randall DIR``).
"""

import csv
import math

import numpy as np

from .figure import finish, new_axes


def read_rows(path):
    with open(path, newline="") as source:
        return list(csv.DictReader(source))


def plot_rose(bins, *, ax=None, png=None, title=None, label=None):
    """A rose from rows with angle_low, angle_high (rad) and share: each
    class a sector whose radius is its share over the share of a circle."""
    if ax is None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        figure = Figure(figsize=(4.8, 4.8), dpi=100, layout="constrained")
        FigureCanvasAgg(figure)
        ax = figure.add_subplot(projection="polar")
    figure = ax.figure
    low = np.array([float(b["angle_low"]) for b in bins])
    high = np.array([float(b["angle_high"]) for b in bins])
    share = np.array([float(b["share"]) for b in bins])
    uniform = 1.0 / max(len(bins), 1)
    ax.bar(low, share / uniform, width=high - low, align="edge", edgecolor="0.2", linewidth=0.5, alpha=0.7,
           label=label)
    ax.plot(np.linspace(0, 2 * math.pi, 200), np.ones(200), "k:", linewidth=0.8)  # a circle: no anisotropy
    ax.set_yticklabels([])
    ax.set_title(title or "contact normals", fontsize="medium")
    return finish(figure, png)


def plot_obliquity_histogram(bins, *, ax=None, png=None, title=None):
    """The obliquity classes (obliquity_low, obliquity_high, share)."""
    figure, ax = new_axes(ax)
    low = np.array([float(b["obliquity_low"]) for b in bins])
    high = np.array([float(b["obliquity_high"]) for b in bins])
    share = np.array([float(b["share"]) for b in bins])
    ax.bar(low, share, width=high - low, align="edge", edgecolor="0.2", linewidth=0.5)
    _label(ax, r"$F_s / \mu F_n$ (sliding at $\pm 1$)", "share of contacts", title or "contact force obliquities",
           legend=None)
    return finish(figure, png)


def _by_region(rows):
    regions = {}
    for row in rows:
        regions.setdefault(row["region"], []).append(row)
    return regions


def plot_shear_series(rows, *, png=None, title=None):
    """Four panels against the deviator strain (%): sin(phi) with the
    tangential share, sliding contacts, anisotropy, coordination."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(figsize=(10, 7), dpi=100, layout="constrained")
    FigureCanvasAgg(figure)
    axes = figure.subplots(2, 2)
    for region, series in _by_region(rows).items():
        strain = 100 * np.array([float(r["deviator_strain"]) for r in series])
        get = lambda key: np.array([float(r[key]) for r in series])  # noqa: E731
        axes[0, 0].plot(strain, get("sin_phi"), label=f"{region}")
        axes[0, 0].plot(strain, get("sin_phi") * get("tangential_share"), "--", linewidth=0.8,
                        label=f"{region}: tangential part")
        axes[0, 1].plot(strain, 100 * get("sliding_fraction"), label=region)
        axes[1, 0].plot(strain, get("anisotropy"), label=region)
        axes[1, 1].plot(strain, get("coordination"), label=region)
    for ax, label in ((axes[0, 0], r"$\sin\phi$ (Fig. 6.24)"), (axes[0, 1], "sliding contacts, % (Fig. 6.28)"),
                      (axes[1, 0], r"anisotropy $\Phi_1 - \Phi_2$ (Fig. 6.29)"),
                      (axes[1, 1], "coordination number (Fig. 6.30)")):
        _label(ax, "deviator strain, %", label, "", legend="x-small")
    figure.suptitle(title or "constant-volume shear", fontsize="medium")
    return finish(figure, png)


def _label(ax, xlabel, ylabel, title, legend="small"):
    """Axis labels, the title, a light grid and (unless None) a legend."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize="medium")
    ax.grid(True, alpha=0.3)
    if legend:
        ax.legend(fontsize=legend)


def plot_stress_path(rows, *, png=None, title=None):
    """Two panels for each region: t against s (kPa, Fig. 6.27), and the
    isotropic stress s against the deviator strain (%, Fig. 6.25: its
    build-up at constant volume)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(figsize=(10, 4.5), dpi=100, layout="constrained")
    FigureCanvasAgg(figure)
    path, isotropic = figure.subplots(1, 2)
    for region, series in _by_region(rows).items():
        s1 = np.array([float(r["stress_1"]) for r in series])
        s2 = np.array([float(r["stress_2"]) for r in series])
        strain = 100 * np.array([float(r["deviator_strain"]) for r in series])
        path.plot((s1 + s2) / 2e3, (s1 - s2) / 2e3, label=region)
        isotropic.plot(strain, (s1 + s2) / 2e3, label=region)
    _label(path, "s = (σ1 + σ2) / 2, kPa", "t = (σ1 − σ2) / 2, kPa", "stress path (Fig. 6.27)")
    _label(isotropic, "deviator strain, %", "s = (σ1 + σ2) / 2, kPa", "isotropic stress (Fig. 6.25)")
    if title:
        figure.suptitle(title, fontsize="medium")
    return finish(figure, png)


def plot_discharge(rows, *, png=None, title=None):
    """Particles discharged against time, one line per hopper run
    (hopper.csv: run, time, discharged)."""
    figure, ax = new_axes(None)
    runs = {}
    for row in rows:
        runs.setdefault(row["run"], []).append((float(row["time"]), int(row["discharged"])))
    for run, points in runs.items():
        t, n = zip(*points)
        ax.plot(t, n, label=run)
    _label(ax, "time since the orifice opened, s", "particles discharged",
           title or "hopper discharge (Randall 6.2)", legend="x-small")
    return finish(figure, png)


def plot_velocity_field(rows, *, png=None, title=None):
    """Particles (particles.csv rows: x, y, radius, vx, vy) as circles with
    their velocities as arrows, the arrows scaled together so the fastest is
    two mean diameters long."""
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle

    figure, ax = new_axes(None)
    x = np.array([float(r["x"]) for r in rows])
    y = np.array([float(r["y"]) for r in rows])
    radius = np.array([float(r["radius"]) for r in rows])
    vx = np.array([float(r["vx"]) for r in rows])
    vy = np.array([float(r["vy"]) for r in rows])
    ax.add_collection(PatchCollection([Circle((a, b), c) for a, b, c in zip(x, y, radius)], facecolor="none",
                                      edgecolor="0.7", linewidth=0.4))
    fastest = float(np.max(np.hypot(vx, vy))) if len(rows) else 0.0
    if fastest > 0.0:
        scale = 4.0 * float(np.mean(radius)) / fastest
        ax.quiver(x, y, vx * scale, vy * scale, angles="xy", scale_units="xy", scale=1.0, width=0.003, color="C0")
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("x, m")
    ax.set_ylabel("y, m")
    ax.set_title(title or f"particle velocities (largest {fastest:.3g} m/s)", fontsize="medium")
    return finish(figure, png)
