"""Miyata et al. (2002) figures of the forces on the plates, from
plate_contacts.csv, force_distribution.csv and force_tail.csv:

- plot_contact_map: where the contacts on each plate are and how strong
  (circle area in proportion to the force), at a stress (Fig. 34: 400 kPa);
  3D over the plate's x-y face, 2D along x;
- plot_force_density: the probability density of f = F/<F> on each plate,
  log scale, with Mueth et al.'s eq. (61), the q-model's eq. (62) and the
  exponential tail fitted above f = 1 (Fig. 35);
- plot_load_share: the share of the load carried by each class of f
  (Fig. 37), with the two models' f P(f).
"""

import numpy as np
from matplotlib.patches import Rectangle

from ..force_distribution import mueth_density, q_model_density
from .figure import finish
from .miyata_loading import new_figure, seed_title
from .miyata_run import MissingInput, select

SEED_MAP_STRESS = 400e3  # Pa: Fig. 34


def map_snapshot(run, stress=None):
    """The snapshot of a contact map: the for_contacts one (any, for files
    without the column) whose target is nearest ``stress`` (default the
    seed's 400 kPa), leaving out the loading's start."""
    try:
        snapshots = run.snapshots("for_contacts")
    except MissingInput:
        snapshots = run.snapshots()
    snapshots = [s for s in snapshots if s[1] > 0]
    if not snapshots:
        raise MissingInput("plate_contacts.csv has no snapshot under load")
    wanted = SEED_MAP_STRESS if stress is None else stress
    return min(snapshots, key=lambda s: abs(s[1] - wanted))


def plate_rows(run, snapshot_index, plate):
    table = run.table("plate_contacts.csv")
    return select(table, (table["snapshot"] == snapshot_index) & (table["plate"] == plate))


def wrap(values, low, high):
    """Positions brought into the periodic cell [low, high)."""
    return low + np.mod(values - low, high - low)


def plot_contact_map(run, *, stress=None, png=None):
    """Fig. 34 at the snapshot map_snapshot picks: both plates side by
    side (3D) or one above the other (2D), one scale for both."""
    index, target, cycle, measured = map_snapshot(run, stress)
    loading, bottom = run.plate_names()
    plates = [(loading, "loading plate", plate_rows(run, index, loading)),
              (bottom, "bottom plate", plate_rows(run, index, bottom))]
    largest = max((rows["normal_force"].max() for _, _, rows in plates if rows["normal_force"].size), default=0.0)
    if largest <= 0:
        raise MissingInput(f"no contact force on either plate at snapshot {index}")
    cell = run.cell()
    three = run.dimension == 3
    figure = new_figure((14, 6.2) if three else (13, 5.5))
    axes = figure.subplots(1, 2) if three else figure.subplots(2, 1, sharex=True)
    biggest_marker = 900.0 if three else 1400.0  # points^2: the largest force's circle
    for ax, (name, role, rows) in zip(axes, plates):
        x = rows["x"]
        y = rows["y"] if three else np.zeros_like(x)
        if cell is not None:
            x = wrap(x, cell[0][0], cell[1][0])
            if three and len(cell[0]) > 1:
                y = wrap(y, cell[0][1], cell[1][1])
        force = rows["normal_force"]
        ax.scatter(x, y, s=biggest_marker * force / largest, facecolor="tab:blue", alpha=0.45, edgecolor="black",
                   linewidth=0.5)
        mean = force.mean() if force.size else 0.0
        for value, text in ((largest, "the largest of both"), (mean, "this plate's mean <F>")):
            if value > 0:
                ax.scatter([], [], s=biggest_marker * value / largest, facecolor="tab:blue", alpha=0.45,
                           edgecolor="black", linewidth=0.5, label=f"{force_text(value)}: {text}")
        if cell is not None:
            if three:
                ax.add_patch(Rectangle(cell[0][:2], *(cell[1][:2] - cell[0][:2]), fill=False, color="0.3",
                                       linestyle="--", linewidth=1, label="the periodic cell"))
            else:
                for edge, label in ((cell[0][0], "the periodic cell"), (cell[1][0], None)):
                    ax.axvline(edge, color="0.3", linestyle="--", linewidth=1, label=label)
        ax.set_title(f"{role} ({name}): {force.size} contacts", fontsize="small")
        ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1.0), labelspacing=2.6,
                  borderpad=1.4, handletextpad=1.6)
        if three:
            ax.set_aspect("equal")
            ax.set_xlabel("x, m")
            ax.set_ylabel("y, m")
            ax.margins(0.12)
        else:
            ax.set_yticks([])
            ax.set_ylim(-1, 1.6)
            ax.margins(x=0.05)
    if not three:
        axes[-1].set_xlabel("x along the plate, m")
    figure.suptitle(seed_title(34, f"contact forces on the plates at {measured / 1e3:.0f} kPa (target "
                                   f"{target / 1e3:.0f} kPa, cycle {cycle}); circle area ∝ force", run),
                    fontsize="medium")
    return finish(figure, png)


def force_text(newtons):
    return f"{newtons / 1e6:.3g} MN" if newtons >= 1e6 else f"{newtons / 1e3:.3g} kN"


def distributions(run):
    """force_distribution.csv by plate, the loading plate first: {plate: rows}."""
    table = run.table("force_distribution.csv")
    return {str(p): select(table, table["plate"] == p) for p in dict.fromkeys(table["plate"])}


def tails(run):
    """force_tail.csv by plate: {plate: row dict}."""
    if not run.has("force_tail.csv"):
        return {}
    table = run.table("force_tail.csv")
    return {str(p): {name: values[k] for name, values in table.items()} for k, p in enumerate(table["plate"])}


def plot_force_density(run, *, png=None):
    """Fig. 35: each plate's P(f) as bars on a log scale, the two models,
    and the tail's exponential fit with its decay rate."""
    by_plate = distributions(run)
    fits = tails(run)
    figure = new_figure((12, 5.2))
    axes = figure.subplots(1, len(by_plate), sharey=True, squeeze=False)[0]
    # The models' tails are drawn to f = 4 at least (the seed's Fig. 35 shows them to f = 5).
    top = max(4.0, max(rows["f_high"][rows["contacts"] > 0].max() for rows in by_plate.values()
                       if rows["contacts"].sum()))
    f = np.linspace(1e-3, top, 400)
    positive = [rows["probability_density"][rows["probability_density"] > 0] for rows in by_plate.values()]
    floor = 0.5 * min(p.min() for p in positive if p.size)
    for ax, (role, (plate, rows)) in zip(axes, zip(("loading plate", "bottom plate"), by_plate.items())):
        shown = rows["probability_density"] > 0
        ax.bar(rows["f_low"][shown], rows["probability_density"][shown],
               width=(rows["f_high"] - rows["f_low"])[shown], align="edge", color="tab:blue", alpha=0.55,
               edgecolor="black", linewidth=0.5, label=f"{int(rows['contacts'].sum())} contacts")
        ax.plot(f, mueth_density(f), "k-", linewidth=2, label="Mueth et al., eq. (61): decay 1.39")
        ax.plot(f, q_model_density(f, 3), "k:", linewidth=2, label="q-model, eq. (62), N = 3: decay 1.89")
        fit = fits.get(plate)
        if fit and fit["tail_contacts"] > 0 and np.isfinite(fit["decay_rate"]):
            beta, start = fit["decay_rate"], fit["tail_from"]
            tail = f[f >= start]
            # P(f) = (n_tail / n) beta exp(-beta (f - from)) above `from`.
            ax.plot(tail, fit["tail_contacts"] / fit["contacts"] * beta * np.exp(-beta * (tail - start)), "--",
                    color="tab:red", linewidth=2,
                    label=f"tail above f = {start:g}: decay {beta:.2f} ± {fit['decay_rate_error']:.2f}")
            ax.set_title(f"{role} ({plate}): {int(fit['snapshots'])} snapshots", fontsize="small")
        else:
            ax.set_title(f"{role} ({plate})", fontsize="small")
        ax.set_yscale("log")
        ax.set_ylim(min(floor, 1e-3), 12.0)  # the models to 1e-3; room above the densities for the legend
        ax.set_xlim(0, top)
        ax.set_xlabel("normalised contact force f = F / <F>")
        ax.grid(True, alpha=0.3, which="both")
        ax.legend(fontsize="x-small", loc="upper right")
    axes[0].set_ylabel("probability density P(f)")
    figure.suptitle(seed_title(35, "probability density of the normalised contact force", run), fontsize="medium")
    return finish(figure, png)


def model_load_density(f, density):
    """The load carried per unit f under a density: f P(f) over its mean
    (1 for the q-model; Mueth's eq. (61) is not normalised to mean 1)."""
    grid = np.linspace(0.0, 30.0, 30001)
    mean = np.trapz(grid * density(grid), grid)
    return f * density(f) / mean


def share_of_load(rows, low, high):
    """The share of the load carried by the classes within [low, high)."""
    inside = (rows["f_low"] >= low - 1e-12) & (rows["f_high"] <= high + 1e-12)
    return float(rows["load_share"][inside].sum())


def plot_load_share(run, *, png=None):
    """Fig. 37: the load carried per class of f on each plate (the load
    density: the class's share of the load over its width)."""
    by_plate = distributions(run)
    figure = new_figure((9, 6.2))
    ax = figure.add_subplot()
    styles = ({"color": "black", "linewidth": 2.5}, {"color": "black", "linewidth": 1.8, "linestyle": ":"})
    notes = []
    top = 0.0
    for (role, style), (plate, rows) in zip(zip(("loading plate", "bottom plate"), styles), by_plate.items()):
        middle = 0.5 * (rows["f_low"] + rows["f_high"])
        ax.plot(middle, rows["load_density"], marker="o", markersize=3, label=f"{role} ({plate})", **style)
        top = max(top, rows["f_high"][rows["contacts"] > 0].max(initial=0.0))
        notes.append(f"{role}: f < 0.5 carries {100 * share_of_load(rows, 0, 0.5):.0f} %, "
                     f"0.5-2 {100 * share_of_load(rows, 0.5, 2.0):.0f} %, "
                     f"f > 2 {100 * share_of_load(rows, 2.0, np.inf):.0f} %")
    top = max(top, 4.0)  # the models' tails, as in Fig. 35
    f = np.linspace(0.0, top, 400)
    ax.plot(f, model_load_density(f, lambda x: q_model_density(x, 3)), color="tab:orange", linewidth=1.2,
            label="q-model, eq. (62): f P(f)")
    ax.plot(f, model_load_density(f, mueth_density), color="tab:green", linewidth=1.2,
            label="Mueth et al., eq. (61): f P(f) / ∫ f P(f) df")
    ax.text(0.02, 0.98, "\n".join(notes), transform=ax.transAxes, ha="left", va="top", fontsize="small",
            bbox={"facecolor": "white", "alpha": 0.8, "edgecolor": "0.7"})
    ax.set_xlim(0, top)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("normalised contact force f = F / <F>")
    ax.set_ylabel("load support ratio per unit f")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=2)
    ax.set_title(seed_title(37, "probability density of the load support ratio", run), fontsize="medium")
    return finish(figure, png)
