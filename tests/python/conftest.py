"""Shared by the Python client's tests: dem_server processes of this build on
loopback, each test on a DDS domain of its own so ctest runs the files side
by side (the configuration comes from CYCLONEDDS_URI, set by ctest)."""

import pathlib

import pytest

import dem

# One domain per test, distinct across this suite by construction, and
# apart from the others: tests/service 40-119, bench_service 125, the demo
# 30 and its bridge's, tests/container 150-157, tests/docs 186-187,
# tests/ros2 190; the Python suite has 160-174 and 180-185, its examples
# 175-178.
DOMAINS = {
    "cases_built_in_python": 160,
    "cases_invalid": 161,
    "contacts_match_the_cpp_client": 162,
    "contacts_filters": 163,
    "errors_server_messages": 164,
    "errors_timeouts_and_interrupts": 165,
    "errors_no_server": 166,
    "experiment_nine_disc": 167,
    "experiment_programme_steps": 168,
    "experiment_one_shot_compression": 172,
    "experiment_server_programme": 173,
    "telemetry_iteration": 169,
    "telemetry_callback": 170,
    "telemetry_gil_released": 171,
    "telemetry_regions": 221,
    "recording_demctl_record": 174,
    "recording_regions": 223,
    "bridge_page": 180,
    "bridge_foxglove": 181,
}
assert len(set(DOMAINS.values())) == len(DOMAINS), "two tests share a DDS domain"
assert all(160 <= d <= 174 or 180 <= d <= 185 or 220 <= d <= 239 for d in DOMAINS.values()), \
    "the Python tests' domains are 160-174 and 180-185 (and issue 13's, 220-239)"

CASES = dem.paths.cases_dir()


def case_file(name):
    """cases/ball/<name>.case.txtpb"""
    return CASES / "ball" / f"{name}.case.txtpb"


@pytest.fixture
def serve(tmp_path):
    """serve(key) starts a dem_server on the domain of ``key`` and returns a
    connected Client; every server is stopped with SIGTERM afterwards, and
    must exit 0."""
    started = []

    def start(key, telemetry_cycles=10):
        server = dem.ServerProcess(f"py_{key}", DOMAINS[key], tmp_path / key, telemetry_cycles=telemetry_cycles)
        server.start()
        client = server.connect(timeout=20)
        started.append((server, client))
        return client

    yield start
    for server, client in started:
        client.close()
        code = server.stop()
        assert code == 0, f"dem_server {server.name} exited {code}; log: {server.log_file.read_text()[-2000:]}"


@pytest.fixture
def out(tmp_path):
    path = pathlib.Path(tmp_path) / "out"
    path.mkdir()
    return path


def until_samples_flow(client, telemetry, kinds=(dem.PlateForces,)):
    """Runs 10 cycles at a time until a sample of each of ``kinds`` arrives
    for the cycle reached: the server's writers of those topics have then
    matched this reader too (discovery goes both ways, a reader can match
    before the writer does, and each topic's writer matches on its own).
    The cycle count reached."""
    assert telemetry.wait_for_publisher()
    for _ in range(50):
        cycle = client.cycle(10).state.cycle
        waiting = set(kinds)
        for sample in telemetry.samples(timeout=0.2):
            if sample.cycle == cycle:
                waiting.discard(type(sample))
            if not waiting:
                telemetry.drain()
                return cycle
    raise AssertionError("no telemetry arrived in 50 tries")
