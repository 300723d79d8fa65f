"""Figures without pyplot: a Figure on the Agg canvas draws and writes PNG
files headless, whatever backend pyplot would pick, and keeps no global
state. Only the live plot's window (stress_settlement.LiveStressSettlement
with show=True) uses pyplot."""

import os
import pathlib

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure


def new_axes(ax=None, size=(6.4, 4.8)):
    """The axes to draw on: ``ax`` itself, or those of a new Agg figure."""
    if ax is not None:
        return ax.figure, ax
    figure = Figure(figsize=size, dpi=100, layout="constrained")  # room for the labels
    FigureCanvasAgg(figure)
    return figure, figure.add_subplot()


def save_png(figure, path):
    """Writes the figure as a PNG; a reader never sees a half-written file
    (written beside it, then renamed over it). Returns the path."""
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    partial = path.with_name(path.name + ".partial")
    figure.savefig(partial, format="png")
    os.replace(partial, path)
    return path


def finish(figure, png):
    """Saves the figure when a path is given; returns the figure."""
    if png is not None:
        save_png(figure, png)
    return figure
