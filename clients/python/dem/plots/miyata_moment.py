"""Miyata et al. (2002) Fig. 36: the flow of the statistical estimate of a
caisson slab's bending moment from the plate's contact forces (Miyata et
al. 1999), drawn as a diagram, and the estimate itself for each plate
(dem.slab_moment: a simply supported one-way slab spanning the periodic
cell along x): the distribution of the largest moment over Monte Carlo
draws against the moments of the measured snapshots, relative to the
design code's uniform reaction (q L^2 / 8)."""

import numpy as np

from ..slab_moment import PlateLoads, moment_ratio, monte_carlo_ratios
from .figure import finish
from .miyata_loading import new_figure, seed_title
from .miyata_plates import wrap
from .miyata_run import MissingInput, select

FLOW = ("probability density P(f) of f = F/<F>\non the plate (Fig. 35)",
        "contact positions on the plate\n(a measured snapshot, Fig. 34)",
        "draw f for each contact from P(f);\nscale to the snapshot's total load",
        "bending moment M(x) of the slab\n(simply supported, span L)",
        "largest moment M_max;\nrepeat for N trials",
        "distribution of M_max / (q L²/8)\n(q L²/8: the uniform reaction)")


def distribution_snapshots(run, plate):
    """The plate's loads in each snapshot pooled into the force
    distribution (for_distribution), or every snapshot under load for files
    written before that column: [(stress, x positions, forces)]."""
    table = run.table("plate_contacts.csv")
    try:
        chosen = [s[0] for s in run.snapshots("for_distribution")]
    except MissingInput:
        chosen = [s[0] for s in run.snapshots() if s[1] > 0]
    snapshots = []
    for index in chosen:
        rows = select(table, (table["snapshot"] == index) & (table["plate"] == plate))
        if rows["normal_force"].size:
            snapshots.append((rows["stress"][0], rows["x"], rows["y"], rows["normal_force"]))
    return snapshots


def slab_span(run, snapshots_by_plate):
    """(low, high, width, how): the slab's supports along x and its width
    across (3D; 1 in 2D, whose forces are per unit depth) - the periodic
    cell from the run's snapshot, else the extent of the contacts seen."""
    cell = run.cell()
    three = run.dimension == 3
    if cell is not None:
        width = float(cell[1][1] - cell[0][1]) if three else 1.0
        return float(cell[0][0]), float(cell[1][0]), width, "the periodic cell"
    xs = np.concatenate([s[1] for snapshots in snapshots_by_plate.values() for s in snapshots])
    ys = np.concatenate([s[2] for snapshots in snapshots_by_plate.values() for s in snapshots])
    width = float(np.ptp(ys)) if three else 1.0
    return float(xs.min()), float(xs.max()), width, "the contacts' extent (no snapshot file gave the cell)"


def _draw_flow(ax):
    """The seed's flow diagram, box by box."""
    ax.set_axis_off()
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    steps = len(FLOW)
    for k, text in enumerate(FLOW):
        y = 1 - (k + 0.5) / steps
        ax.text(0.5, y, text, ha="center", va="center", fontsize="small",
                bbox={"boxstyle": "round,pad=0.5", "facecolor": "0.93" if k < 2 else "white", "edgecolor": "0.3"})
        if k + 1 < steps:
            ax.annotate("", xy=(0.5, y - 0.5 / steps - 0.03), xytext=(0.5, y - 0.5 / steps + 0.03),
                        arrowprops={"arrowstyle": "-|>", "color": "0.3"})


def plot_bending_moment(run, *, trials=10000, seed=2002, png=None):
    """Fig. 36: the flow diagram and, per plate, the Monte Carlo
    distribution of M_max / (q L^2 / 8) with the measured pdf, the two
    models' and equal forces, against the measured snapshots' values."""
    loading, bottom = run.plate_names()
    by_plate = {plate: distribution_snapshots(run, plate) for plate in (loading, bottom)}
    if not any(by_plate.values()):
        raise MissingInput("plate_contacts.csv has no snapshot with contacts on the plates")
    low, high, width, how = slab_span(run, by_plate)
    span = high - low
    figure = new_figure((15, 7))
    grid = figure.add_gridspec(1, 3, width_ratios=[0.8, 1.3, 1.3])
    _draw_flow(figure.add_subplot(grid[0]))
    for k, (role, plate) in enumerate((("loading plate", loading), ("bottom plate", bottom))):
        ax = figure.add_subplot(grid[k + 1])
        snapshots = [PlateLoads(wrap(x, low, high) - low, forces) for _, x, _, forces in by_plate[plate]]
        if not snapshots:
            ax.text(0.5, 0.5, f"no contacts on {plate}", transform=ax.transAxes, ha="center")
            continue
        measured = np.array([moment_ratio(span, s.positions, s.forces, width) for s in snapshots])
        estimates = {name: monte_carlo_ratios(snapshots, span, width, density=name, trials=trials, seed=seed)
                     for name in ("measured", "q-model", "mueth", "equal")}
        drawn = np.concatenate([estimates[name] for name in ("measured", "q-model", "mueth")])
        left = 0.95 * min(1.0, np.percentile(drawn, 0.5), measured.min())
        right = 1.05 * max(np.percentile(drawn, 99.5), measured.max())
        bins = np.linspace(left, right, 60)
        ax.hist(estimates["measured"], bins=bins, density=True, color="tab:blue", alpha=0.5,
                label=f"measured P(f): mean {estimates['measured'].mean():.2f}, "
                      f"95 % below {np.percentile(estimates['measured'], 95):.2f}")
        for name, style, label in (("q-model", ":", "q-model, eq. (62)"), ("mueth", "-", "Mueth et al., eq. (61)")):
            ax.hist(estimates[name], bins=bins, density=True, histtype="step", linestyle=style, color="black",
                    linewidth=1.5, label=f"{label}: mean {estimates[name].mean():.2f}, "
                                         f"95 % below {np.percentile(estimates[name], 95):.2f}")
        # Equal forces at the measured positions give one value per snapshot: their mean.
        ax.axvline(estimates["equal"].mean(), color="0.45", linestyle="-.", linewidth=1.5,
                   label=f"equal forces f = 1 (the positions alone): mean {estimates['equal'].mean():.2f}")
        for value in measured:
            ax.axvline(value, color="tab:red", linewidth=1.2, alpha=0.8)
        ax.plot([], [], color="tab:red", label=f"the {measured.size} measured snapshots: mean {measured.mean():.2f}")
        ax.axvline(1.0, color="black", linestyle="--", linewidth=1.2, label="uniform reaction (design code): 1")
        ax.set_xlim(left, right)
        ax.set_xlabel("largest bending moment M_max / (q L²/8)")
        ax.set_ylabel("probability density")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2)
        stresses = np.array([s[0] for s in by_plate[plate]])
        ax.set_title(f"{role} ({plate}): {len(snapshots)} snapshots at {stresses.min() / 1e3:.0f}-"
                     f"{stresses.max() / 1e3:.0f} kPa, {trials} trials", fontsize="small")
    figure.suptitle(seed_title(36, "statistical estimate of the bending moment of a slab under the contact forces",
                               run) + f"\nslab: simply supported over L = {span:.3g} m ({how})"
                    + (f", moment per unit width over W = {width:.3g} m" if run.dimension == 3 else
                       ", per unit depth"), fontsize="medium")
    return finish(figure, png)
