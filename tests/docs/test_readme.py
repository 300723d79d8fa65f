"""The README's examples run as a new user would paste them: the service
session (dem_server, demctl: load, monitor, record, run-until, hold, status
--json, contacts, snapshot, a staged case), the Python client's block and
dem_run's. Each block is taken from README.md as it stands; only the DDS
domain (so the test has its own), the build directory and out/ (into a
temporary directory) are replaced - and the test fails if those are not
found, so it follows the README rather than a copy of it. The results
must also make physical sense (the top wall stays inside its box).

Environment: DEM_SOURCE_DIR, DEM_BUILD_DIR; domains 186 and 187.
"""

import json
import os
import pathlib
import re
import subprocess

import pytest

import dem
from dem.recording import Recording

SOURCE = pathlib.Path(os.environ["DEM_SOURCE_DIR"])
BUILD = pathlib.Path(os.environ["DEM_BUILD_DIR"])
README = (SOURCE / "README.md").read_text()


def block(section, language):
    """The first ```language block after the heading `## section`."""
    start = README.index(f"\n## {section}\n")
    found = re.compile(rf"```{language}\n(.*?)```", re.S).search(README, start)
    assert found, f"README.md: no {language} block in '{section}'"
    return found.group(1)


def replace(text, old, new):
    assert old in text, f"the README's block no longer has {old!r}: update this test"
    return text.replace(old, new)


def run_shell(script, tmp_path, timeout=300):
    result = subprocess.run(["bash", "-e", "-c", script], cwd=SOURCE, capture_output=True, text=True, timeout=timeout,
                            env=dict(os.environ, OMP_WAIT_POLICY="passive"))
    assert result.returncode == 0, f"exit {result.returncode}\n{result.stdout[-3000:]}\n{result.stderr[-3000:]}"
    return result


def test_the_service_session(tmp_path):
    script = block("The simulation service", "sh")
    script = replace(script, "--domain 7", "--domain 186")
    script = replace(script, "build/", f"{BUILD}/")
    script = replace(script, "out/", f"{tmp_path}/out/")
    # The session leaves monitor and record to end with the server: wait for them.
    result = run_shell(script + "\nwait\n", tmp_path)
    out = tmp_path / "out" / "press"
    reached = re.search(r"the stress on top reached [0-9.e+]+ Pa after (\d+) cycles", result.stdout)
    assert reached, result.stdout
    state = json.loads((out / "state.json").read_text())
    # About 70 cycles to 1 MPa (0.005 m a cycle), then 1000 holding.
    assert 50 < int(reached.group(1)) < 100
    assert state["status"]["cycle"] == int(reached.group(1)) + 1000
    top = next(w for w in state["plates"]["walls"] if w["name"] == "top")
    # Physically sensible: the top wall 0.36 m down a 300 m box, carrying about 1 MPa at rest.
    assert 0.3 < top["settlement"] < 0.4
    assert 0.8e6 < top["normal_stress"] < 1.2e6
    assert state["stats"]["kinetic_energy"] < 1e-3
    with open(out / "monitor.csv") as monitor:
        assert len(monitor.readlines()) > 10
    recording = Recording(out / "telemetry.mcap")
    plates = [m.data for m in recording.messages("/dem/press/plate_forces")]
    # The recording goes on to the staged case; the nine-disc session is in it up to the state saved.
    assert state["status"]["cycle"] in {p.cycle for p in plates}
    assert len((out / "top.csv").read_text().splitlines()) == 1 + top["contacts"]
    assert (tmp_path / "out" / "press.snapshot").stat().st_size > 0
    assert (out / "miyata_cs_reduced" / "compression.csv").is_file()  # the staged case ran on the server


def test_the_python_client_block(tmp_path):
    script = block("The Python client", "sh")
    script = replace(script, "$PWD/build/", f"{BUILD}/")
    script = replace(script, "domain=21", "domain=187")
    script = replace(script, "out/", f"{tmp_path}/out/")
    run_shell(script, tmp_path)
    assert (tmp_path / "out" / "press" / "contact_c.png").stat().st_size > 1000


def test_running_a_case(tmp_path):
    script = block("Running a case", "sh")
    script = replace(script, "build/", f"{BUILD}/")
    script = replace(script, "out/", f"{tmp_path}/out/")
    run_shell(script, tmp_path)
    for name in ("walls.csv", "assembly.csv", "probes.csv", "contacts.csv", "particles.csv", "final.snapshot"):
        assert (tmp_path / "out" / "nine" / name).stat().st_size > 0, name
