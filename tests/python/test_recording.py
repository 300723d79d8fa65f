"""Recordings: `demctl record FILE.mcap` writes a server's telemetry as a
ROS 2 bag holds it (ros2msg schemas, CDR messages), dem.recording reads it
back - complete, and equal to what the server reports - and an independent
reader from the npm registry (@mcap/core, tests/npm/read_mcap.mjs) reads
the same file, every CRC checked, to the same messages byte for byte.

Environment (ctest): DEM_NPM_DIR, where tests/npm/install.sh put the npm
packages and scripts.
"""

import hashlib
import json
import os
import pathlib
import signal
import subprocess
import time

import pytest

import dem
from dem.recording import Recording, RecordingError

from conftest import DOMAINS, case_file, until_samples_flow

NPM_DIR = pathlib.Path(os.environ.get("DEM_NPM_DIR", ""))
KEY = "recording_demctl_record"


def msg_fields(name):
    """The field lines of ros2/dem_interfaces/msg/<name>.msg, comments dropped."""
    path = dem.paths.source_dir() / "ros2" / "dem_interfaces" / "msg" / f"{name}.msg"
    lines = [line.split("#", 1)[0].strip() for line in path.read_text().splitlines()]
    return [line for line in lines if line]


class DemctlRecord:
    """`demctl record FILE` of the server of ``key``, started once its
    subscriptions are matched (it says so: nothing published after is missed)."""

    def __init__(self, key, path):
        self.path = path
        self.process = subprocess.Popen([str(dem.paths.demctl_program()), "--server", f"py_{key}", "--domain",
                                         str(DOMAINS[key]), "--timeout", "20", "record", str(path)],
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.process.stderr.readline()
        assert line.startswith("recording server"), line + self.process.stderr.read()

    def stop(self):
        """Ctrl-C; the summary line demctl printed."""
        time.sleep(0.5)  # the last telemetry sample follows the reply
        self.process.send_signal(signal.SIGINT)
        stdout, stderr = self.process.communicate(timeout=30)
        assert self.process.returncode == 0, stderr
        assert "recorded" in stdout and "plate forces" in stdout
        return stdout


@pytest.fixture
def recorded(serve, tmp_path):
    """A 300-cycle run of the nine-disc test with telemetry every 10 cycles,
    recorded by demctl record; (the file, the state after the run)."""
    press = serve(KEY, telemetry_cycles=10)
    press.load_case(case_file("nine_disc_damped"))
    press.set_wall_velocity("top", (0, -0.5))
    recorder = DemctlRecord(KEY, tmp_path / "run.mcap")
    press.cycle(300)
    state = press.state()
    recorder.stop()
    return recorder.path, state


def test_the_recording_holds_every_sample_of_the_run_as_the_server_reported_it(recorded):
    path, state = recorded
    recording = Recording(path)
    assert recording.profile == "ros2"
    topic = f"/dem/py_{KEY}"
    assert recording.topics() == {f"{topic}/status": "dem_interfaces/msg/Status",
                                  f"{topic}/plate_forces": "dem_interfaces/msg/PlateForces",
                                  f"{topic}/contact_stats": "dem_interfaces/msg/ContactStats",
                                  f"{topic}/region_measures": "dem_interfaces/msg/RegionTelemetry"}
    assert list(recording.messages(f"{topic}/region_measures")) == []  # a case without regions
    plates = [m.data for m in recording.messages(f"{topic}/plate_forces")]
    cycles = [p.cycle for p in plates]
    assert cycles[-30:] == list(range(10, 301, 10)), str(cycles)  # every sample of the run, in order
    last = plates[-1]
    assert last.cycle == state.state.cycle == 300
    for wall, reported in zip(last.walls, state.plates.walls):
        assert (wall.name, wall.normal_stress, wall.settlement) == (reported.name, reported.normal_stress,
                                                                      reported.settlement)
    stats = [m.data for m in recording.messages(f"{topic}/contact_stats")]
    assert [s.cycle for s in stats][-30:] == cycles[-30:]
    assert stats[-1].contacts == state.stats.contacts
    statuses = [m.data.state_name for m in recording.messages(f"{topic}/status")]
    assert "running" in statuses and statuses[0] == "loaded"
    # Log times are when the samples came, in order; publish times the server's clock.
    times = [m.log_time for m in recording.messages()]
    assert times == sorted(times) and times[0] > 1.6e18


def test_a_cases_region_measures_are_recorded_as_the_server_published_them(serve, tmp_path):
    """The region_measures topic (a case with output.region: biaxial's three
    regions) goes into the recording beside the plates, each sample decoded
    from its nested RegionMeasures equal to what a subscriber received."""
    key = "recording_regions"
    client = serve(key, telemetry_cycles=10)
    client.load_case(dem.paths.cases_dir().parent / "tests" / "io" / "data" / "biaxial.case.txtpb")
    recorder = DemctlRecord(key, tmp_path / "regions.mcap")
    with client.subscribe(plate_forces=False, contact_stats=False, region_measures=True) as telemetry:
        start = until_samples_flow(client, telemetry, kinds=(dem.RegionTelemetry,))
        client.cycle(200)
        received = {}
        for sample in telemetry.samples(timeout=2.0):
            received[sample.cycle] = sample
            if sample.cycle == start + 200:
                break
    summary = recorder.stop()
    topic = f"/dem/py_{key}/region_measures"
    recorded = {m.data.cycle: m.data for m in Recording(recorder.path).messages(topic)}
    cycles = list(range(start + 10, start + 201, 10))
    assert [c for c in cycles if c in recorded] == cycles, sorted(recorded)
    assert f"{len(recorded)} region measures" in summary
    last, live = recorded[start + 200], received[start + 200]
    assert last.dimension == 2 and [r.name for r in last.regions] == ["all", "core", "circle"]
    for mine, theirs in zip(last.regions, live.regions):
        assert (mine.name, mine.particles, mine.porosity, mine.mean_stress) == \
            (theirs.name, theirs.particles, theirs.porosity, theirs.mean_stress)
        assert list(mine.stress) == list(theirs.stress) and list(mine.fabric) == list(theirs.fabric)


def test_the_schemas_are_the_interface_packages_messages(recorded):
    path, _ = recorded
    recording = Recording(path)
    for schema_id, (name, encoding, text) in recording.schemas.items():
        assert encoding == "ros2msg"
        own = text.split("=" * 80)[0].splitlines()
        assert own == msg_fields(name.rsplit("/", 1)[1])
        assert f"MSG: builtin_interfaces/Time" in text


@pytest.mark.skipif(not (NPM_DIR / "node_modules").is_dir(), reason="the npm packages are not installed "
                    "(ctest runs tests/npm/install.sh first)")
def test_mcap_core_from_npm_reads_the_same_messages(recorded):
    path, _ = recorded
    result = subprocess.run(["node", str(NPM_DIR / "read_mcap.mjs"), str(path)], capture_output=True, text=True,
                            timeout=60)
    assert result.returncode == 0, result.stderr
    seen = json.loads(result.stdout)
    recording = Recording(path)
    assert seen["profile"] == "ros2"
    assert seen["streamDone"] and seen["streamedMessages"] == len(recording)
    assert seen["statisticsMessageCount"] == len(recording)
    assert seen["dataSectionCrc"] != 0
    assert {c["topic"]: c["schemaName"] for c in seen["channels"]} == recording.topics()
    assert {c["messageEncoding"] for c in seen["channels"]} == {"cdr"}
    assert {c["schemaEncoding"] for c in seen["channels"]} == {"ros2msg"}
    topics = {c["id"]: c["topic"] for c in seen["channels"]}
    theirs = [(topics[channel], int(log), int(publish), digest) for channel, _, log, publish, digest in seen["messages"]]
    ours = [(topic, log, publish, hashlib.sha256(data).hexdigest())
            for topic, log, publish, data in recording.raw_messages()]
    assert theirs == ours


def test_a_file_that_is_not_a_recording_is_named(tmp_path):
    path = tmp_path / "not.mcap"
    path.write_bytes(b"walls.csv\n")
    with pytest.raises(RecordingError, match="not.mcap: not an MCAP file"):
        Recording(path)


def test_the_stress_settlement_plot_reads_a_recording(recorded):
    from dem.plots.stress_settlement import StressSettlementSeries

    path, state = recorded
    series = StressSettlementSeries.from_file(path, ["top"])
    top = next(w for w in state.plates.walls if w.name == "top")
    assert series.column("top", "stress")[-1] == top.normal_stress
    assert series.column("top", "settlement")[-1] == top.settlement
