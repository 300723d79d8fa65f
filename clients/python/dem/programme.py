"""A case's loading programme (its stages) run through the service, as dem_run
runs it in-process (engine/src/programme.cpp, run_stage): at a stage's start
its wall motions and damping are set; then it cycles for its count, or until
every condition of its ``until`` holds, checked every check_interval cycles
from the stage's start and never before min_cycles.

Each piece becomes service commands: a wall motion set_wall_velocity or
set_wall_servo (the case's servo force and gain per unit force are turned
into the service's stress and gain per unit stress with the wall's area),
damping set_parameter, cycles cycle; the conditions are checked here, from
get_state, between cycle commands, so a script can watch and sample each
stage as it goes. A stage that trims the sample or places a wall has no
command of its own and raises ProgrammeError: Client.run_programme runs
such a programme on the server instead (the run_programme command).
"""

import dataclasses

from .errors import ProgrammeError


def has(message, field):
    """Whether ``field`` is set - False when this schema has no such field, so
    the runner reads cases written for older and newer schemas alike."""
    return field in message.DESCRIPTOR.fields_by_name and message.HasField(field)


@dataclasses.dataclass(frozen=True)
class StageOutcome:
    index: int
    name: str
    cycles_run: int
    condition_met: bool  # a stop condition ended the stage before its cycle cap


def check_stage_supported(case, index):
    """ProgrammeError naming the stage and what the service cannot do, if anything."""
    stage = case.stage[index]
    label = f'stage {index} ("{stage.name}")'
    if has(stage, "trim"):
        raise ProgrammeError(f"{label} trims the sample, which no single command does: "
                             "Client.run_programme runs the stages on the server")
    if has(stage, "place_wall"):
        raise ProgrammeError(f'{label} places wall "{stage.place_wall.wall}" on the sample, which no single '
                             "command does: Client.run_programme runs the stages on the server")
    if has(stage, "damping"):
        for rotation in ("global_alpha_rotation", "local_alpha_rotation"):
            if has(stage.damping, rotation):
                raise ProgrammeError(f"{label} sets damping.{rotation}, which the service cannot set apart")


def run_programme(client, case, *, stages=None, sample_every=0, on_sample=None, on_wait=None):
    """Runs the case's stages (all, or the indices in ``stages``) on the
    server, which must have the case loaded. ``on_sample(index, cycle)`` is
    called every ``sample_every`` cycles of a stage with the stage's index
    and the server's cycle count; returning False ends the stage.
    ``on_wait()`` is called while cycles run (Client.cycle). Returns a
    StageOutcome per stage."""
    indices = range(len(case.stage)) if stages is None else stages
    for index in indices:
        check_stage_supported(case, index)
    runner = _Runner(client, case)
    return [runner.run_stage(index, sample_every, on_sample, on_wait) for index in indices]


class _Runner:
    def __init__(self, client, case):
        self.client = client
        self.case = case
        self.three_d = case.dimension == 3
        self.areas = {w.name: w.area for w in client.state().plates.walls}
        # Walls under servo control and their target force (N): the case's
        # initial motions, then each stage's commands (run_stage's
        # servo_tolerance looks at every servo wall).
        self.servo_targets = {w.name: w.motion.servo.target_force
                              for w in case.wall if has(w, "motion") and has(w.motion, "servo")}

    def run_stage(self, index, sample_every, on_sample, on_wait):
        stage = self.case.stage[index]
        for command in stage.wall:
            self._set_motion(command.wall, command.motion)
        if has(stage, "damping"):
            self._set_damping(stage.damping)

        until = stage.until
        conditional = any(has(until, name) for name in
                          ("kinetic_energy_below", "out_of_balance_below", "kinetic_to_elastic_below",
                           "unbalanced_force_below", "servo_tolerance",
                           "wall_stress_above", "wall_settlement_above"))
        check = max(until.check_interval or 10, 1)  # the schema's default: 10
        done = 0
        while done < stage.cycles:
            chunk = stage.cycles - done
            if sample_every > 0:
                chunk = min(chunk, sample_every - done % sample_every)
            if conditional:
                chunk = min(chunk, check - done % check)
            reply = self.client.cycle(chunk, on_wait=on_wait)
            done += chunk
            if on_sample is not None and sample_every > 0 and done % sample_every == 0:
                if on_sample(index, reply.state.cycle) is False:
                    break
            if conditional and done >= until.min_cycles and done % check == 0 and self._conditions_hold(until):
                return StageOutcome(index, stage.name, done, True)
        return StageOutcome(index, stage.name, done, False)

    def _area(self, wall):
        try:
            area = self.areas[wall]
        except KeyError:
            raise ProgrammeError(f'the server has no wall "{wall}" (walls: {", ".join(self.areas)})') from None
        if area <= 0:
            raise ProgrammeError(f'wall "{wall}" has no area to turn its servo force into a stress')
        return area

    def _set_motion(self, wall, motion):
        if has(motion, "servo"):
            servo = motion.servo
            area = self._area(wall)
            # Case: v = gain (F_target - F), gain in m/(N s); service: v = gain' (s_target - s)
            # with s = F / area, so gain' = gain * area (Randall 1989, 4.1).
            self.client.set_wall_servo(wall, servo.target_force / area, gain=servo.gain * area,
                                       max_speed=servo.max_speed)
            self.servo_targets[wall] = servo.target_force
            return
        velocity = (motion.velocity.x, motion.velocity.y, motion.velocity.z)
        if self.three_d:
            spin = (motion.angular_velocity_3d.x, motion.angular_velocity_3d.y, motion.angular_velocity_3d.z)
        else:
            spin = motion.angular_velocity
        self.client.set_wall_velocity(wall, velocity, spin)
        self.servo_targets.pop(wall, None)

    def _set_damping(self, damping):
        # A stage's damping replaces the whole damping from then on.
        self.client.set_parameter("contact_damping", damping.contact_beta)
        self.client.set_parameter("global_damping", damping.global_alpha)
        self.client.set_parameter("local_damping", damping.local_alpha)

    def _conditions_hold(self, until):
        reply = self.client.state()
        stats = reply.stats
        walls = {w.name: w for w in reply.plates.walls}
        if has(until, "kinetic_energy_below") and not stats.kinetic_energy < until.kinetic_energy_below:
            return False
        if has(until, "out_of_balance_below") and not (
                stats.contacts > 0 and stats.out_of_balance < until.out_of_balance_below):
            return False
        if has(until, "kinetic_to_elastic_below") and not (
                stats.contacts > 0 and stats.kinetic_to_elastic < until.kinetic_to_elastic_below):
            return False
        if has(until, "unbalanced_force_below") and not (
                stats.contacts > 0 and stats.unbalanced_force < until.unbalanced_force_below):
            return False
        if has(until, "servo_tolerance"):
            if not self.servo_targets:
                return False
            for wall, target in self.servo_targets.items():
                if abs(walls[wall].normal_force - target) > until.servo_tolerance * abs(target):
                    return False
        if has(until, "wall_stress_above"):
            threshold = until.wall_stress_above
            if walls[threshold.wall].normal_stress < threshold.value:
                return False
        if has(until, "wall_settlement_above"):
            threshold = until.wall_settlement_above
            if walls[threshold.wall].settlement < threshold.value:
                return False
        return True
