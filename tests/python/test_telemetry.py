"""Telemetry from Python: iterated while a run goes on, or delivered to a
callback; and the GIL released while a reply is awaited, so Python threads
keep running meanwhile."""

import threading
import time

import pytest

import dem
from conftest import case_file, until_samples_flow


def test_iterating_over_the_telemetry_of_a_run(serve):
    client = serve("telemetry_iteration", telemetry_cycles=10)
    client.load_case(case_file("nine_disc_damped"))
    client.set_wall_velocity("top", (0, -12))
    with client.subscribe(status=True) as telemetry:
        start = until_samples_flow(client, telemetry, kinds=(dem.PlateForces, dem.ContactStats))
        run = client.start_cycle(200)
        plates, stats, states = [], [], []
        for sample in telemetry.samples(timeout=1.0):
            if isinstance(sample, dem.PlateForces):
                plates.append(sample)
            elif isinstance(sample, dem.ContactStats):
                stats.append(sample)
            else:
                states.append(sample)
            if plates and plates[-1].cycle == start + 200 and stats and stats[-1].cycle == start + 200:
                break
        assert client.await_run(run, timeout=10).cycles_run == 200
        # The status (durable, the last one kept) ends with the run's end.
        for sample in telemetry.samples(timeout=0.5):
            if isinstance(sample, dem.Status):
                states.append(sample)
    # Every sample, in order: telemetry every 10 cycles (and once more as the run ends).
    # (A warm-up sample may still come after the drain: only the run's count.)
    assert sorted(set(p.cycle for p in plates if p.cycle > start)) == list(range(start + 10, start + 201, 10))
    assert [p.cycle for p in plates] == sorted(p.cycle for p in plates)
    assert sorted(set(s.cycle for s in stats if s.cycle > start)) == list(range(start + 10, start + 201, 10))
    assert states[-1].state == "loaded" and states[-1].cycle == start + 200
    top = plates[-1].wall("top")
    assert top.name == "top" and top.settlement == pytest.approx((start + 200) * 12 * 0.01)
    assert top.normal_stress == pytest.approx(top.normal_force / top.area)
    assert len(top.position) == 3 and top.contacts == 3
    with pytest.raises(KeyError, match='no wall "roof" \\(walls: bottom, right, top, left\\)'):
        plates[-1].wall("roof")
    assert stats[-1].particles == 9 and len(stats[-1].histogram) > 0
    assert telemetry.closed


def test_a_callback_receives_every_sample(serve):
    client = serve("telemetry_callback", telemetry_cycles=10)
    client.load_case(case_file("nine_disc_damped"))
    received = []
    flowing, done = threading.Event(), threading.Event()

    def on_sample(sample):  # on the subscription's own thread
        received.append(sample)
        flowing.set()
        if sample.cycle == 300:
            done.set()

    telemetry = client.subscribe(contact_stats=False, callback=on_sample)
    try:
        assert telemetry.wait_for_publisher()
        for _ in range(50):  # until samples flow (discovery goes both ways)
            start = client.cycle(10).state.cycle
            if flowing.wait(0.2):
                break
        client.cycle(300 - start)
        assert done.wait(10.0)
    finally:
        telemetry.close()
    assert sorted(set(s.cycle for s in received if s.cycle > start)) == list(range(start + 10, 301, 10))
    assert all(isinstance(s, dem.PlateForces) for s in received)


def test_the_gil_is_released_while_waiting(serve):
    client = serve("telemetry_gil_released")
    client.load_case(case_file("verification_assembly"))
    beats = []
    stop = threading.Event()

    def heartbeat():
        while not stop.is_set():
            beats.append(time.monotonic())
            time.sleep(0.005)

    thread = threading.Thread(target=heartbeat)
    thread.start()
    try:
        # The main thread waits a second in one slice for a reply that does
        # not come; with the GIL held the heartbeat would stop for that second.
        started = time.monotonic()
        with pytest.raises(dem.ReplyTimeout):
            client.cycle(10 ** 9, timeout=1.0, wait_interval=1.0)
        ended = time.monotonic()
    finally:
        stop.set()
        thread.join()
        client.stop()
    assert ended - started >= 0.9
    during = [t for t in beats if started <= t <= ended]
    gaps = [b - a for a, b in zip([started] + during, during + [ended])]
    assert len(during) > 20 and max(gaps) < 0.3, f"the heartbeat paused {max(gaps):.3f} s while the main thread waited"


def test_the_measures_of_a_cases_regions(serve):
    """A case with measurement regions (output.region) publishes their
    stress, fabric, porosity and coordination (dem.RegionTelemetry)."""
    client = serve("telemetry_regions", telemetry_cycles=10)
    client.load_case(dem.paths.cases_dir().parent / "tests" / "io" / "data" / "biaxial.case.txtpb")
    with client.subscribe(plate_forces=False, contact_stats=False, region_measures=True) as telemetry:
        cycle = until_samples_flow(client, telemetry, kinds=(dem.RegionTelemetry,))
        client.cycle(2000)
        last = None
        for sample in telemetry.samples(timeout=1.0):
            assert isinstance(sample, dem.RegionTelemetry)
            last = sample
            if sample.cycle == cycle + 2000:
                break
    assert last is not None and last.cycle == cycle + 2000
    assert last.dimension == 2
    assert [r.name for r in last.regions] == ["all", "core", "circle"]
    whole = last.region("all")
    assert whole.particles == 120
    assert len(whole.stress) == 4 and len(whole.fabric) == 4
    assert 0.0 < whole.porosity < 1.0
    assert whole.mean_stress == pytest.approx(0.5 * (whole.stress[0] + whole.stress[3]))
