"""Contact forces drawn as BALL drew them (Cundall & Strack 1979, Figs. 5(b)
and 11): "rectangles through the contacts and with the orientation of the
contact forces. The lengths of the rectangles are equal to the sum of the
radii of the discs in contact and the widths are proportional to the
magnitudes of the contact forces" - pictures like those of photoelastic discs.

A wall contact has one disc: its rectangle runs from the contact point into
the disc, as long as the disc's radius. In 3D the wire carries only the
magnitude of the shear force, so a rectangle follows the contact normal with
the force's full magnitude; the picture is a slab of the assembly projected
on a plane (``plane``, ``slab``).
"""

import numpy as np
from matplotlib.collections import LineCollection, PatchCollection, PolyCollection
from matplotlib.patches import Circle, Polygon

from .figure import finish, new_axes


def contact_force_vectors(contacts, dimension):
    """Each contact's force as a vector (its direction and magnitude).

    2D: F_n e + F_s t with t the clockwise rotation of e (Cundall & Strack
    eqs. 10 and 16-17: both signed the same way, so the sum has the force's
    orientation). 3D: |F| along the normal, |F| = sqrt(F_n^2 + F_s^2)."""
    normal = contacts["normal"][:, :dimension]
    fn = contacts["normal_force"][:, None]
    fs = contacts["shear_force"][:, None]
    if dimension == 2:
        tangent = np.column_stack([normal[:, 1], -normal[:, 0]])
        return fn * normal + fs * tangent
    return np.sqrt(fn ** 2 + fs ** 2) * normal


def force_rectangles(state, contacts, max_width):
    """The rectangles' corners, (M, 4, dimension), and their forces (M,).
    Contacts without force are left out."""
    dim = state.dimension
    if contacts.size == 0:
        return np.empty((0, 4, dim)), np.empty(0)
    vectors = contact_force_vectors(contacts, dim)
    magnitude = np.linalg.norm(vectors, axis=1)
    keep = magnitude > 0
    contacts, vectors, magnitude = contacts[keep], vectors[keep], magnitude[keep]
    if magnitude.size == 0:
        return np.empty((0, 4, dim)), magnitude
    direction = vectors / magnitude[:, None]
    point = contacts["point"][:, :dim]
    first_radius = state.radii[contacts["first"]]
    is_wall = contacts["second_wall"] >= 0
    second_radius = np.where(is_wall, 0.0, state.radii[np.maximum(contacts["second_particle"], 0)])

    # Particle-particle: centred on the contact, R1 + R2 long.
    half = 0.5 * (first_radius + second_radius)
    start = point - half[:, None] * direction
    end = point + half[:, None] * direction
    # Particle-wall: from the contact point into the disc, R1 long.
    towards_centre = state.positions[contacts["first"]] - point
    inward = np.where((np.sum(towards_centre * direction, axis=1) >= 0)[:, None], direction, -direction)
    start = np.where(is_wall[:, None], point, start)
    end = np.where(is_wall[:, None], point + first_radius[:, None] * inward, end)

    width = max_width * magnitude / magnitude.max()
    side = _perpendicular(direction) * (0.5 * width)[:, None]
    corners = np.stack([start + side, end + side, end - side, start - side], axis=1)
    return corners, magnitude


def _perpendicular(direction):
    """A unit vector across each direction (in 3D, in the plane of the first two axes when it can be)."""
    if direction.shape[1] == 2:
        return np.column_stack([-direction[:, 1], direction[:, 0]])
    across = np.cross(direction, np.array([0.0, 1.0, 0.0]))
    fallback = np.cross(direction, np.array([1.0, 0.0, 0.0]))
    small = np.linalg.norm(across, axis=1) < 1e-9
    across[small] = fallback[small]
    return across / np.linalg.norm(across, axis=1)[:, None]


def superquadric_outline(a, b, n, angle, centre, points=64):
    """|x/a|^n + |y/b|^n = 1 turned by angle about centre (Miyata et al.
    2002, eq. 34), as a closed polygon."""
    t = np.linspace(0.0, 2.0 * np.pi, points, endpoint=False)
    c, s = np.cos(t), np.sin(t)
    x = a * np.sign(c) * np.abs(c) ** (2.0 / n)
    y = b * np.sign(s) * np.abs(s) ** (2.0 / n)
    rotation = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    return np.column_stack([x, y]) @ rotation.T + centre


def plot_force_chains(state, contacts, *, max_width=None, plane=(0, 2), slab=None, draw_particles=True,
                      draw_walls=True, ax=None, png=None, title=None):
    """The force-chain picture of ``contacts`` (a contact array, e.g.
    Client.contacts()) in the assembly ``state`` (dem.snapshot.State).

    ``max_width``: the width of the largest force's rectangle (default: 0.6
    of the mean particle radius). The view is the particles' extent. 3D: ``plane`` names the two axes drawn (default
    x and z) and ``slab`` the thickness around the assembly's middle along
    the third axis (default four mean radii)."""
    figure, ax = new_axes(ax, size=(7.0, 7.0))
    dim = state.dimension
    mean_radius = float(state.radii.mean()) if state.radii.size else 1.0
    max_width = max_width or 0.6 * mean_radius
    if dim == 2:
        axes, inside = (0, 1), np.ones(len(state.radii), dtype=bool)
    else:
        axes = tuple(plane)
        depth_axis = ({0, 1, 2} - set(axes)).pop()
        middle = 0.5 * (state.positions[:, depth_axis].min() + state.positions[:, depth_axis].max())
        half = 0.5 * (slab or 4.0 * mean_radius)
        inside = np.abs(state.positions[:, depth_axis] - middle) <= half
        if contacts.size:
            contacts = contacts[np.abs(contacts["point"][:, depth_axis] - middle) <= half]

    if draw_particles:
        ax.add_collection(_particle_outlines(state, inside, axes))
    if draw_walls and dim == 2:
        ends = [w.ends() for w in state.walls]
        if ends:
            ax.add_collection(LineCollection(ends, colors="0.3", linewidths=2.0))
    corners, forces = force_rectangles(state, contacts, max_width)
    if forces.size:
        ax.add_collection(PolyCollection(corners[:, :, list(axes)], facecolors="black", edgecolors="none"))
    ax.set_aspect("equal")
    _frame(ax, state, inside, axes)
    names = "xyz"
    ax.set_xlabel(f"{names[axes[0]]} [m]")
    ax.set_ylabel(f"{names[axes[1]]} [m]")
    ax.set_title(title or f"contact forces of {state.case_name} at cycle {state.cycle} "
                          f"(largest {forces.max() if forces.size else 0:.3g} N)", fontsize="medium")
    return finish(figure, png)


def _frame(ax, state, inside, axes):
    """The particles' extent and a margin of two largest radii (the walls may reach far beyond)."""
    if not inside.any():
        ax.autoscale_view()
        return
    positions = state.positions[inside][:, list(axes)]
    margin = 2.0 * float(state.radii[inside].max())
    low, high = positions.min(axis=0) - margin, positions.max(axis=0) + margin
    ax.set_xlim(low[0], high[0])
    ax.set_ylim(low[1], high[1])


def _particle_outlines(state, inside, axes):
    style = dict(facecolor="none", edgecolor="0.6", linewidth=0.5)
    patches = []
    for i in np.flatnonzero(inside):
        centre = state.positions[i, list(axes)]
        if state.dimension == 2 and state.shapes.size and state.shapes[i, 0] > 0:
            a, b, n, _ = state.shapes[i]
            patches.append(Polygon(superquadric_outline(a, b, n, state.rotations[i], centre), closed=True))
        else:
            patches.append(Circle(centre, state.radii[i]))  # an ellipsoid: its bounding sphere
    return PatchCollection(patches, **style)
