"""Parameter sweeps (docs/SWEEPS.md): cases built from a base case and
parameter ranges, run by the one-shot dem_server as tasks of a backend -
local processes, a Slurm job array or a Dask distributed cluster -
followed while they run, continued after an interruption, and gathered
into numpy arrays and one summary table.

    import dem.sweep
    sweep = dem.sweep.Sweep.create("out/sweeps/cs_friction", "cases/miyata/cs.case.txtpb",
                                   {"material[*].friction": [0.2, 0.35, 0.51, 0.7]}, domain=7)
    sweep.run(dem.sweep.LocalBackend(workers=2))     # or SlurmBackend(), DaskBackend(client)
    results = sweep.results()                         # numpy arrays; writes summary.csv
    for i in range(len(results)):
        settlement, stress = results.curve(i)

Every task's server is named <sweep name>_NNNN on the sweep's domain, so
`demctl --domain 7 monitor --sweep cs_friction` follows them all live.
Running the same script again (or Sweep.open(dir).run(backend)) runs only
what is not done: tasks that never ran, failed or were stopped, which
resume from their newest checkpoint when the sweep keeps checkpoints.
`python3 -m dem.sweep` does the same from a shell (status, run, results).
"""

from .backends import DaskBackend, LocalBackend, SlurmBackend, array_ranges
from .directory import STATES, Progress, Sweep, TaskStatus
from .parameters import Parameter, build_case, combinations, set_field
from .results import FINAL_FIELDS, Results

create = Sweep.create
open_sweep = Sweep.open

__all__ = ["DaskBackend", "FINAL_FIELDS", "LocalBackend", "Parameter", "Progress", "Results", "STATES",
           "SlurmBackend", "Sweep", "TaskStatus", "array_ranges", "build_case", "combinations", "create",
           "open_sweep", "set_field"]
