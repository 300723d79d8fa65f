"""Randall's (1989) 6.4.2 figures, the centripetal compaction, from the
directory ``dem_validate randall-centripetal --out DIR`` writes
(centripetal.csv, circles.csv, profile.csv, and the contacts and particles of the states
it keeps):

- plot_contact_forces: the contact forces as lines between the centres of
  the particles in contact, as wide as the force is large, with the
  measurement circles (Fig. 6.4 after the centripetal compression, Fig. 6.6
  at 100 kPa);
- plot_porosity_profile: the porosity in rings round the centre (Fig. 6.5),
  after the compaction, at equilibrium and at 100 kPa;
- plot_circle_series: a measure of each circle against its deviator strain,
  sin(phi) from its stress (Fig. 6.7) or its volumetric strain (Fig. 6.8),
  the strains from the circle's best-fit displacement gradient since the
  shear began;
- draw_centripetal_directory: all five, as ``python3 -m dem.plots randall
  DIR`` draws them, each skipped with a line when its files are missing.
"""

import pathlib

import numpy as np

from .figure import finish, new_axes, save_png
from .granular import _by_region, _label, read_rows


def plot_contact_forces(particles, contacts, *, circles=None, centre=None, png=None, title=None):
    """particles.csv and contacts.csv rows of one state; ``circles`` a dict
    name -> radius drawn round ``centre``."""
    from matplotlib.collections import LineCollection, PatchCollection
    from matplotlib.patches import Circle

    figure, ax = new_axes(None, size=(7.0, 7.0))
    by_id = {int(p["id"]): p for p in particles}
    x = np.array([float(p["x"]) for p in particles])
    y = np.array([float(p["y"]) for p in particles])
    radius = np.array([float(p["radius"]) for p in particles])
    ax.add_collection(PatchCollection([Circle((a, b), r) for a, b, r in zip(x, y, radius)], facecolor="none",
                                      edgecolor="0.75", linewidth=0.4))
    segments, forces = [], []
    for c in contacts:
        first = by_id[int(c["first"])]
        start = (float(first["x"]), float(first["y"]))
        if c["second_kind"] == "particle":
            second = by_id[int(c["second"])]
            end = (float(second["x"]), float(second["y"]))
        else:
            end = (float(c["x"]), float(c["y"]))
        segments.append((start, end))
        forces.append(float(c["normal_force"]))
    forces = np.array(forces)
    largest = float(forces.max()) if forces.size else 0.0
    if largest > 0.0:
        widths = 4.0 * forces / largest
        ax.add_collection(LineCollection(segments, linewidths=widths, colors="black"))
    if circles and centre is not None:
        for name, r in circles.items():
            ax.add_patch(Circle(centre, r, facecolor="none", edgecolor="C3", linestyle="--", linewidth=0.8))
            ax.annotate(name, (centre[0] + r / np.sqrt(2), centre[1] + r / np.sqrt(2)), color="C3",
                        fontsize="x-small")
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("x, m")
    ax.set_ylabel("y, m")
    ax.set_title((title or "contact forces") + f" (largest {largest:.3g} N)", fontsize="medium")
    return finish(figure, png)


def plot_porosity_profile(rows, *, png=None, title=None):
    """profile.csv rows (state, radius_low, radius_high, porosity): the
    porosity of each ring against its mid radius, one line per state."""
    figure, ax = new_axes(None)
    states = {}
    for row in rows:
        states.setdefault(row["state"], []).append(row)
    for state, ring in states.items():
        middle = [500.0 * (float(r["radius_low"]) + float(r["radius_high"])) for r in ring]
        ax.plot(middle, [float(r["porosity"]) for r in ring], "o-", label=state)
    _label(ax, "radius from the centre of the field, mm", "porosity of the ring",
           title or "porosity through the assembly (Fig. 6.5)")
    return finish(figure, png)


def plot_circle_series(rows, key, ylabel, *, scale=1.0, png=None, title=None):
    """``key`` of each circle against the circle's own deviator strain (%)."""
    figure, ax = new_axes(None)
    for region, series in _by_region(rows).items():
        strain = 100 * np.array([float(r["deviator_strain"]) for r in series])
        ax.plot(strain, scale * np.array([float(r[key]) for r in series]), label=region)
    _label(ax, "deviator strain of the circle, %", ylabel, title or "")
    return figure if png is None else finish(figure, png)


class CentripetalRun:
    """The files of a dem_validate randall-centripetal directory, read once."""

    def __init__(self, directory):
        self.directory = pathlib.Path(directory)
        self._tables = {}

    def has(self, name):
        return (self.directory / name).is_file()

    def table(self, name):
        if name not in self._tables:
            self._tables[name] = read_rows(self.directory / name)
        return self._tables[name]

    def circles(self):
        """The measurement circles by name (radius, m) and the field's centre."""
        circles, centre = {}, None
        for row in self.table("circles.csv"):
            circles[row["region"]] = float(row["radius"])
            centre = (float(row["centre_x"]), float(row["centre_y"]))
        return circles, centre

    def forces(self, state, caption):
        circles, centre = self.circles() if self.has("circles.csv") else ({}, None)
        return plot_contact_forces(self.table(f"{state}/particles.csv"), self.table(f"{state}/contacts.csv"),
                                   circles=circles, centre=centre, title=caption)


def figures(run):
    """(seed figure, file name, what it needs, how to draw it) for each figure."""
    return (
        ("6.4", "fig6_4_forces_compacted.png", ("compacted/particles.csv", "compacted/contacts.csv"),
         lambda: run.forces("compacted", "contact forces after centripetal compression (Fig. 6.4)")),
        ("6.5", "fig6_5_porosity.png", ("profile.csv",), lambda: plot_porosity_profile(run.table("profile.csv"))),
        ("6.6", "fig6_6_forces_100_kPa.png", ("at_100_kPa/particles.csv", "at_100_kPa/contacts.csv"),
         lambda: run.forces("at_100_kPa", "contact forces at 100 kPa isotropic stress (Fig. 6.6)")),
        ("6.7", "fig6_7_sin_phi.png", ("centripetal.csv",),
         lambda: plot_circle_series(run.table("centripetal.csv"), "sin_phi", r"$\sin\Phi$",
                                    title=r"$\sin\Phi$, constant mean stress (Fig. 6.7)")),
        ("6.8", "fig6_8_volumetric_strain.png", ("centripetal.csv",),
         lambda: plot_circle_series(run.table("centripetal.csv"), "volumetric_strain",
                                    "volumetric strain, % (contraction positive)", scale=100.0,
                                    title="volumetric strain, constant mean stress (Fig. 6.8)")),
    )


def draw_centripetal_directory(directory, out=None, say=lambda line: None):
    """Figs. 6.4-6.8 from a dem_validate randall-centripetal directory into
    ``out`` (default: the directory); returns the PNG paths written. Each
    figure whose files are missing is skipped and reported through ``say``."""
    run = CentripetalRun(directory)
    out = pathlib.Path(out) if out else run.directory
    written = []
    for number, name, inputs, draw in figures(run):
        missing = [n for n in inputs if not run.has(n)]
        if missing:
            say(f"skipped Fig. {number}: no {', '.join(missing)} in {run.directory}")
            continue
        written.append(save_png(draw(), out / name))
    return written
