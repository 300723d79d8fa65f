"""dem.sweep (docs/SWEEPS.md): cases built from parameter paths, the sweep
directory, the local and Dask backends running Miyata's reduced CS case,
progress, an interrupted sweep continued, the results gathered, the
command line, and dem.bridge following a sweep's servers only. Domains
201-203 (tests/sweep/CMakeLists.txt)."""

import asyncio
import fcntl
import os
import pathlib
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import dem
import dem.sweep
from dem.sweep import Parameter, Sweep

CS_REDUCED = dem.paths.cases_dir() / "miyata" / "cs_reduced.case.txtpb"
LOCAL_DOMAIN, INTERRUPT_DOMAIN, DASK_DOMAIN = 201, 202, 203


def base_case():
    return dem.cases.load_case_file(CS_REDUCED)


# --- building cases ---------------------------------------------------------

def test_parameter_paths_set_what_they_name():
    case = base_case()
    dem.sweep.set_field(case, "material[rock].friction", 0.3)
    assert [m.friction for m in case.material] == [0.3, 0.51]
    dem.sweep.set_field(case, "material[*].friction", 0.7)
    assert [m.friction for m in case.material] == [0.7, 0.7]
    dem.sweep.set_field(case, "stage[2].wall[0].motion.velocity.y", -0.01)
    assert case.stage[2].wall[0].motion.velocity.y == -0.01
    dem.sweep.set_field(case, "particles[0].random_packing.seed", 7)
    assert case.particles[0].random_packing.seed == 7
    dem.sweep.set_field(case, "gravity.y", -5)
    assert case.gravity.y == -5.0


@pytest.mark.parametrize("path, value, message", [
    ("material[granite].friction", 0.3, "none is named 'granite' (names: rock, plate)"),
    ("material.friction", 0.3, "material is repeated"),
    ("material[rock].stickiness", 0.3, "Material has no field 'stickiness'"),
    ("stage[9].cycles", 10, "stage[9]: there are 3"),
    ("particles[0].random_packing.seed", 1.5, "is not a whole number"),
    ("gravity", 1.0, "gravity is a message"),
])
def test_a_wrong_path_or_value_says_what_is_wrong(path, value, message):
    with pytest.raises((KeyError, ValueError)) as error:
        dem.sweep.set_field(base_case(), path, value)
    assert message in str(error.value)


def test_grid_and_zip_combinations_and_functions():
    friction = Parameter("friction", [0.3, 0.6], path="material[*].friction")
    speed = Parameter("speed", [0.05, 0.1, 0.2], apply=lambda case, v: setattr(
        case.stage[2].wall[0].motion.velocity, "y", -v))
    grid = dem.sweep.combinations([friction, speed])
    assert len(grid) == 6 and grid[1] == {"friction": 0.3, "speed": 0.1}
    with pytest.raises(ValueError, match="as many values"):
        dem.sweep.combinations([friction, speed], "zip")
    base = base_case()
    built = dem.sweep.build_case(base, [friction, speed], grid[5])
    assert built.material[1].friction == 0.6 and built.stage[2].wall[0].motion.velocity.y == -0.2
    assert base.material[1].friction == 0.51  # the base case is left as it was


def test_a_sweep_directory_is_made_once(tmp_path):
    sweep = Sweep.create(tmp_path / "s", CS_REDUCED, {"material[*].friction": [0.3, 0.6]}, domain=LOCAL_DOMAIN)
    assert sweep.name == "s" and len(sweep.tasks) == 2 and sweep.unfinished() == [0, 1]
    assert sweep.server_name(1) == "s_0001"
    assert dem.cases.load_case_file(sweep.case_file(1)).material[0].friction == 0.6
    assert os.access(sweep.task_script, os.X_OK)
    assert "domain=201" in (sweep.directory / "sweep.conf").read_text()
    again = Sweep.create(tmp_path / "s", CS_REDUCED, {"material[*].friction": [0.3, 0.6]}, domain=LOCAL_DOMAIN)
    assert again.tasks == sweep.tasks
    with pytest.raises(dem.DemError, match="holds another sweep"):
        Sweep.create(tmp_path / "s", CS_REDUCED, {"material[*].friction": [0.3, 0.9]}, domain=LOCAL_DOMAIN)
    with pytest.raises(ValueError, match="sweep name"):
        Sweep.create(tmp_path / "t", CS_REDUCED, {"material[*].friction": [0.3]}, name="9lives")


def test_particle_files_are_found_from_the_base_case(tmp_path):
    bench = dem.paths.cases_dir() / "bench" / "plate_compression_10k.case.txtpb"
    sweep = Sweep.create(tmp_path / "b", bench, {"material[sphere].friction": [0.4]})
    path = pathlib.Path(sweep.case(0).particles[0].csv_file.path)
    assert path.is_absolute() and path.name == "packing_N10000.csv"
    assert path == (bench.parent / "../../../shared/bench/packing_N10000.csv").resolve()


# --- running ------------------------------------------------------------------

def watch_bridge(domain, sweep_name, seen, stop):
    """dem.bridge --sweep in a thread: records every server it advertised."""
    from dem.bridge.server import Bridge
    bridge = Bridge(domain, port=0, sweep=sweep_name)

    async def run():
        task = asyncio.create_task(bridge.serve())
        while not stop.is_set():
            seen.update(channel.server for channel in list(bridge.channels.values()))
            await asyncio.sleep(0.05)
        bridge.stop()
        await task

    asyncio.run(run())


def test_local_backend_runs_follows_and_gathers(tmp_path):
    # A server of another name on the sweep's domain: the bridge following the sweep leaves it out.
    outsider = dem.ServerProcess("outsider", LOCAL_DOMAIN, tmp_path / "outsider").start()
    seen, stop = set(), threading.Event()
    bridge = threading.Thread(target=watch_bridge, args=(LOCAL_DOMAIN, "loc", seen, stop))
    bridge.start()
    try:
        sweep = Sweep.create(tmp_path / "loc", CS_REDUCED, {"material[*].friction": [0.3, 0.45, 0.6]},
                             domain=LOCAL_DOMAIN)
        reports = []
        progress = sweep.run(dem.sweep.LocalBackend(workers=2), on_progress=reports.append, poll=0.2)
    finally:
        stop.set()
        bridge.join()
        assert outsider.stop() == 0
    assert progress.finished and progress.counts["done"] == 3
    assert reports[0].counts["pending"] + reports[0].counts["running"] == 3
    assert any(r.counts["running"] for r in reports), [str(r) for r in reports]
    assert seen and seen <= {"loc_0000", "loc_0001", "loc_0002"}, seen

    results = sweep.results()
    assert results.parameters["friction"].tolist() == [0.3, 0.45, 0.6]
    assert list(results.states) == ["done"] * 3
    assert results.stress.shape == results.settlement.shape == (3, results.lengths.max())
    for i in range(3):
        settlement, stress = results.curve(i)
        assert settlement.size > 100 and np.all(np.diff(settlement) > 0)  # the plate only goes down
        assert np.isnan(results.stress[i, results.lengths[i]:]).all()
        assert stress[-1] >= 900e3 and results.final["stress"][i] == stress[-1]
        assert results.final["stiffness_final"][i] > 1e6 and results.final["contacts"][i] > 200
    rows = (sweep.directory / "summary.csv").read_text().splitlines()
    assert rows[0].startswith("task,friction,server,state,exit_code,attempts,plate,samples,cycles,")
    assert len(rows) == 4 and all(",done,0,1,top," in row for row in rows[1:])
    # Run again: nothing is left to do.
    assert sweep.submit(dem.sweep.LocalBackend()) is None


def test_an_interrupted_sweep_continues_where_it_stopped(tmp_path):
    # Slower plates (0.02 m/s instead of 0.05), so a task is caught running; checkpoints every 5,000 cycles.
    sweep = Sweep.create(tmp_path / "intr", CS_REDUCED,
                         {"material[*].friction": [0.3, 0.45, 0.6],
                          "stage[2].wall[0].motion.velocity.y": [-0.02]}, domain=INTERRUPT_DOMAIN,
                         checkpoint_cycles=5000)
    script = f"""
import dem.sweep
dem.sweep.Sweep.open({str(sweep.directory)!r}).run(dem.sweep.LocalBackend(workers=1), poll=0.1)
"""
    # Ctrl-C while task 1 runs (and has a checkpoint): its server stops with a final snapshot; task 2 never starts.
    runner = subprocess.Popen([sys.executable, "-c", script], start_new_session=True,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    deadline = time.monotonic() + 60
    checkpoints = sweep.task_dir(1) / "miyata_cs_reduced" / "checkpoints"
    while sweep.status([1])[0].state != "running" or not list(checkpoints.glob("*.resume")):
        assert runner.poll() is None and time.monotonic() < deadline, runner.stdout.read().decode()
        time.sleep(0.05)
    os.killpg(runner.pid, signal.SIGINT)
    runner.wait(60)
    states = [t.state for t in sweep.status()]
    assert states == ["done", "stopped", "pending"], states
    assert sweep.status([1])[0].exit_code == 4
    assert sweep.unfinished() == [1, 2]

    first = (sweep.task_dir(0) / "miyata_cs_reduced" / "final.snapshot").stat().st_mtime_ns
    progress = Sweep.open(sweep.directory).run(dem.sweep.LocalBackend(workers=2), poll=0.2, on_progress=None)
    assert progress.finished
    attempts = [t.attempt for t in sweep.status()]
    assert attempts == [1, 2, 1], attempts  # task 0 was not run again
    assert [t.resumed for t in sweep.status()] == [False, True, False]  # task 1 went on from its checkpoint
    assert "resuming from the checkpoint at cycle" in (sweep.task_dir(1) / "dem_server.log").read_text()
    assert (sweep.task_dir(0) / "miyata_cs_reduced" / "final.snapshot").stat().st_mtime_ns == first


def test_a_running_task_is_not_started_twice(tmp_path):
    sweep = Sweep.create(tmp_path / "twice", CS_REDUCED, {"material[*].friction": [0.3]},
                         domain=INTERRUPT_DOMAIN)
    # Another process holds the task's lock, as a running task (its script and server) does.
    sweep.task_dir(0).mkdir(parents=True)
    with open(sweep.task_dir(0) / "task.lock", "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        assert sweep.status()[0].state == "running" and sweep.unfinished() == []
        second = subprocess.run(["bash", str(sweep.task_script), str(sweep.directory), "0"], capture_output=True,
                                text=True, timeout=30)
        assert second.returncode == 75 and "running already" in second.stderr
    assert sweep.status()[0].state == "pending" and sweep.unfinished() == [0]


def test_dask_backend(tmp_path):
    distributed = pytest.importorskip("distributed")
    sweep = Sweep.create(tmp_path / "dsk", CS_REDUCED, {"material[*].friction": [0.3, 0.6]}, domain=DASK_DOMAIN)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        progress = sweep.run(dem.sweep.DaskBackend(client), poll=0.2, on_progress=None)
    assert progress.finished
    assert sorted(p.name for p in (sweep.directory / "logs").iterdir()) == ["dask-0000.out", "dask-0001.out"]
    assert (sweep.directory / "logs" / "dask-0001.out").read_text().strip().endswith("done (exit 0)")
    assert sweep.results().final["stress"].min() >= 900e3


def test_the_command_line(tmp_path):
    sweep = Sweep.create(tmp_path / "cli", CS_REDUCED, {"material[*].friction": [0.3, 0.6]}, domain=LOCAL_DOMAIN)
    command = [sys.executable, "-m", "dem.sweep"]
    status = subprocess.run(command + ["status", str(sweep.directory)], capture_output=True, text=True)
    assert status.returncode == 1 and "pending" in status.stdout
    run = subprocess.run(command + ["run", str(sweep.directory), "--tasks", "1", "--poll", "0.2"],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 1, run.stdout + run.stderr  # task 0 is still to run
    assert [t.state for t in sweep.status()] == ["pending", "done"]
    run = subprocess.run(command + ["run", str(sweep.directory), "--poll", "0.2"], capture_output=True, text=True,
                         timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    results = subprocess.run(command + ["results", str(sweep.directory)], capture_output=True, text=True)
    assert results.returncode == 0 and results.stdout.count(",done,") == 2
    wrong = subprocess.run(command + ["status", str(tmp_path)], capture_output=True, text=True)
    assert wrong.returncode == 2 and "not a sweep directory" in wrong.stderr


def test_packings_runs_a_case_over_packings_and_dem_validate_judges_them(tmp_path):
    command = [sys.executable, "-m", "dem.sweep", "packings", str(CS_REDUCED), "--out", str(tmp_path / "packings"),
               "--packings", "2", "--workers", "2", "--domain", str(LOCAL_DOMAIN)]
    run = subprocess.run(command, capture_output=True, text=True, timeout=240)
    output = run.stdout + run.stderr
    assert run.returncode in (0, 1), output  # the verdict over two packings, either way
    sweep = Sweep.open(tmp_path / "packings")
    assert [t.state for t in sweep.status()] == ["done", "done"]
    assert "miyata_cs_reduced over 2 packings" in output, output
    assert output.count("over packings:") >= 3, output  # one line per check, "N of 2 packings"
    verdict = "miyata-compression: PASS" if run.returncode == 0 else "miyata-compression: FAIL"
    assert verdict in output, output
    # Each task ran its own packing: the case's seed, then 1.
    results = sweep.results(write_summary=False)
    assert [int(seed) for seed in results.parameters["seed"]] == [2002, 1], results.parameters
    cycles = {(task.output_dir() / "compression.csv").read_text().count("\n") for task in sweep.status()}
    assert len(cycles) == 2, "two packings loaded alike"
