"""A connection to one dem_server: every command of docs/SERVICE.md, sent and
its reply awaited with a timeout. The work is done by the C++ client library
(dem::client) through the extension module dem._client, as rclpy does it
over rcl; the GIL is released while a reply is awaited.

    with dem.Client("press", domain=7) as press:
        press.load_case("cases/ball/nine_disc_damped.case.txtpb")
        press.set_wall_velocity("top", (0, -0.5))     # lower the top wall at 0.5 m/s
        press.run_until(wall="top", stress=1e6, max_cycles=2000)   # until it carries 1 MPa
        contacts = press.contacts(wall="top")    # numpy structured array

A reply with an error status raises dem.ServerError carrying the server's
status and message; no reply in time raises dem.ReplyTimeout; no server,
dem.NoSuchServer. Times are in seconds; quantities in SI units, as the case.
"""

import os
import pathlib
import time

from . import _client
from .cases import case_pb2
from .paths import use_loopback
from .telemetry import Subscription


def _vector(values, what):
    """A 3-vector from 2 or 3 components (2D leaves z out)."""
    values = tuple(float(v) for v in values)
    if len(values) == 2:
        return values + (0.0,)
    if len(values) == 3:
        return values
    raise ValueError(f"{what} takes 2 or 3 components (got {len(values)})")


def _spin(value):
    """An angular velocity: a number (2D, about z) or 3 components."""
    if isinstance(value, (int, float)):
        return (0.0, 0.0, float(value))
    return _vector(value, "an angular velocity")


class Client:
    """A connection to the dem_server named ``server`` on DDS ``domain``.

    Connecting waits up to ``timeout`` seconds for the server (its status,
    then one round trip). ``reply_timeout`` bounds the wait for the reply to
    any command but a run (cycle, run_until), which waits as long as it
    takes unless given a timeout. ``dds_config`` empty means
    $CYCLONEDDS_URI, else the repository's loopback-only file.
    """

    def __init__(self, server="dem", domain=0, *, timeout=5.0, reply_timeout=60.0, dds_config="", client_id=""):
        use_loopback()
        self._native = _client.Client(server, domain, dds_config, timeout, reply_timeout, client_id)

    # --- the connection ---------------------------------------------------

    @property
    def server(self):
        return self._native.server

    @property
    def domain(self):
        return self._native.domain

    @property
    def client_id(self):
        return self._native.client_id

    @property
    def status(self):
        """The server's latest status (dem.Status)."""
        return self._native.status()

    def server_alive(self):
        return self._native.server_alive()

    def wait_for_status(self, condition, timeout, poll=0.02):
        """Waits until condition(status) holds; the status, or None after timeout s."""
        deadline = time.monotonic() + timeout
        while True:
            status = self._native.status()
            if condition(status):
                return status
            if time.monotonic() >= deadline:
                return None
            time.sleep(poll)

    def close(self):
        """Ends the connection (its receiving thread); idempotent."""
        if not self._native.closed:
            self._native.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # --- loading --------------------------------------------------------------

    def load_case(self, case=None, *, text=None, on_server=False, source_name=None, timeout=None):
        """Loads a case: a dem.cases.Case message (sent serialized), a case
        file (its text is sent, named by the path, as demctl does; with
        on_server=True the server reads the file itself, so paths inside it
        resolve against its directory), or ``text`` in protobuf text format.
        Returns the reply; its ``state`` describes what was loaded."""
        if (case is None) == (text is None):
            raise TypeError("load_case takes a case (a Case message or a file) or text=, not both")
        if text is not None:
            return self._native.load_case_text(text, source_name or "<text>", timeout)
        if isinstance(case, case_pb2.Case):
            name = source_name or f"<case {case.name}>"
            return self._native.load_case_binary(case.SerializeToString(), name, timeout)
        path = pathlib.Path(case)
        if on_server:
            return self._native.load_case_path(str(path.resolve()), timeout)
        return self._native.load_case_text(path.read_text(), source_name or str(path), timeout)

    # --- walls and parameters -----------------------------------------------

    def set_wall_velocity(self, wall, velocity, angular_velocity=0.0, *, timeout=None):
        """Moves a wall: the velocity of its point P (m/s; 2 or 3 components)
        and its angular velocity about P (rad/s; a number about z in 2D)."""
        return self._native.set_wall_velocity(wall, _vector(velocity, "a wall velocity"),
                                              _spin(angular_velocity), timeout)

    def set_wall_servo(self, wall, stress, *, gain=0.0, max_speed=0.0, timeout=None):
        """Servo-controls a wall's normal stress (Pa); gain m/(Pa s) and
        max_speed m/s, 0 = chosen by the server (docs/SERVICE.md)."""
        return self._native.set_wall_servo(wall, float(stress), float(gain), float(max_speed), timeout)

    def set_parameter(self, name, value, *, material="", timeout=None):
        """contact_damping, global_damping, local_damping, time_step_fraction,
        or friction of a material."""
        return self._native.set_parameter(name, float(value), material, timeout)

    def set_gravity(self, gravity, *, timeout=None):
        return self._native.set_gravity(_vector(gravity, "gravity"), timeout)

    # --- running ------------------------------------------------------------------

    def cycle(self, cycles, *, timeout=None, on_wait=None, wait_interval=0.1):
        """Runs ``cycles`` cycles and returns the reply when they are done.
        ``on_wait()`` is called every ``wait_interval`` s meanwhile, in this
        thread (a live plot's update). Ctrl-C stops the run on the server."""
        return self._native.cycle(int(cycles), timeout, on_wait, wait_interval)

    def start_cycle(self, cycles):
        """Starts a cycle command and returns its request id at once (await_run)."""
        return self._native.start_cycle(int(cycles))

    def run_until(self, *, max_cycles, wall="", stress=None, settlement=None, kinetic_energy=None,
                  check_interval=0, timeout=None, on_wait=None, wait_interval=0.1):
        """Runs until every condition that is set holds at once - a wall's
        ``stress`` (Pa) or ``settlement`` (m) at or above its value, the
        kinetic energy below ``kinetic_energy`` (J); the engine's stop rule,
        a case stage's - or ``max_cycles`` have run. The reply's
        ``condition_met`` says whether the conditions ended it."""
        return self._native.run_until(wall, _optional(stress), _optional(settlement), _optional(kinetic_energy),
                                      int(max_cycles), int(check_interval), timeout, on_wait, wait_interval)

    def start_run_until(self, *, max_cycles, wall="", stress=None, settlement=None, kinetic_energy=None,
                        check_interval=0):
        return self._native.start_run_until(wall, _optional(stress), _optional(settlement),
                                            _optional(kinetic_energy), int(max_cycles), int(check_interval))

    def run_programme(self, *, first_stage=0, stage_count=0, sample_every=0, stage_ends=False, resume=False,
                      stage_cycles_done=0, timeout=None, on_wait=None, wait_interval=0.1):
        """Runs the loaded case's stages on the server as dem_run does - trims,
        wall placements, wall motions, damping, stop conditions - from
        ``first_stage`` (counted from 1; 0 = the first) for ``stage_count``
        stages (0 = to the last), and returns the reply when they end.

        In steps: with ``sample_every`` > 0 the run returns every that many
        cycles of a stage (counted from its start) and at each stage's end,
        with ``stage_ends`` at each stage's end; the reply's ``stage`` (from
        1), ``stage_cycles`` and ``stage_ended`` say where, the world waits
        there, and a run with ``resume`` - ``first_stage`` the stage it was
        in (the next when it ended), ``stage_cycles_done`` its cycles run -
        carries on as if never interrupted. dem.run_programme does the loop."""
        return self._native.run_programme(int(first_stage), int(stage_count), int(sample_every), bool(stage_ends),
                                          bool(resume), int(stage_cycles_done), timeout, on_wait, wait_interval)

    def start_run_programme(self, *, first_stage=0, stage_count=0, sample_every=0, stage_ends=False, resume=False,
                            stage_cycles_done=0):
        return self._native.start_run_programme(int(first_stage), int(stage_count), int(sample_every),
                                                bool(stage_ends), bool(resume), int(stage_cycles_done))

    def await_run(self, request_id, *, timeout=None, on_wait=None, wait_interval=0.1):
        """The reply to a run started with start_cycle, start_run_until or start_run_programme."""
        return self._native.await_reply(request_id, timeout, on_wait, wait_interval, True)

    def stop(self, *, timeout=None):
        """Stops the running command (its own reply is then ``cancelled``)."""
        return self._native.stop(timeout)

    # --- reading ------------------------------------------------------------------

    def state(self, *, timeout=None):
        """get_state: the reply's ``plates`` (dem.PlateForces), ``stats``
        (dem.ContactStats), ``state`` (dem.Status) and ``state_hash``."""
        return self._native.get_state(timeout)

    def contacts(self, *, wall=None, box=None, min_force=None, particle=None, chunk_size=0, timeout=None):
        """The contacts as a numpy structured array (dem.CONTACT_DTYPE), one
        row per contact: those on ``wall`` (a name), with their point inside
        ``box`` ((min corner, max corner)), with a normal force above
        ``min_force``, of ``particle`` (its id, which a trim does not
        change) - any that are given. A removed or unknown particle raises
        dem.NotFound naming it."""
        box_min, box_max = (None, None) if box is None else (_vector(box[0], "a box corner"),
                                                             _vector(box[1], "a box corner"))
        reply = self._native.query_contacts(wall, box_min, box_max, _optional(min_force),
                                            None if particle is None else int(particle), int(chunk_size), timeout)
        return reply.contacts

    def snapshot(self, *, timeout=None):
        """The whole state as snapshot bytes (idl/dem/snapshot.proto);
        dem.snapshot.State reads them, load_snapshot restores them."""
        return self._native.save_snapshot("", True, timeout).data

    def save_snapshot(self, path, *, timeout=None):
        """Saves a snapshot in the server's output directory; the reply's path."""
        return self._native.save_snapshot(str(path), False, timeout)

    def load_snapshot(self, snapshot, *, timeout=None):
        """Restores a snapshot: bytes, or a path in the server's output directory."""
        if isinstance(snapshot, (bytes, bytearray)):
            return self._native.load_snapshot_bytes(bytes(snapshot), timeout)
        return self._native.load_snapshot_path(os.fspath(snapshot), timeout)

    def shutdown(self, *, timeout=None):
        """Stops the server (it writes its tables and exits)."""
        return self._native.shutdown(timeout)

    # --- telemetry ---------------------------------------------------------------

    def subscribe(self, *, plate_forces=True, contact_stats=True, status=False, region_measures=False, callback=None,
                  capacity=100000):
        """The server's telemetry as a dem.Subscription: iterate over it, take
        samples with get()/drain(), or have ``callback(sample)`` called on a
        thread of its own. ``region_measures``: also the measures of the
        case's regions (dem.RegionTelemetry; output.region in the case)."""
        native = _client.Telemetry(self._native, plate_forces, contact_stats, status, capacity, region_measures)
        return Subscription(native, callback=callback)


def _optional(value):
    return None if value is None else float(value)


def list_servers(domain, *, dds_config="", discovery=1.5):
    """The servers alive on a domain, as (name, dem.Status or None) pairs."""
    use_loopback()
    return _client.list_servers(domain, dds_config, discovery)
