"""Miyata et al. (2002) figures of the loading as a whole, from a run's
compression.csv and its summaries:

- plot_stress_settlement_states: the loading plate's stress against its
  settlement with the three states shaded, the final state's line and the
  stress drops (Figs. 26 and 32), and under it, on the same settlement axis,
  the quasi-static measures of assembly.csv (docs/CASES.md);
- plot_contact_ratio: the loading plate's contacts over the bottom plate's
  against the stress (Fig. 29);
- plot_plate_contacts: the contacts on each plate against the stress, with
  each state's rate (Fig. 33);
- plot_load_by_formation: the share of the load carried by the contacts
  formed first (40 %), next (30 %) and last (30 %), and by the state they
  formed in (Fig. 30).
"""

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .quasi_static import QUASI_STATIC, draw_quasi_static_panels
from .figure import finish
from .miyata_run import STATES, MissingInput, select

STATE_COLOURS = {"initial": "tab:blue", "transition": "tab:orange", "final": "tab:green"}

def new_figure(size):
    figure = Figure(figsize=size, dpi=100, layout="constrained")
    FigureCanvasAgg(figure)
    return figure


def seed_title(number, text, run):
    return f"Miyata et al. (2002) Fig. {number}: {text}\n{run.name}"


def state_rows(compression, states):
    """{state: the rows of compression.csv in it}, from each state's first
    cycle to the next state's."""
    firsts = [(name, states[name]["first_cycle"]) for name in STATES if name in states]
    rows = {}
    for k, (name, first) in enumerate(firsts):
        end = firsts[k + 1][1] if k + 1 < len(firsts) else np.inf
        rows[name] = select(compression, (compression["cycle"] >= first) & (compression["cycle"] < end))
    return rows


def _shade_states(ax, states, compression, x_of):
    """Each state's span of the x axis, shaded in its colour (x_of maps a
    row of compression.csv to x: settlement or stress)."""
    for name, rows in state_rows(compression, states).items():
        if rows["cycle"].size == 0:
            continue
        x = x_of(rows)
        row = states[name]
        ax.axvspan(x.min(), x.max(), color=STATE_COLOURS[name], alpha=0.12, linewidth=0,
                   label=f"{name}: {row['stress_from'] / 1e3:.0f}-{row['stress_to'] / 1e3:.0f} kPa")


def plot_stress_settlement_states(run, *, png=None):
    """Fig. 26 (2D) or 32 (3D), with the quasi-static measures under it
    when assembly.csv is there."""
    compression = run.table("compression.csv")
    states = run.states()
    measures = run.table("assembly.csv") if run.has("assembly.csv") else None
    panels = 1 + (len(QUASI_STATIC) if measures is not None else 0)
    figure = new_figure((8.5, 5.5 + 1.6 * (panels - 1)))
    axes = figure.subplots(panels, 1, sharex=True, gridspec_kw={"height_ratios": [3.2] + [1] * (panels - 1)},
                           squeeze=False)[:, 0]
    ax = axes[0]
    settlement = compression["settlement"]
    _shade_states(ax, states, compression, lambda rows: rows["settlement"])
    ax.plot(settlement, compression["stress"] / 1e3, color="black", linewidth=1.2, label="loading plate")
    if "final" in states:
        final = state_rows(compression, states)["final"]
        if final["cycle"].size >= 2:
            slope = states["final"]["tangent_stiffness"]
            x = final["settlement"]
            intercept = final["stress"].mean() - slope * x.mean()
            ax.plot(x, (intercept + slope * x) / 1e3, "--", color="tab:green", linewidth=1.5,
                    label=f"final state's line: {slope / 1e6:.3g} MPa/m, R² = {states['final']['r_squared']:.3f}")
    if run.has("stress_drops.csv"):
        drops = run.table("stress_drops.csv")
        count = drops["peak_cycle"].size
        by_cycle = dict(zip(compression["cycle"].astype(int), settlement))
        for k in range(count):
            trough = by_cycle.get(int(drops["trough_cycle"][k]), drops["peak_settlement"][k])
            ax.plot([drops["peak_settlement"][k], trough],
                    [drops["peak_stress"][k] / 1e3, drops["trough_stress"][k] / 1e3], color="red", linewidth=1.5)
        if count:
            ax.plot(drops["peak_settlement"], drops["peak_stress"] / 1e3, "v", color="red", markersize=6,
                    label=f"stress drops ({count}; largest {100 * drops['relative_drop'].max():.0f} %)")
        else:
            ax.plot([], [], " ", label="no stress drops")
    ax.set_ylabel("vertical stress on the plate, kPa")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="upper left")
    number = 32 if run.dimension == 3 else 26
    ax.set_title(seed_title(number, "stress-settlement relation of the loading plate", run), fontsize="medium")
    if measures is not None:
        _draw_quasi_static(axes[1:], compression, measures)
    axes[-1].set_xlabel("settlement of the loading plate, m")
    return finish(figure, png)


def _draw_quasi_static(axes, compression, measures):
    """assembly.csv's measures at the cycles of compression.csv, against the settlement."""
    settlement_at = dict(zip(compression["cycle"].astype(int), compression["settlement"]))
    cycles = measures["cycle"].astype(int)
    rows = np.array([c in settlement_at for c in cycles])
    x = np.array([settlement_at[c] for c in cycles[rows]])
    draw_quasi_static_panels(axes, x, {column: measures[column][rows] for column, *_ in QUASI_STATIC
                                       if column in measures})


def _against_stress(run):
    """A figure against the loading plate's stress with the states shaded:
    (figure, axes, compression.csv, the states)."""
    compression = run.table("compression.csv")
    states = run.states()
    figure = new_figure((7.5, 5))
    ax = figure.add_subplot()
    _shade_states(ax, states, compression, lambda rows: rows["stress"] / 1e3)
    return figure, ax, compression, states


def _label_against_stress(ax, run, number, title, ylabel, legend):
    ax.set_xlabel("vertical stress on the loading plate, kPa")
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc=legend)
    ax.set_title(seed_title(number, title, run), fontsize="medium")


def plot_contact_ratio(run, *, png=None):
    """Fig. 29: the loading plate's contacts over the bottom plate's."""
    figure, ax, compression, _ = _against_stress(run)
    touching = compression["bottom_contacts"] > 0
    ax.plot(compression["stress"][touching] / 1e3, compression["contact_ratio"][touching], color="black",
            linewidth=1.2, label="loading / bottom plate contacts")
    _label_against_stress(ax, run, 29, "normalised contact points on the loading plate",
                          "normalised contact points on the loading plate", "lower right")
    return finish(figure, png)


def plot_plate_contacts(run, *, png=None):
    """Fig. 33: the contacts on both plates against the stress, and each
    state's least-squares rate (compression_states.csv's contact_rate)."""
    try:
        loading, bottom = run.plate_names()
    except MissingInput:  # compression.csv does not name them
        loading, bottom = "loading plate", "bottom plate"
    figure, ax, compression, states = _against_stress(run)
    stress = compression["stress"] / 1e3
    ax.plot(stress, compression["loading_contacts"], color="black", linewidth=1.2, label=f"{loading} (loading)")
    ax.plot(stress, compression["bottom_contacts"], color="0.5", linewidth=1.2, label=f"{bottom} (bottom)")
    for name, rows in state_rows(compression, states).items():
        if rows["cycle"].size < 2:
            continue
        rate = states[name]["contact_rate"]  # contacts per Pa
        s = rows["stress"]
        line = rows["loading_contacts"].mean() + rate * (s - s.mean())
        ax.plot(s / 1e3, line, "--", color=STATE_COLOURS[name], linewidth=1.5,
                label=f"{name}: {1e5 * rate:.2g} contacts per 100 kPa")
    _label_against_stress(ax, run, 33, "evolution of the number of contact points", "contact points",
                          "center right")
    return finish(figure, png)


def plot_load_by_formation(run, *, png=None):
    """Fig. 30: each plate's load carried by its contacts grouped by when
    they formed - the seed's first 40 %, next 30 %, last 30 %
    (load_by_formation.csv) and, beside it, by the state they formed in
    (load_by_state.csv) - against the shares equal loads would give."""
    tables = [("load_by_formation.csv", "group", "in the order they formed (the seed's 40/30/30 %)")]
    if run.has("load_by_state.csv"):
        tables.append(("load_by_state.csv", "state", "by the state they formed in"))
    figure = new_figure((5.5 * len(tables), 6))
    axes = figure.subplots(1, len(tables), squeeze=False)[0]
    for ax, (name, column, subtitle) in zip(axes, tables):
        table = run.table(name)
        plates = list(dict.fromkeys(table["plate"]))
        width = 0.8 / len(STATES)
        for k, state in enumerate(STATES):
            rows = table[column] == state
            load = 100 * table["load_share"][rows]
            contacts = 100 * table["contact_share"][rows]
            x = np.arange(len(plates)) + (k - 1) * width
            ax.bar(x, load, width=width, color=STATE_COLOURS[state], alpha=0.8, edgecolor="black", linewidth=0.5,
                   label=f"{state}: load")
            ax.plot(np.column_stack([x - width / 2, x + width / 2]).T, np.vstack([contacts, contacts]),
                    color="black", linewidth=2)
            for xi, value in zip(x, load):
                ax.text(xi, max(value / 2, 3), f"{value:.0f} %", ha="center", va="center", fontsize="small")
        ax.plot([], [], color="black", linewidth=2, label="its share of the contacts (equal loads)")
        ax.set_xticks(np.arange(len(plates)), [f"{p}\n({stress / 1e3:.0f} kPa)"
                                              for p, stress in zip(plates, _stress_per_plate(table, plates))])
        ax.set_ylabel("share of the plate's load, %")
        ax.set_ylim(0, 100)
        ax.grid(True, axis="y", alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2)
        ax.set_title(f"contacts grouped {subtitle}", fontsize="small")
    figure.supxlabel("the seed (2D, 900 kPa): the contacts formed in the initial and transition states carry over "
                     "70 %, the final state's 20 % or less (rectangles: initial > 50 %, final < 15 %)",
                     fontsize="small")
    figure.suptitle(seed_title(30, "load supported by the contacts formed in each state", run), fontsize="medium")
    return finish(figure, png)


def _stress_per_plate(table, plates):
    return [table["stress"][table["plate"] == p][0] for p in plates]
