"""Miyata et al. (2002) figures of the whole assembly under the plate, from
particles_at_stress.csv and contacts_at_stress.csv (the particles and
contacts at the loading's start and at each contacts_at_stress stress):

- plot_force_networks: the contact forces between particles as BALL drew
  them (force_chains.force_rectangles: along the force, as wide as it is
  strong) at the lowest and the highest of those stresses (Fig. 27: 50
  and 900 kPa);
- plot_rotations: each particle's rotation between the unloaded state and
  the first stress, and between the first and the second, as its grey
  level, white for none and black for the largest (Fig. 28: 0-50 and
  50-250 kPa).

A 3D assembly is drawn as a slab about the middle of the cell, seen along
y: each ellipsoid as its outline projected on the x-z plane.
"""

import math
import types

import numpy as np
from matplotlib.collections import PatchCollection, PolyCollection
from matplotlib.patches import Circle, Ellipse, Polygon

from .figure import finish
from .force_chains import force_rectangles, superquadric_outline
from .miyata_loading import new_figure, seed_title
from .miyata_run import MissingInput, select

# What force_rectangles reads of a contact.
_CONTACT_FIELDS = np.dtype([("first", np.int64), ("second_particle", np.int64), ("second_wall", np.int64),
                            ("point", np.float64, 3), ("normal", np.float64, 3), ("normal_force", np.float64),
                            ("shear_force", np.float64)])


class Assembly:
    """The particles and contacts of one snapshot."""

    def __init__(self, run, snapshot):
        particles = run.table("particles_at_stress.csv")
        contacts = run.table("contacts_at_stress.csv")
        self.dimension = run.dimension
        self.index, self.target_stress, self.cycle, self.stress = snapshot
        p = select(particles, particles["snapshot"] == self.index)
        if p["id"].size == 0:
            raise MissingInput(f"particles_at_stress.csv has no particles at snapshot {self.index}")
        axes = "xyz"[: self.dimension]
        self.ids = p["id"].astype(int)
        self.positions = np.column_stack([p[a] for a in axes])
        self.radii = p["radius"]
        if self.dimension == 2:
            self.rotations = p["rotation"]
            self.shapes = np.column_stack([p["a"], p["b"], p["n"]])
        else:
            self.rotations = np.column_stack([p[f"rotation_{c}"] for c in "wxyz"])
            self.shapes = np.column_stack([p["a1"], p["a2"], p["a3"]])
        self.contacts = select(contacts, contacts["snapshot"] == self.index)
        try:
            self.plates = run.plate_names()
        except MissingInput:  # every wall a contact names
            self.plates = None

    def thickness(self):
        """The particles' mean smallest semi-axis (a disc's radius), m: it
        sets the widest force's width."""
        return float(self.shapes.min(axis=1).mean())

    def equivalent_radii(self):
        """The radius of a disc of the same area (2D: a superquadric's area
        is 4ab Gamma(1 + 1/n)^2 / Gamma(1 + 2/n)) or a sphere of the same
        volume (3D: (a1 a2 a3)^(1/3)), m."""
        if self.dimension == 3:
            return np.cbrt(np.prod(self.shapes, axis=1))
        a, b, n = self.shapes.T
        area = 4 * a * b * np.array([math.gamma(1 + 1 / e) ** 2 / math.gamma(1 + 2 / e) for e in n])
        return np.sqrt(area / np.pi)

    def row_of(self, ids):
        """Each particle id's row in the arrays here."""
        rows = np.full(int(self.ids.max()) + 1, -1)
        rows[self.ids] = np.arange(self.ids.size)
        return rows[np.asarray(ids, dtype=int)]

    def contact_array(self):
        """The contacts as force_rectangles reads them, particles named by row."""
        c = self.contacts
        n = c["first"].size
        array = np.zeros(n, dtype=_CONTACT_FIELDS)
        if n == 0:
            return array
        with_wall = c["second_kind"] == "wall"
        axes = "xyz"[: self.dimension]
        # "second" is a particle's id or a wall's name.
        second = np.array([-1 if wall else int(float(s)) for s, wall in zip(c["second"].astype(str), with_wall)])
        array["first"] = self.row_of(c["first"])
        array["second_particle"] = np.where(with_wall, -1, self.row_of(np.maximum(second, 0)))
        array["second_wall"] = np.where(with_wall, 0, -1)
        for k, a in enumerate(axes):
            array["point"][:, k] = c[a]
            array["normal"][:, k] = c[f"n{a}"]
        array["normal_force"] = c["normal_force"]
        array["shear_force"] = c["shear_force"]
        return array

    def plate_levels(self):
        """{plate name: its height}, from the contact points on it (the
        loading and bottom plates only, when the run names them)."""
        c = self.contacts
        vertical = "y" if self.dimension == 2 else "z"
        walls = c["second_kind"] == "wall"
        names = [str(n) for n in dict.fromkeys(c["second"][walls]) if self.plates is None or n in self.plates]
        return {name: float(np.mean(c[vertical][walls & (c["second"] == name)])) for name in names}


def assembly_snapshots(run):
    """The snapshots the whole assembly was written at, in order (the
    first is the loading's start, target 0)."""
    particles = run.table("particles_at_stress.csv")
    run.table("contacts_at_stress.csv")
    seen = {}
    for k, index in enumerate(particles["snapshot"]):
        seen.setdefault(int(index), (int(index), particles["target_stress"][k], int(particles["cycle"][k]),
                                     particles["stress"][k]))
    if not seen:
        raise MissingInput("particles_at_stress.csv is empty: the case asked for no contacts_at_stress, or the "
                           "loading never began")
    return [seen[i] for i in sorted(seen)]


def _view(assembly, slab=None):
    """The axes drawn (x and y in 2D, x and z in 3D) and which particles and
    contacts lie in the slab drawn (3D: about the middle along y, four mean
    radii thick unless ``slab`` says)."""
    if assembly.dimension == 2:
        return (0, 1), np.ones(assembly.ids.size, dtype=bool), None
    y = assembly.positions[:, 1]
    middle = 0.5 * (y.min() + y.max())
    half = 0.5 * (slab or 4.0 * float(assembly.radii.mean()))
    return (0, 2), np.abs(y - middle) <= half, (middle, half)


def drawing_order(assembly, inside):
    """The particles drawn, the farthest first (3D, seen from -y) so the
    nearer cover them."""
    rows = np.flatnonzero(inside)
    if assembly.dimension == 3:
        rows = rows[np.argsort(-assembly.positions[rows, 1], kind="stable")]
    return rows


def _outlines(assembly, rows, axes):
    """The outlines of the particles in ``rows``: a superquadric (Miyata
    eq. 34) or disc in 2D, an ellipsoid's (eq. 43) shadow on the plane
    drawn in 3D."""
    patches = []
    for i in rows:
        centre = assembly.positions[i, list(axes)]
        if assembly.dimension == 2:
            a, b, n = assembly.shapes[i]
            if n == 2 and a == b:
                patches.append(Circle(centre, a))
            else:
                patches.append(Polygon(superquadric_outline(a, b, n, assembly.rotations[i], centre), closed=True))
        else:
            patches.append(_ellipsoid_shadow(assembly.shapes[i], assembly.rotations[i], centre, axes))
    return patches


def _ellipsoid_shadow(semi_axes, quaternion, centre, axes):
    """The outline of an ellipsoid seen along the axis not in ``axes``: the
    ellipse whose matrix is the inverse of the plane's block of A^-1 = R
    diag(a^2) R^T (its support function, projected)."""
    rotation = quaternion_matrix(quaternion)
    inverse = rotation @ np.diag(np.asarray(semi_axes) ** 2) @ rotation.T
    block = inverse[np.ix_(list(axes), list(axes))]
    values, vectors = np.linalg.eigh(block)
    angle = np.degrees(np.arctan2(vectors[1, 1], vectors[0, 1]))
    return Ellipse(centre, 2 * np.sqrt(values[1]), 2 * np.sqrt(values[0]), angle=angle)


def quaternion_matrix(q):
    """The rotation matrix of a unit quaternion (w, x, y, z), body to world."""
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def rotation_between(before, after):
    """Each particle's rotation from ``before`` to ``after`` (Assembly), in
    degrees, for the particles in both, by id: (ids, angles).
    2D: the difference of the accumulated angles; 3D: the angle of q_after
    q_before^-1, 2 acos |q_before . q_after|."""
    ids = np.intersect1d(before.ids, after.ids)
    rows_before = before.row_of(ids)
    rows_after = after.row_of(ids)
    if after.dimension == 2:
        angle = np.abs(after.rotations[rows_after] - before.rotations[rows_before])
    else:
        dot = np.abs(np.sum(after.rotations[rows_after] * before.rotations[rows_before], axis=1))
        angle = 2 * np.arccos(np.clip(dot, 0.0, 1.0))
    return ids, np.degrees(angle)


def _panel_axes(assemblies, slab=None):
    """A figure with one panel per assembly, stacked, sized to the sample."""
    axes_drawn, inside, _ = _view(assemblies[0], slab)
    extent = np.ptp(assemblies[0].positions[inside][:, list(axes_drawn)], axis=0) + 1e-9
    height = float(np.clip(10.0 * extent[1] / extent[0], 2.2, 6.0))
    figure = new_figure((11, 0.8 + (height + 1.3) * len(assemblies)))  # room for each panel's title and axis
    return figure, figure.subplots(len(assemblies), 1, squeeze=False)[:, 0]


def _frame(ax, assembly, inside, axes, plates):
    """The particles' extent, the plates drawn across it."""
    positions = assembly.positions[inside][:, list(axes)]
    margin = float(assembly.radii[inside].mean())
    low, high = positions.min(axis=0) - margin, positions.max(axis=0) + margin
    for name, level in plates.items():
        ax.plot([low[0], high[0]], [level, level], color="0.2", linewidth=2.5, solid_capstyle="butt")
        ax.annotate(name, (high[0], level), fontsize="x-small", ha="right", va="bottom")
        low[1], high[1] = min(low[1], level - 0.3 * margin), max(high[1], level + 0.3 * margin)
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])
    ax.set_aspect("equal")
    names = "xyz"
    ax.set_xlabel(f"{names[axes[0]]}, m")
    ax.set_ylabel(f"{names[axes[1]]}, m")


def _stress_label(assembly):
    if assembly.target_stress == 0:
        return f"the loading's start (cycle {assembly.cycle})"
    return f"{assembly.stress / 1e3:.0f} kPa (target {assembly.target_stress / 1e3:.0f} kPa, cycle {assembly.cycle})"


def _slab_note(assembly, slab):
    view = _view(assembly, slab)[2]
    return "" if view is None else f"; a slab y = {view[0]:.2f} ± {view[1]:.2f} m, seen along y"


def plot_force_networks(run, *, slab=None, png=None):
    """Fig. 27: the contact forces at the lowest and the highest stress of
    contacts_at_stress (the seed: 50 and 900 kPa)."""
    loaded = [s for s in assembly_snapshots(run) if s[1] > 0]
    if not loaded:
        raise MissingInput("particles_at_stress.csv holds only the loading's start: no contacts_at_stress "
                           "stress was reached")
    chosen = [loaded[0]] if len(loaded) == 1 else [loaded[0], loaded[-1]]
    assemblies = [Assembly(run, s) for s in chosen]
    figure, axes = _panel_axes(assemblies, slab)
    for ax, assembly in zip(axes, assemblies):
        axes_drawn, inside, view = _view(assembly, slab)
        outlines = _outlines(assembly, drawing_order(assembly, inside), axes_drawn)
        ax.add_collection(PatchCollection(outlines, facecolor="none", edgecolor="0.6", linewidth=0.5))
        contacts = assembly.contact_array()
        if view is not None and contacts.size:
            contacts = contacts[np.abs(contacts["point"][:, 1] - view[0]) <= view[1]]
        # BALL's rectangles are R1 + R2 long: for shaped particles the
        # radius of the same area (2D) or volume (3D), not the bounding one.
        state = types.SimpleNamespace(dimension=assembly.dimension, positions=assembly.positions,
                                      radii=assembly.equivalent_radii())
        corners, forces = force_rectangles(state, contacts, 0.6 * assembly.thickness())
        if forces.size:
            ax.add_collection(PolyCollection(corners[:, :, list(axes_drawn)], facecolors="black",
                                             edgecolors="none"))
        _frame(ax, assembly, inside, axes_drawn, assembly.plate_levels())
        largest = f"{forces.max() / 1e3:.3g} kN" if forces.size else "none"
        ax.set_title(f"{_stress_label(assembly)}\n{forces.size} contacts, largest {largest}"
                     f"{_slab_note(assembly, slab)}", fontsize="small")
    stresses = " and ".join(f"{a.target_stress / 1e3:.0f}" for a in assemblies)
    figure.suptitle(seed_title(27, f"contact forces between particles at {stresses} kPa (width ∝ force)", run),
                    fontsize="medium")
    return finish(figure, png)


def plot_rotations(run, *, slab=None, png=None):
    """Fig. 28: each particle's rotation from the loading's start to the
    first stress of contacts_at_stress, and from the first to the second
    (the seed: 0-50 and 50-250 kPa), white for none, black for the
    largest in each panel."""
    snapshots = assembly_snapshots(run)
    if snapshots[0][1] != 0 or len(snapshots) < 2:
        raise MissingInput("particles_at_stress.csv lacks the loading's start or any stress after it")
    pairs = list(zip(snapshots[:-1], snapshots[1:]))[:2]
    figure, axes = _panel_axes([Assembly(run, pairs[0][1])] * len(pairs), slab)
    for ax, (first, second) in zip(axes, pairs):
        before, after = Assembly(run, first), Assembly(run, second)
        ids, degrees = rotation_between(before, after)
        axes_drawn, inside, _ = _view(after, slab)
        inside &= np.isin(after.ids, ids)
        shown = after.row_of(ids)
        angle = np.zeros(after.ids.size)
        angle[shown] = degrees
        rows = drawing_order(after, inside)
        collection = PatchCollection(_outlines(after, rows, axes_drawn), cmap="Greys", edgecolor="0.55",
                                     linewidth=0.4)
        collection.set_array(angle[rows])
        largest = float(angle[inside].max()) if inside.any() else 0.0
        collection.set_clim(0.0, largest if largest > 0 else 1.0)
        ax.add_collection(collection)
        _frame(ax, after, inside, axes_drawn, after.plate_levels())
        figure.colorbar(collection, ax=ax, label="rotation, degrees", shrink=0.9)
        ax.set_title(f"from {_stress_label(before)} to {_stress_label(after)}\nlargest {largest:.3g}°, "
                     f"median {np.median(angle[inside]):.2g}°{_slab_note(after, slab)}", fontsize="small")
    figure.suptitle(seed_title(28, "particle rotations (white: none, black: the largest)", run), fontsize="medium")
    return finish(figure, png)
