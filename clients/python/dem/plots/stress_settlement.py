"""A plate's normal stress against its settlement (the curves of Miyata et al.
2002, Figs. 26 and 32), drawn from the server's plate-force telemetry, and
live while a run goes on:

    with press.subscribe() as telemetry, \\
            LiveStressSettlement(telemetry, ["top"], png="out/stress.png") as live:
        press.run_until(wall="top", stress=1e6, max_cycles=100000, on_wait=live.update)

``update()`` runs in the caller's thread (matplotlib is not thread-safe):
Client.cycle and run_until call it through ``on_wait`` while they wait.
Headless it rewrites the PNG (and, with ``frames``, numbered frames) at most
every ``redraw_interval`` seconds; with ``show=True`` it draws in a window.
"""

import csv
import pathlib
import time

import numpy as np
from matplotlib.ticker import EngFormatter

from .figure import finish, new_axes, save_png
from .quasi_static import QUASI_STATIC


class StressSettlementSeries:
    """Each wall's settlement, normal stress and contacts, sample by sample."""

    def __init__(self, walls=None, origin=None):
        self.walls = list(walls) if walls else None  # None: every wall seen
        # Settlement counted from these (wall -> m), e.g. where loading began.
        self.origin = dict(origin or {})
        self._rows = {}  # wall -> list of (cycle, time, settlement, stress, contacts)
        # The quasi-static measures sample by sample (column -> values, in
        # the order of the first wall's rows), when the source has them: a
        # demctl monitor table (docs/CASES.md, "Quasi-static measures").
        self.measures = {}

    def add(self, plate_forces):
        """Adds one PlateForces sample (telemetry or a reply's ``plates``)."""
        for wall in plate_forces.walls:
            if self.walls is not None and wall.name not in self.walls:
                continue
            rows = self._rows.setdefault(wall.name, [])
            if rows and rows[-1][0] == plate_forces.cycle:
                continue  # the same cycle again (a reply after the telemetry)
            settlement = wall.settlement - self.origin.get(wall.name, 0.0)
            rows.append((plate_forces.cycle, plate_forces.time, settlement, wall.normal_stress, wall.contacts))

    @classmethod
    def from_monitor_csv(cls, path, walls=None):
        """The rows ``demctl monitor --csv`` recorded: cycle, time and, per
        plate shown, <wall>_stress and <wall>_settlement (the monitor's
        contacts column counts the whole sample's, so a plate's is 0 here)."""
        with open(path, newline="") as source:
            rows = list(csv.DictReader(source))
        columns = rows[0].keys() if rows else []
        shown = [c[: -len("_stress")] for c in columns if c.endswith("_stress")]
        unknown = [w for w in walls or [] if w not in shown]
        if unknown:
            raise ValueError(f"{path}: no plate {', '.join(unknown)} in the monitor's columns (plates: {', '.join(shown)})")
        series = cls(walls or shown)
        for row in rows:
            for wall in series.walls:
                series._rows.setdefault(wall, []).append(
                    (int(row["cycle"]), float(row["time"]), float(row[f"{wall}_settlement"]),
                     float(row[f"{wall}_stress"]), 0))
        for column, *_ in QUASI_STATIC:
            if column in columns:
                series.measures[column] = np.array([float(row[column]) for row in rows])
        return series

    @classmethod
    def from_walls_csv(cls, path, walls=None):
        """walls.csv of dem_run or dem_server: one row per wall per output
        interval with its normal_stress and settlement."""
        with open(path, newline="") as source:
            rows = list(csv.DictReader(source))
        shown = list(dict.fromkeys(row["wall"] for row in rows))
        unknown = [w for w in walls or [] if w not in shown]
        if unknown:
            raise ValueError(f"{path}: no wall {', '.join(unknown)} (walls: {', '.join(shown)})")
        series = cls(walls or shown)
        for row in rows:
            if row["wall"] in series.walls:
                series._rows.setdefault(row["wall"], []).append(
                    (int(row["cycle"]), float(row["time"]), float(row["settlement"]), float(row["normal_stress"]),
                     int(row["contacts"])))
        return series

    @classmethod
    def from_compression_csv(cls, path, walls=None):
        """compression.csv of the plate loading analyses: the loading plate's
        stress and settlement from the loading stage on (its name is not in
        the file: the curve is called "loading plate")."""
        if walls:
            raise ValueError(f"{path}: compression.csv holds the loading plate only; leave out --wall "
                             "(walls.csv has every wall)")
        with open(path, newline="") as source:
            rows = list(csv.DictReader(source))
        series = cls(["loading plate"])
        series._rows["loading plate"] = [(int(row["cycle"]), float(row["time"]), float(row["settlement"]),
                                          float(row["stress"]), int(row["loading_contacts"])) for row in rows]
        return series

    @classmethod
    def from_recording(cls, path, walls=None):
        """A `demctl record` recording (MCAP): every plate forces sample in it."""
        from ..recording import Recording

        recording = Recording(path)
        topics = [t for t, schema in recording.topics().items() if schema == "dem_interfaces/msg/PlateForces"]
        if not topics:
            raise ValueError(f"{path}: no plate forces in this recording (topics: {', '.join(recording.topics())})")
        series = cls(walls)
        for topic in topics:
            for message in recording.messages(topic):
                series.add(message.data)
        shown = list(series._rows)
        unknown = [w for w in walls or [] if w not in shown]
        if unknown:
            raise ValueError(f"{path}: no wall {', '.join(unknown)} in the plate forces (walls: {', '.join(shown)})")
        return series

    @classmethod
    def from_file(cls, path, walls=None):
        """Any file that holds plates' stress and settlement: a `demctl
        monitor --csv` table, walls.csv or compression.csv of dem_run and
        dem_server, or a `demctl record` recording (.mcap)."""
        path = pathlib.Path(path)
        if path.suffix == ".mcap":
            return cls.from_recording(path, walls)
        with open(path, newline="") as source:
            columns = next(csv.reader(source), [])
        if {"wall", "normal_stress", "settlement"} <= set(columns):
            return cls.from_walls_csv(path, walls)
        if {"stress", "settlement", "loading_contacts"} <= set(columns):
            return cls.from_compression_csv(path, walls)
        if any(c.endswith("_stress") for c in columns) and any(c.endswith("_settlement") for c in columns):
            return cls.from_monitor_csv(path, walls)
        raise ValueError(f"{path}: no plate stress and settlement in it (columns: {', '.join(columns) or 'none'}); "
                         "give a demctl monitor --csv table, walls.csv, compression.csv or a demctl record .mcap")

    def names(self):
        return list(self.walls) if self.walls is not None else list(self._rows)

    def __len__(self):
        return sum(len(rows) for rows in self._rows.values())

    def column(self, wall, name):
        """cycle, time, settlement (m), stress (Pa) or contacts of one wall, as an array."""
        index = ("cycle", "time", "settlement", "stress", "contacts").index(name)
        return np.array([row[index] for row in self._rows.get(wall, [])])

    def write_csv(self, path):
        """One row per wall per sample: wall,cycle,time,settlement,stress,contacts."""
        path = pathlib.Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        with open(path, "w", newline="") as out:
            writer = csv.writer(out)
            writer.writerow(["wall", "cycle", "time", "settlement", "stress", "contacts"])
            for wall in self.names():
                for row in self._rows.get(wall, []):
                    writer.writerow([wall, *(repr(v) if isinstance(v, float) else v for v in row)])
        return path


def plot_stress_settlement(series, *, walls=None, ax=None, png=None, title=None):
    """Normal stress (Pa) against settlement (m), one curve per wall; with
    the quasi-static measures under it, against the first wall's
    settlement, when the series has them (and no axes were given)."""
    walls = walls or series.names()
    if ax is not None or not series.measures or not walls:
        figure, ax = new_axes(ax)
        _draw(ax, series, walls, title)
        return finish(figure, png)
    from .miyata_loading import new_figure
    from .quasi_static import draw_quasi_static_panels

    panels = [column for column, *_ in QUASI_STATIC if column in series.measures]
    figure = new_figure((8.0, 5.0 + 1.5 * len(panels)))
    axes = figure.subplots(1 + len(panels), 1, sharex=True,
                           gridspec_kw={"height_ratios": [3.0] + [1] * len(panels)}, squeeze=False)[:, 0]
    _draw(axes[0], series, walls, title)
    axes[0].set_xlabel("")
    draw_quasi_static_panels(axes[1:], series.column(walls[0], "settlement"), series.measures, panels)
    axes[-1].set_xlabel(f"settlement of {walls[0]}")
    axes[-1].xaxis.set_major_formatter(EngFormatter(unit="m"))
    return finish(figure, png)


def _draw(ax, series, walls, title):
    ax.clear()
    for wall in walls:
        settlement = series.column(wall, "settlement")
        if settlement.size:
            ax.plot(settlement, series.column(wall, "stress"), marker=".", markersize=3, linewidth=1, label=wall)
    ax.set_xlabel("settlement")
    ax.set_ylabel("normal stress")
    ax.xaxis.set_major_formatter(EngFormatter(unit="m"))
    ax.yaxis.set_major_formatter(EngFormatter(unit="Pa"))
    ax.grid(True, alpha=0.3)
    if any(series.column(wall, "settlement").size for wall in walls):
        ax.legend(title="plate")
    if title:
        ax.set_title(title, fontsize="medium")


class LiveStressSettlement:
    """Stress against settlement, redrawn from a Subscription as samples come."""

    def __init__(self, subscription, walls=None, *, png=None, frames=None, show=False, redraw_interval=1.0,
                 title=None):
        self.subscription = subscription
        self.series = StressSettlementSeries(walls)
        self.png = pathlib.Path(png) if png else None
        self.frames = pathlib.Path(frames) if frames else None
        self.frame_count = 0
        self.redraw_interval = redraw_interval
        self.title = title
        self._drawn_at = 0.0
        self._drawn_samples = -1
        self._show = show
        if show:
            from matplotlib import pyplot  # a window only when asked for one
            self._pyplot = pyplot
            pyplot.ion()
            self.figure = pyplot.figure()
            self.ax = self.figure.add_subplot()
        else:
            self.figure, self.ax = new_axes()

    def update(self):
        """Takes the samples that arrived; redraws when due. Returns how many came."""
        samples = [s for s in self.subscription.drain() if hasattr(s, "walls")]
        for sample in samples:
            self.series.add(sample)
        if time.monotonic() - self._drawn_at >= self.redraw_interval:
            self.redraw()
        return len(samples)

    def redraw(self):
        if len(self.series) == self._drawn_samples:
            return
        self._drawn_samples = len(self.series)
        self._drawn_at = time.monotonic()
        _draw(self.ax, self.series, self.series.names(), self.title)
        if self._show:
            self.figure.canvas.draw_idle()
            self._pyplot.pause(0.001)
        if self.png:
            save_png(self.figure, self.png)
        if self.frames:
            self.frame_count += 1
            save_png(self.figure, self.frames / f"stress_settlement_{self.frame_count:04d}.png")

    def finish(self, settle=0.3):
        """Takes the last samples (waiting up to ``settle`` s for stragglers)
        and draws the final picture."""
        deadline = time.monotonic() + settle
        while time.monotonic() < deadline:
            sample = self.subscription.get(max(0.0, deadline - time.monotonic()))
            if sample is None:
                break
            if hasattr(sample, "walls"):
                self.series.add(sample)
        self.update()
        self._drawn_samples = -1
        self.redraw()
        return self.figure

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.finish()


def main(argv=None):
    """python3 -m dem.plots stress-settlement FILE PNG [--wall W ...]: the
    stress-settlement curve from a ``demctl monitor --csv`` table, walls.csv
    or compression.csv (dem_run, dem_server), or a ``demctl record``
    recording (.mcap)."""
    import argparse

    parser = argparse.ArgumentParser(prog="python3 -m dem.plots stress-settlement", description=main.__doc__)
    parser.add_argument("file", help="monitor.csv, walls.csv, compression.csv or a .mcap recording")
    parser.add_argument("png")
    parser.add_argument("--wall", action="append", help="plates to draw (default: every plate recorded)")
    parser.add_argument("--title")
    args = parser.parse_args(argv)
    try:
        series = StressSettlementSeries.from_file(args.file, args.wall)
    except (OSError, ValueError) as error:
        parser.exit(2, f"{parser.prog}: error: {error}\n")
    plot_stress_settlement(series, png=args.png, title=args.title)
    print(f"wrote {args.png} ({len(series)} points)")
