"""dem.sweep's Slurm backend on a real one-machine Slurm cluster
(scripts/slurm/local_cluster.sh): a sweep submitted as one job array, a
second submission while it is queued submits nothing, a failed task is
reported and resubmitted alone. Needs root (slurmd); domain 204."""

import os
import pathlib
import subprocess

import pytest

import dem
import dem.sweep
from dem.sweep import Sweep

DOMAIN = 204
CS_REDUCED = dem.paths.cases_dir() / "miyata" / "cs_reduced.case.txtpb"
LOCAL_CLUSTER = dem.paths.source_dir() / "scripts" / "slurm" / "local_cluster.sh"

pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason="a Slurm node runs jobs as their users: needs root")


@pytest.fixture
def slurm(monkeypatch):
    # Not in tmp_path: pytest makes that private, and munged runs as the user munge.
    cluster = pathlib.Path(os.environ["DEM_SLURM_CLUSTER_DIR"])
    subprocess.run(["bash", str(LOCAL_CLUSTER), "start", str(cluster)], check=True, timeout=120)
    monkeypatch.setenv("SLURM_CONF", str(cluster / "slurm.conf"))
    yield cluster
    subprocess.run(["bash", str(LOCAL_CLUSTER), "stop", str(cluster)], check=True, timeout=120)


def test_a_sweep_as_a_slurm_job_array(tmp_path, slurm):
    sweep = Sweep.create(tmp_path / "arr", CS_REDUCED, {"material[*].friction": [0.3, 0.5, 0.7]}, domain=DOMAIN)
    good = sweep.case_file(1).read_text()
    sweep.case_file(1).write_text(good + "no_such_field: 1\n")
    backend = dem.sweep.SlurmBackend(max_running=1)  # one at a time, so the array stays queued a while
    handle = sweep.submit(backend)
    assert handle.job.isdigit()
    assert sweep.submit(backend) is None  # every task is queued or running in that job already
    assert backend.active(sweep) == [0, 1, 2] or sweep.status()[0].state != "pending"
    progress = sweep.wait(handle, poll=0.3)
    assert [t.state for t in progress.tasks] == ["done", "failed", "done"], [str(t) for t in progress.tasks]
    failed = sweep.failed()
    assert [t.index for t in failed] == [1] and failed[0].exit_code == 3
    # The log names the case file and the line (the server quotes none of a file's content: docs/SECURITY.md).
    lines = good.count("\n") + 1
    assert f"0001.case.txtpb:{lines}:" in failed[0].log_tail(), failed[0].log_tail()
    assert (sweep.directory / "logs" / f"slurm-{handle.job}_1.out").is_file()
    assert backend.active(sweep) == []

    sweep.case_file(1).write_text(good)  # mended, and resubmitted alone
    progress = sweep.run(backend, tasks=[1], poll=0.3, on_progress=None)
    assert progress.finished
    assert [t.attempt for t in sweep.status()] == [1, 2, 1]
    jobs = [s["job"] for s in sweep.submissions()]
    assert len(jobs) == 2 and jobs[0] == handle.job and sweep.submissions()[1]["tasks"] == [1]
    assert sweep.results().final["stress"].min() >= 900e3
