"""A simulation's state as numpy arrays, read from snapshot bytes
(Client.snapshot(); schema idl/dem/snapshot.proto): the particles' positions,
radii, velocities and spins, and the walls where they stand. The service has
no particle query; a snapshot carries everything, exactly as the engine holds
it.

    state = dem.snapshot.State.from_bytes(press.snapshot())
    state.positions      # (N, dimension), m
    state.radii          # (N,), m (a superquadric's or ellipsoid's bounding radius)
"""

import dataclasses
import hashlib

import numpy as np

from . import snapshot_pb2
from ._client import CONTACT_DTYPE
from .errors import DemError


# The frame around every snapshot's bytes (io/include/dem/io/snapshot_frame.h):
# "DEMSNAP1", the payload's length (8 bytes, little-endian), its SHA-256.
_MAGIC = b"DEMSNAP1"
_HEADER = 48


def unframe(data):
    """The serialized dem.proto.Snapshot inside a snapshot's frame, once its
    length and SHA-256 match; DemError naming what is wrong otherwise."""
    data = bytes(data)
    if len(data) < _HEADER or data[:8] != _MAGIC:
        raise DemError('not a dem snapshot (it does not start with the "DEMSNAP1" header)')
    length = int.from_bytes(data[8:16], "little")
    payload = data[_HEADER:]
    if length != len(payload):
        raise DemError(f"a snapshot of {length} bytes, but {len(payload)} follow its header (truncated or extended)")
    if hashlib.sha256(payload).digest() != data[16:48]:
        raise DemError("corrupt snapshot: its SHA-256 checksum does not match its contents")
    return payload


@dataclasses.dataclass(frozen=True)
class WallState:
    name: str
    point: np.ndarray       # P, (dimension,), m
    direction: np.ndarray   # e (2D) or u (3D), unit
    h1: float
    h2: float
    direction2: np.ndarray  # v (3D), empty in 2D
    k1: float
    k2: float

    def ends(self):
        """2D: the wall's end points P + h1 e and P + h2 e, (2, 2)."""
        return np.array([self.point + self.h1 * self.direction, self.point + self.h2 * self.direction])

    def normal(self):
        """The unit normal towards the particles: e turned counter-clockwise
        in 2D (Cundall & Strack Fig. 4), u x v in 3D."""
        if len(self.point) == 2:
            return np.array([-self.direction[1], self.direction[0]])
        return np.cross(self.direction, self.direction2)


@dataclasses.dataclass(frozen=True)
class State:
    case_name: str
    dimension: int
    cycle: int
    time: float                 # s
    time_step: float            # s
    positions: np.ndarray       # (N, dimension), m
    radii: np.ndarray           # (N,), m
    velocities: np.ndarray      # (N, dimension), m/s, at the last half step
    angular_velocities: np.ndarray  # (N,) about z in 2D, (N, 3) in 3D, rad/s
    rotations: np.ndarray   # (N,) angle in 2D (rad, counter-clockwise), (N, 4) quaternion w, x, y, z in 3D
    # Per particle, 2D: a superquadric's a, b, n, initial angle (rad) - a = 0 for a
    # disc (Miyata et al. 2002, eq. 34); 3D: an ellipsoid's three semi-axes
    # and its quaternion w, x, y, z - first semi-axis 0 for a sphere. Empty
    # when every particle is a disc or a sphere.
    shapes: np.ndarray
    walls: tuple
    # The touching rows of the contact table as a CONTACT_DTYPE array, the
    # rows a query_contacts returns and in its order: particle pairs, then
    # particle-wall contacts, each in the table's order.
    contacts: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0, dtype=CONTACT_DTYPE))

    @classmethod
    def from_bytes(cls, data):
        message = snapshot_pb2.Snapshot()
        payload = unframe(data)
        try:
            message.ParseFromString(payload)
        except Exception as error:  # protobuf's DecodeError and its C++ twin differ by version
            raise DemError(f"not a dem snapshot: {error}") from None
        if message.format != "dem.snapshot":
            raise DemError(f'not a dem snapshot (format "{message.format}")')
        dim = message.dimension or 2
        p = message.particles
        spin = 1 if dim == 2 else 3
        walls = tuple(
            WallState(w.name, np.array(w.point), np.array(w.direction), w.h1, w.h2,
                      np.array(w.direction2), w.k1, w.k2)
            for w in message.walls)
        angular = np.array(p.angular_velocity, dtype=float)
        rotation = np.array(p.rotation, dtype=float)
        shapes = np.array(p.shape, dtype=float)
        shape_values = 4 if dim == 2 else 7
        return cls(
            case_name=message.case_name,
            dimension=dim,
            cycle=message.cycle,
            time=message.time,
            time_step=message.time_step,
            positions=np.array(p.position, dtype=float).reshape(-1, dim),
            radii=np.array(p.radius, dtype=float),
            velocities=np.array(p.velocity, dtype=float).reshape(-1, dim),
            angular_velocities=angular if spin == 1 else angular.reshape(-1, 3),
            rotations=rotation if dim == 2 else rotation.reshape(-1, 4),
            shapes=shapes.reshape(-1, shape_values) if shapes.size else shapes,
            walls=walls,
            contacts=_contacts(message.contacts, dim),
        )

    @classmethod
    def from_file(cls, path):
        """A snapshot file: one the server saved (save_snapshot, or a one-shot
        run's final.snapshot) or dem_run wrote."""
        with open(path, "rb") as data:
            return cls.from_bytes(data.read())

    def wall(self, name):
        for w in self.walls:
            if w.name == name:
                return w
        raise KeyError(f'no wall "{name}" (walls: {", ".join(w.name for w in self.walls)})')


def _contacts(table, dim):
    """The contact table's touching rows as the service reports them
    (engine/src/measures.cpp, list_contacts): shear force and damping signed
    along t in 2D, their magnitudes in 3D."""
    touching = np.array(table.touching, dtype=bool)
    with_wall = np.array(table.with_wall, dtype=bool)
    tangential = 1 if dim == 2 else 3
    second = np.array(table.second, dtype=np.int32)
    rows = np.zeros(touching.size, dtype=CONTACT_DTYPE)
    rows["first"] = table.first
    rows["second_particle"] = np.where(with_wall, -1, second)
    rows["second_wall"] = np.where(with_wall, second, -1)
    rows["point"][:, :dim] = np.array(table.point, dtype=float).reshape(-1, dim)
    rows["normal"][:, :dim] = np.array(table.normal, dtype=float).reshape(-1, dim)
    rows["overlap"] = table.overlap
    rows["normal_force"] = table.normal_force
    rows["normal_damping"] = table.normal_damping
    for name, values in (("shear_force", table.shear_force), ("shear_damping", table.shear_damping)):
        values = np.array(values, dtype=float).reshape(-1, tangential)
        rows[name] = values[:, 0] if dim == 2 else np.linalg.norm(values, axis=1)
    rows["sliding"] = table.sliding
    # The shear spring's force on the first particle, as the engine reports
    # it (engine/src/contact_forces.cpp, to_record): -F_s t with t the normal
    # turned clockwise in 2D, minus the shear vector in 3D.
    shear = np.array(table.shear_force, dtype=float).reshape(-1, tangential)
    if dim == 2:
        normal = rows["normal"]
        rows["tangential_force"][:, 0] = -(shear[:, 0] * normal[:, 1])
        rows["tangential_force"][:, 1] = shear[:, 0] * normal[:, 0]
    else:
        rows["tangential_force"] = -shear
    rows["formed_cycle"] = table.formed_cycle
    rows["force"][:, :dim] = np.array(table.force, dtype=float).reshape(-1, dim)
    order = np.concatenate([np.flatnonzero(touching & ~with_wall), np.flatnonzero(touching & with_wall)])
    return rows[order]  # indexing keeps CONTACT_DTYPE's layout; concatenating would pack it
