"""Why ``import dem`` failed, said where it fails: the package is built for
one interpreter - Debian's python3, with Debian's python3-protobuf and
python3-numpy, and an extension module compiled for its version - and a
python3 found first on PATH (pyenv, a virtual environment, conda) sees
none of them ("No module named 'google'"). This module imports nothing
that could be missing."""

import os
import sys

from . import _build_info

# The Debian package each module the client imports comes from.
PACKAGES = {"google": "python3-protobuf", "numpy": "python3-numpy"}


def dependency_hint(missing):
    """The message of the ImportError raised for ModuleNotFoundError `missing`."""
    name = (missing.name or "").split(".")[0]
    built_for = getattr(_build_info, "PYTHON", "/usr/bin/python3")
    running = sys.executable or "this interpreter"
    what = (f"dem's extension module for {built_for}" if name == "dem" else
            f"Debian's {PACKAGES[name]}" if name in PACKAGES else f"the module {missing.name}")
    same = built_for and os.path.exists(built_for) and os.path.realpath(running) == os.path.realpath(built_for)
    if same:
        return (f"import dem: {missing} - {what} is missing for {running}; install it "
                f"(scripts/install_deps.sh, or apt-get install python3-protobuf python3-numpy)")
    return (f"import dem: {missing} - the package is built for {built_for} (Python "
            f"{getattr(_build_info, 'PYTHON_VERSION', '3')}, with Debian's python3-protobuf and python3-numpy), "
            f"and this is {running} (Python {sys.version_info.major}.{sys.version_info.minor}), which does not "
            f"see {what}: run it with {built_for} (docs/PYTHON.md)")
