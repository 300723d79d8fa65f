"""Where the programs and files of this build are, and the loopback-only DDS
environment every process here uses (docs/DDS.md, "Loopback only").

Environment variables override the build's locations: DEM_SERVER_PROGRAM,
DEMCTL_PROGRAM, DEM_RUN_PROGRAM, DEM_VALIDATE_PROGRAM, DEM_SOURCE_DIR,
DEM_SWEEP_TASK_SCRIPT.
"""

import os
import pathlib

from . import _build_info


def _program(variable, built):
    path = os.environ.get(variable) or built
    if not path:
        raise FileNotFoundError(f"this build has no such program; set {variable} to one")
    return pathlib.Path(path)


def server_program():
    """dem_server of this build (or $DEM_SERVER_PROGRAM)."""
    return _program("DEM_SERVER_PROGRAM", _build_info.SERVER_PROGRAM)


def demctl_program():
    """demctl of this build (or $DEMCTL_PROGRAM)."""
    return _program("DEMCTL_PROGRAM", _build_info.DEMCTL_PROGRAM)


def run_program():
    """dem_run of this build (or $DEM_RUN_PROGRAM)."""
    return _program("DEM_RUN_PROGRAM", _build_info.RUN_PROGRAM)


def validate_program():
    """dem_validate of this build (or $DEM_VALIDATE_PROGRAM)."""
    return _program("DEM_VALIDATE_PROGRAM", getattr(_build_info, "VALIDATE_PROGRAM", ""))


def source_dir():
    """The repository this build came from (or $DEM_SOURCE_DIR)."""
    return pathlib.Path(os.environ.get("DEM_SOURCE_DIR") or _build_info.SOURCE_DIR)


def cases_dir():
    return source_dir() / "cases"


def sweep_task_script():
    """scripts/slurm/dem_sweep_task.sh, which runs one task of a sweep (or
    $DEM_SWEEP_TASK_SCRIPT); installed in <prefix>/share/dem/scripts/slurm."""
    return pathlib.Path(os.environ.get("DEM_SWEEP_TASK_SCRIPT") or source_dir() / "scripts" / "slurm" /
                        "dem_sweep_task.sh")


def loopback_uri():
    """CYCLONEDDS_URI for the repository's loopback-only configuration."""
    return "file://" + _build_info.LOOPBACK_CONFIG


def use_loopback():
    """Makes this process and the processes it starts use the loopback-only
    configuration, unless CYCLONEDDS_URI already names one. The C++ client
    falls back to the same file; setting the variable also covers dem_server
    and demctl started from here."""
    os.environ.setdefault("CYCLONEDDS_URI", loopback_uri())
    return os.environ["CYCLONEDDS_URI"]
