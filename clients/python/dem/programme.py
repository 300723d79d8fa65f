"""A case's loading programme run by the server (the run_programme command),
stage by stage and, when asked, paused at exact cycles for the script to
read the world: the force at a contact every 10 cycles, as dem_run's probes.

The server runs every stage as dem_run does (trims, wall placements, wall
motions, damping, stop conditions). With ``sample_every`` the run returns
every that many cycles of a stage, counted from its start, and at each
stage's end; the world waits there while ``on_sample`` reads it (contacts,
state, a snapshot), and the next run_programme resumes it as if never
interrupted - the same cycles, the same state, bit for bit (docs/PYTHON.md,
"Programmes").
"""

import dataclasses

from .errors import ProgrammeError


def has(message, field):
    """Whether ``field`` is set - False when this schema has no such field, so
    the readers of cases accept those written for older and newer schemas alike."""
    return field in message.DESCRIPTOR.fields_by_name and message.HasField(field)


@dataclasses.dataclass(frozen=True)
class StageOutcome:
    index: int
    name: str
    cycles_run: int
    condition_met: bool  # a stop condition ended the stage before its cycle cap


def run_programme(client, case, *, stages=None, sample_every=0, on_sample=None, on_wait=None, timeout=None):
    """Runs the stages of ``case``, which the server must have loaded, on the
    server: all, or the consecutive indices (from 0) in ``stages``.
    ``on_sample(index, cycle)`` is called every ``sample_every`` cycles of a
    stage with the stage's index and the server's cycle, the run paused
    there; returning False ends the stage (the next one begins).
    ``on_wait()`` is called while cycles run; ``timeout`` bounds each
    step. Returns a StageOutcome per stage."""
    first, end = _stage_range(len(case.stage), stages)
    outcomes = []
    stage, done, resume = first, 0, False
    while stage < end:
        reply = client.run_programme(first_stage=stage + 1, stage_count=end - stage, sample_every=sample_every,
                                     stage_ends=True, resume=resume, stage_cycles_done=done, timeout=timeout,
                                     on_wait=on_wait)
        index, resume = reply.stage - 1, True
        carry_on = True
        if on_sample is not None and sample_every > 0 and reply.stage_cycles > 0 and \
                reply.stage_cycles % sample_every == 0:
            carry_on = on_sample(index, reply.state.cycle) is not False
        if reply.stage_ended or not carry_on:
            outcomes.append(StageOutcome(index, case.stage[index].name, reply.stage_cycles,
                                         reply.stage_ended and reply.condition_met))
            stage, done = index + 1, 0
        else:
            stage, done = index, reply.stage_cycles
    return outcomes


def _stage_range(count, stages):
    """The stages to run as [first, end), from 0."""
    if stages is None:
        return 0, count
    indices = list(stages)
    if not indices:
        return 0, 0
    if indices != list(range(indices[0], indices[0] + len(indices))) or indices[0] < 0 or indices[-1] >= count:
        raise ProgrammeError(f"stages {indices} are not consecutive stages of the case's {count}")
    return indices[0], indices[0] + len(indices)
