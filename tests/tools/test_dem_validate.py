"""dem_validate as a user runs it: a verdict at the end with the exit code
to match, --out required and said so in the help (it used to write into
./validation unasked and exit 0 whatever it measured).

Environment: DEM_VALIDATE (the program).
"""

import os
import subprocess

DEM_VALIDATE = os.environ["DEM_VALIDATE"]


def run(*arguments):
    return subprocess.run([DEM_VALIDATE, *arguments], capture_output=True, text=True, timeout=300)


def test_a_check_ends_with_its_verdict_and_exit_code(tmp_path):
    result = run("restitution", "--out", str(tmp_path))
    assert result.returncode == 0, result.stderr
    lines = result.stdout.strip().splitlines()
    assert lines[-1] == "restitution: PASS (6 checks)"
    assert all(line.startswith("  pass  ") for line in lines[-7:-1]), lines[-7:]
    assert (tmp_path / "restitution.csv").is_file()


def test_out_is_required_and_the_help_says_so(tmp_path):
    result = subprocess.run([DEM_VALIDATE, "restitution"], capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert result.returncode == 2
    assert "--out is required" in result.stderr
    assert not list(tmp_path.iterdir()), "nothing is written where it was not asked for"
    help_text = run("--help").stdout
    assert "--out DIR" in help_text and "verdict" in help_text
    assert "--out" in run("restitution", "--help").stdout
