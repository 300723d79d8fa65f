"""clients/python/examples/friction_sweep.py as a user runs it, on the
reduced CS case and three frictions: every task done, the figures and the
curves written, the plate at 900 kPa at the end of every curve; run again,
it finds nothing left to do.
    example_friction_sweep.py EXAMPLE OUT_DIR DOMAIN"""

import csv
import pathlib
import shutil
import subprocess
import sys

import dem

example, out, domain = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
shutil.rmtree(out, ignore_errors=True)
command = [sys.executable, example, "--case", str(dem.paths.cases_dir() / "miyata" / "cs_reduced.case.txtpb"),
           "--frictions", "0.3", "0.5", "0.7", "--out", str(out), "--domain", domain, "--name", "example_cs"]
run = subprocess.run(command, capture_output=True, text=True, timeout=150)
print(run.stdout, run.stderr)
assert run.returncode == 0, f"the example exited {run.returncode}"
for name in ("stress_settlement_family.png", "final_measures.png", "curves.csv", "sweep/summary.csv"):
    assert (out / name).stat().st_size > 0, name
with open(out / "curves.csv", newline="") as table:
    rows = list(csv.DictReader(table))
for friction in ("0.3", "0.5", "0.7"):
    curve = [r for r in rows if r["friction"] == friction]
    assert len(curve) > 100 and float(curve[-1]["stress"]) >= 900e3, (friction, len(curve))
again = subprocess.run(command, capture_output=True, text=True, timeout=60)
assert again.returncode == 0 and "3 done" in again.stdout, again.stdout + again.stderr
assert "running" not in again.stdout, again.stdout
print("ok: the example swept three frictions; run again, it found nothing left to do")
