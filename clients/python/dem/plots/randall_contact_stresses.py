"""Randall's (1989) Figs. 6.42-6.43 and his section 4.6's contact
statistics, from the tables ``dem_validate randall-shear --out DIR`` writes
(contact_stresses.csv, size_contacts.csv):

- plot_contact_stress_histograms: the mean normal contact stress N / (pi
  a^2) of the contacts in the first measurement region at 0, 0.1 and 0.2 %
  deviator strain, one histogram a state on the same classes, each with
  the normal distribution of its mean and standard deviation (Randall: "at
  the start of shear the distribution ... approximates a normal
  distribution", its spread growing with the strain);
- plot_size_contacts: each particle size's coordination and share of the
  contacts (4.6: "whether ... it is the smallest particles that are
  generally redundant").
"""

import math

import numpy as np

from .figure import finish, new_axes


def _by_state(rows):
    states = {}
    for row in rows:
        states.setdefault(row["state"], []).append(row)
    return states


def plot_contact_stress_histograms(rows, *, png=None, title=None, bins=20):
    """contact_stresses.csv rows (state, normal_stress in Pa, ...): one panel a
    state, stacked, on classes shared by all, in MPa."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    states = _by_state(rows)
    figure = Figure(figsize=(7.0, 2.4 * max(len(states), 1) + 0.6), dpi=100, layout="constrained")
    FigureCanvasAgg(figure)
    axes = figure.subplots(max(len(states), 1), 1, sharex=True, squeeze=False)[:, 0]
    stresses = {state: np.array([float(r["normal_stress"]) for r in series]) / 1e6 for state, series in states.items()}
    largest = max((float(s.max()) for s in stresses.values() if len(s)), default=1.0)
    edges = np.linspace(0.0, largest * 1.0001, bins + 1)
    for ax, (state, values) in zip(axes, stresses.items()):
        ax.hist(values, bins=edges, color="0.6", edgecolor="0.3", label=f"{len(values)} contacts")
        if len(values) > 1:
            mean, deviation = float(values.mean()), float(values.std(ddof=1))
            x = np.linspace(edges[0], edges[-1], 200)
            density = np.exp(-0.5 * ((x - mean) / deviation) ** 2) / (deviation * math.sqrt(2 * math.pi))
            ax.plot(x, density * len(values) * (edges[1] - edges[0]), color="C0",
                    label=f"normal: mean {mean:.0f}, sd {deviation:.0f} MPa")
        ax.set_ylabel("contacts")
        ax.set_title(f"deviator strain {state}", fontsize="medium")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="x-small")
    axes[-1].set_xlabel("mean normal contact stress N / (π a²), MPa")
    figure.suptitle(title or "mean normal contact stresses (Randall Figs. 6.42 graded, 6.43 uniform)",
                    fontsize="medium")
    return finish(figure, png)


def plot_size_contacts(rows, *, png=None, title=None):
    """size_contacts.csv rows of the first state: each size's coordination
    number (bars) and its share of the contacts."""
    first = next(iter(_by_state(rows).values()), [])
    first = [r for r in first if int(r["particles"]) > 0]
    figure, ax = new_axes(None)
    labels = [f"{1e3 * float(r['radius']):.2f}" for r in first]
    coordination = [float(r["coordination"]) for r in first]
    bars = ax.bar(labels, coordination, color="0.6", edgecolor="0.3")
    for bar, row in zip(bars, first):
        ax.annotate(f"{100 * float(row['share']):.0f} % of contacts\n{row['particles']} particles",
                    (bar.get_x() + bar.get_width() / 2, bar.get_height()), ha="center", va="bottom",
                    fontsize="x-small")
    ax.set_xlabel("particle radius, mm")
    ax.set_ylabel("contacts a particle")
    state = first[0]["state"] if first else ""
    ax.set_title(title or f"each size's contacts at {state} (Randall 4.6)", fontsize="medium")
    ax.grid(True, axis="y", alpha=0.3)
    return finish(figure, png)
