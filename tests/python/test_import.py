"""The package imports under Debian's python3, with the extension module and
the protobuf classes this build made."""

import os
import pathlib
import sys

import numpy as np


def test_runs_under_debians_python():
    assert sys.executable == "/usr/bin/python3"


def test_the_package_and_its_extension_come_from_this_build():
    import dem
    import dem._client

    package = pathlib.Path(dem.__file__).parent
    assert pathlib.Path(dem._client.__file__).parent == package
    assert package.parent == pathlib.Path(os.environ["PYTHONPATH"].split(os.pathsep)[0])
    for module in ("case_pb2.py", "snapshot_pb2.py", "_build_info.py"):
        assert (package / module).is_file(), module
    assert dem.paths.server_program().is_file()
    assert dem.paths.loopback_uri().endswith("config/cyclonedds-loopback.xml")


def test_the_public_names():
    import dem

    for name in dem.__all__:
        assert hasattr(dem, name), name
    assert issubclass(dem.ServerError, dem.DemError)
    assert issubclass(dem.ReplyTimeout, TimeoutError)
    import dem.plots

    for name in dem.plots.__all__:
        assert callable(getattr(dem.plots, name)), name


def test_the_contact_dtype():
    import dem

    dtype = dem.CONTACT_DTYPE
    assert dtype.names == ("first", "second_particle", "second_wall", "point", "normal", "overlap", "normal_force",
                           "shear_force", "tangential_force", "normal_damping", "shear_damping", "sliding",
                           "formed_cycle", "force")
    for vector in ("point", "normal", "tangential_force", "force"):
        assert dtype[vector].shape == (3,), vector
    assert dtype["first"] == np.int32 and dtype["normal_force"] == np.float64 and dtype["sliding"] == np.bool_
    assert dtype["formed_cycle"] == np.uint64


def test_the_case_classes_are_generated_from_the_schema():
    import dem

    source = (dem.paths.source_dir() / "idl/dem/case.proto").read_text()
    fields = dem.cases.Case.DESCRIPTOR.fields_by_name
    for name in ("name", "material", "contact_model", "particles", "wall", "stage", "output", "dimension"):
        assert name in fields and f" {name} = " in source
    assert dem.cases.Case.DESCRIPTOR.full_name == "dem.proto.Case"
    from dem import snapshot_pb2

    assert snapshot_pb2.Snapshot.DESCRIPTOR.full_name == "dem.proto.Snapshot"


def _import_dem_with(interpreter_arguments):
    """`import dem` in another interpreter: its exit status and stderr."""
    import subprocess

    result = subprocess.run([*interpreter_arguments, "-c", "import dem"], capture_output=True, text=True,
                            env={**os.environ, "PYTHONNOUSERSITE": "1"})
    return result.returncode, result.stderr


def test_an_interpreter_without_debians_packages_gets_a_hint():
    # python3 -S: Debian's interpreter without its site packages (no protobuf,
    # no numpy), as a python3 of pyenv or a virtual environment sees them.
    code, stderr = _import_dem_with([sys.executable, "-S"])
    assert code != 0
    last = stderr.strip().splitlines()[-1]
    print(last)
    assert last.startswith("ImportError: import dem: No module named 'google'")
    assert "Debian's python3-protobuf is missing for /usr/bin/python3" in last


def test_another_python3_first_on_path_is_told_which_to_use():
    import shutil

    other = shutil.which("python3", path=os.environ.get("DEM_TEST_PATH", os.environ.get("PATH", "")))
    if other is None or os.path.realpath(other) == os.path.realpath(sys.executable):
        import pytest

        pytest.skip("no python3 other than Debian's on PATH")
    code, stderr = _import_dem_with([other])
    assert code != 0
    last = stderr.strip().splitlines()[-1]
    print(last)
    assert "ImportError: import dem: No module named" in last
    assert "the package is built for /usr/bin/python3" in last and "run it with /usr/bin/python3" in last
