"""Where a sweep's tasks run. Every backend runs the sweep's copy of
dem_sweep_task.sh with the sweep directory and a task index, so a task
runs, reports and resumes the same way everywhere (docs/SWEEPS.md):

    LocalBackend(workers=2)         processes on this machine, `workers` at a time
    SlurmBackend(options=[...])     one Slurm job array (sbatch), the scheduler's queue
    DaskBackend(client)             one task each on a Dask distributed cluster

A backend's submit(sweep, tasks) returns a handle: done(), cancel(), and
interrupted() (what Ctrl-C in Sweep.wait does). active(sweep) names the
tasks an earlier submission still holds (queued or running), which a new
submission leaves alone.
"""

import os
import signal
import subprocess
import threading
import uuid

from ..errors import DemError


def _command(sweep, index):
    return ["bash", str(sweep.task_script), str(sweep.directory), str(index)]


class LocalBackend:
    """The tasks as processes of this one, at most `workers` at a time
    (default: the cores over the sweep's threads per task)."""

    kind = "local"

    def __init__(self, workers=None):
        self.workers = workers

    def active(self, sweep):
        return []  # a task left running by an earlier process holds its lock: the sweep sees it running

    def submit(self, sweep, tasks):
        workers = self.workers or max(1, (os.cpu_count() or 1) // max(1, int(sweep.conf.get("threads", 1)) or 1))
        return LocalHandle(sweep, tasks, workers)


class LocalHandle:
    def __init__(self, sweep, tasks, workers):
        self.job = None
        self.exit_codes = {}
        self._sweep = sweep
        self._queue = list(tasks)
        self._running = {}
        self._lock = threading.Lock()
        self._cancelled = False
        self._error = None
        self._threads = [threading.Thread(target=self._work, name=f"dem-sweep-{n}", daemon=True)
                         for n in range(min(workers, len(tasks)))]
        for thread in self._threads:
            thread.start()

    def _work(self):
        try:
            while True:
                with self._lock:
                    if self._cancelled or not self._queue:
                        return
                    index = self._queue.pop(0)
                    log = open(self._sweep.directory / "logs" / f"local-{index:04d}.out", "ab")
                    # Started under the lock, so cancel() sees every process there is; in a session of
                    # its own, so Ctrl-C reaches this process alone, which then stops them in order.
                    process = subprocess.Popen(_command(self._sweep, index), stdout=log, stderr=subprocess.STDOUT,
                                               stdin=subprocess.DEVNULL, start_new_session=True)
                    self._running[index] = process
                code = process.wait()
                log.close()
                with self._lock:
                    del self._running[index]
                    self.exit_codes[index] = code
        except Exception as error:  # reported by check()
            self._error = error

    def done(self):
        return not any(thread.is_alive() for thread in self._threads)

    def check(self):
        if self._error is not None:
            raise DemError(f"the local backend failed: {self._error}") from self._error

    def cancel(self, timeout=60):
        """Starts no more tasks and stops those running with SIGTERM: each
        server stops after its chunk of cycles with a final snapshot (the
        task is then "stopped", and runs again, or resumes, next time)."""
        with self._lock:
            self._cancelled = True
            for process in self._running.values():
                if process.poll() is None:
                    process.send_signal(signal.SIGTERM)
        for thread in self._threads:
            thread.join(timeout)

    def interrupted(self):
        self.cancel()


class SlurmBackend:
    """One Slurm job array per submission: sbatch --array=<the tasks> of the
    sweep's task script, with its name, a log per task in logs/, as many
    CPUs per task as the sweep's threads, and your `options` (partition,
    time limit, account, ...). `max_running` caps the tasks running at once
    (--array=...%N). Slurm's commands come from PATH, and SLURM_CONF when set."""

    kind = "slurm"

    def __init__(self, options=(), max_running=None):
        self.options = list(options)
        self.max_running = max_running

    def submit(self, sweep, tasks):
        array = array_ranges(tasks) + (f"%{self.max_running}" if self.max_running else "")
        command = ["sbatch", "--parsable", f"--array={array}", f"--job-name={sweep.name}",
                   f"--output={sweep.directory / 'logs' / 'slurm-%A_%a.out'}",
                   f"--cpus-per-task={max(1, int(sweep.conf.get('threads', 1)) or 1)}",
                   f"--chdir={sweep.directory}", *self.options, str(sweep.task_script), str(sweep.directory)]
        result = _slurm(command)
        job = result.stdout.strip().split(";")[0]
        if not job.isdigit():
            raise DemError(f"sbatch printed {result.stdout!r}, not a job id")
        return SlurmHandle(job)

    def active(self, sweep):
        """The tasks of this sweep's earlier job arrays that Slurm still has queued or running."""
        jobs = {s["job"] for s in sweep.submissions() if s.get("backend") == self.kind and s.get("job")}
        held = set()
        for job in jobs:
            for line in SlurmHandle(job).tasks():
                held.add(int(line))
        return sorted(held)


class SlurmHandle:
    def __init__(self, job):
        self.job = str(job)

    def tasks(self):
        """The array task ids of this job still in Slurm's queue (pending or running)."""
        result = _slurm(["squeue", "-h", "-r", "-j", self.job, "-o", "%K"], unknown_ok=True)
        return [line.strip() for line in result.stdout.splitlines() if line.strip().isdigit()]

    def done(self):
        result = _slurm(["squeue", "-h", "-j", self.job, "-o", "%i"], unknown_ok=True)
        return not result.stdout.strip()

    def cancel(self):
        _slurm(["scancel", self.job])

    def interrupted(self):
        print(f"the Slurm job array {self.job} goes on; scancel {self.job} cancels it")


def _slurm(command, unknown_ok=False):
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=60)
    except FileNotFoundError:
        raise DemError(f"{command[0]} is not installed (Slurm's client commands, Debian's slurm-client)") from None
    if result.returncode != 0:
        # A job that ended and left the controller's memory (MinJobAge) is unknown: it is no longer queued.
        if unknown_ok and "Invalid job id" in result.stderr:
            return subprocess.CompletedProcess(command, 0, "", "")
        raise DemError(f"{' '.join(command)} exited {result.returncode}: {result.stderr.strip()}")
    return result


def array_ranges(indices):
    """Slurm's --array list: [0, 1, 2, 5, 7, 8] -> "0-2,5,7-8"."""
    indices = sorted(set(indices))
    parts = []
    start = previous = None
    for index in indices + [None]:
        if start is not None and index == previous + 1:
            previous = index
            continue
        if start is not None:
            parts.append(str(start) if start == previous else f"{start}-{previous}")
        start = previous = index
    return ",".join(parts)


class DaskBackend:
    """One Dask task per sweep task on a distributed cluster: a
    distributed.Client, or the scheduler's address. A worker runs the task
    script as a process (subprocess.call is all that travels), so workers
    need the sweep directory at the same path (a shared file system), bash
    and dem_server - not this package. Each worker thread runs one task at
    a time: give workers as many threads as tasks should run on them.
    `resources` (e.g. {"cores": 4}) is passed to Client.submit for clusters
    whose workers declare theirs."""

    kind = "dask"

    def __init__(self, client, resources=None):
        if isinstance(client, str):
            import distributed  # Debian's python3-distributed
            client = distributed.Client(client)
        self.client = client
        self.resources = resources

    def active(self, sweep):
        return []  # futures live with the client that made them

    def submit(self, sweep, tasks):
        token = uuid.uuid4().hex[:8]
        futures = {}
        for index in tasks:
            log = sweep.directory / "logs" / f"dask-{index:04d}.out"
            # The script's output goes to the sweep's log, redirected by a shell on the worker.
            command = ["bash", "-c", 'exec bash "$0" "$1" "$2" >>"$3" 2>&1', *_command(sweep, index)[1:], str(log)]
            futures[index] = self.client.submit(subprocess.call, command, key=f"{sweep.name}-{index:04d}-{token}",
                                                pure=False, resources=self.resources)
        return DaskHandle(self.client, futures)


class DaskHandle:
    def __init__(self, client, futures):
        self.job = None
        self.client = client
        self.futures = futures

    def done(self):
        return all(future.done() for future in self.futures.values())

    @property
    def exit_codes(self):
        return {index: future.result() for index, future in self.futures.items() if future.status == "finished"}

    def cancel(self):
        """Cancels the tasks not started; those running go on (Dask cannot
        stop a running task)."""
        self.client.cancel(list(self.futures.values()))

    def interrupted(self):
        self.cancel()

