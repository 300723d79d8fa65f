"""A sweep's results drawn together (dem.sweep.Results): the family of
stress-settlement curves, one per task, coloured by a swept parameter, and
a final measure against that parameter."""

import numpy as np
from matplotlib import colormaps
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize
from matplotlib.ticker import EngFormatter

from .figure import finish, new_axes


def _parameter(results, parameter):
    names = list(results.parameters.dtype.names)
    parameter = parameter or names[0]
    if parameter not in names:
        raise ValueError(f"the sweep has no parameter {parameter!r} (parameters: {', '.join(names)})")
    return parameter, results.parameters[parameter]


def plot_stress_settlement_family(results, *, parameter=None, ax=None, png=None, title=None, cmap="viridis"):
    """The loading plate's normal stress against its settlement for every
    task with a series, coloured by `parameter` (default: the first swept)."""
    figure, ax = new_axes(ax)
    parameter, values = _parameter(results, parameter)
    numeric = np.issubdtype(values.dtype, np.number)
    colours = colormaps[cmap]
    norm = Normalize(float(values.min()), float(values.max())) if numeric and values.size else None
    for index in np.argsort(values, kind="stable"):
        settlement, stress = results.curve(index)
        if not settlement.size:
            continue
        colour = colours(norm(float(values[index]))) if norm is not None and norm.vmax > norm.vmin else None
        state = "" if results.states[index] == "done" else f" ({results.states[index]})"
        ax.plot(settlement, stress, linewidth=1.2, color=colour, label=f"{parameter} = {values[index]}{state}")
    ax.set_xlabel("settlement")
    ax.set_ylabel("normal stress")
    ax.xaxis.set_major_formatter(EngFormatter(unit="m"))
    ax.yaxis.set_major_formatter(EngFormatter(unit="Pa"))
    ax.grid(True, alpha=0.3)
    if norm is not None and norm.vmax > norm.vmin:
        figure.colorbar(ScalarMappable(norm=norm, cmap=colours), ax=ax, label=parameter)
    if len(results) <= 12:
        ax.legend(fontsize="small")
    if title:
        ax.set_title(title, fontsize="medium")
    return finish(figure, png)


def plot_final_measure(results, measure, *, parameter=None, ax=None, png=None, title=None, unit=None, label=None):
    """A final measure (a field of results.final) against a swept parameter,
    for the tasks that are done."""
    figure, ax = new_axes(ax)
    parameter, values = _parameter(results, parameter)
    done = results.states == "done"
    order = np.argsort(values[done], kind="stable")
    ax.plot(values[done][order], results.final[measure][done][order], marker="o")
    ax.set_xlabel(parameter)
    ax.set_ylabel(label or measure.replace("_", " "))
    if unit:
        ax.yaxis.set_major_formatter(EngFormatter(unit=unit))
    ax.grid(True, alpha=0.3)
    if title:
        ax.set_title(title, fontsize="medium")
    return finish(figure, png)
