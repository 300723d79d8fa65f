"""ros2/dem_interfaces/msg matches the service's IDL: the committed files are
what ros2/generate_interfaces.py makes of idl/dem/*.idl, and field by field
and constant by constant they carry what idlc itself made of the IDL (the C
headers the service is built with) - a reading of the IDL independent of
the generator's.

Environment: DEM_SOURCE_DIR (the repository), DEM_IDLC_HEADERS (idlc's
output for idl/dem: telemetry.h, command.h).
"""

import os
import pathlib
import re
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ["DEM_SOURCE_DIR"])
HEADERS = pathlib.Path(os.environ["DEM_IDLC_HEADERS"])
MSG_DIR = SOURCE / "ros2" / "dem_interfaces" / "msg"

C_TYPES = {"char *": "string", "uint8_t": "uint8", "int32_t": "int32", "uint32_t": "uint32", "int64_t": "int64",
           "uint64_t": "uint64", "double": "float64", "bool": "bool"}


def c_structs():
    """Struct name -> [(member, .msg type)] from idlc's headers."""
    structs = {}
    for header in ("telemetry.h", "command.h"):
        text = (HEADERS / header).read_text()
        for match in re.finditer(r"typedef struct dem_interfaces_msg_dds__(\w+)_\n\{\n(.*?)\n\}", text, re.S):
            members = []
            for line in match.group(2).splitlines():
                declaration = re.fullmatch(r"\s*(.+?)\s*(\w+);", line)
                c_type, name = declaration.groups()
                members.append((name, msg_type(c_type)))
            structs[match.group(1)] = members
    return structs


def msg_type(c_type):
    if c_type in C_TYPES:
        return C_TYPES[c_type]
    if c_type == "dds_sequence_octet":
        return "uint8[]"
    sequence = re.fullmatch(r"dds_sequence_(\w+)", c_type)
    if sequence:
        element = sequence.group(1)
        # dds_sequence_int32 names its element int32_t; dds_sequence_double, double
        return (C_TYPES.get(element + "_t") or C_TYPES.get(element) or msg_type("struct " + element)) + "[]"
    nested = re.fullmatch(r"struct (\w+?)_msg_dds__(\w+)_", c_type)
    assert nested, c_type
    package, name = nested.groups()
    return name if package == "dem_interfaces" else f"{package}/{name}"


def c_constants():
    """Struct name -> [(NAME, value)] from idlc's #defines."""
    constants = {}
    for header in ("telemetry.h", "command.h"):
        for name, constant, value in re.findall(r"#define dem_interfaces_msg_(\w+)_Constants_(\w+) (-?\d+)",
                                                (HEADERS / header).read_text()):
            constants.setdefault(name, []).append((constant, value))
    return constants


def msg_contents(path):
    """([(name, type)], [(NAME, value)]) of a .msg file, comments dropped."""
    fields, constants = [], []
    for line in path.read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        type_, rest = line.split(None, 1)
        if "=" in rest:
            name, value = (part.strip() for part in rest.split("=", 1))
            constants.append((name, value))
        else:
            fields.append((rest.strip(), type_))
    return fields, constants


def test_the_committed_files_are_what_the_generator_makes_of_the_idl():
    result = subprocess.run([sys.executable, str(SOURCE / "ros2" / "generate_interfaces.py"), str(SOURCE / "idl" / "dem"),
                             "--msg-dir", str(MSG_DIR), "--check"], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr


def test_every_idl_struct_has_a_message_file_and_no_more():
    assert {p.stem for p in MSG_DIR.glob("*.msg")} == set(c_structs())


@pytest.mark.parametrize("name", sorted(c_structs()))
def test_fields_match_idlcs_structs_field_by_field(name):
    fields, constants = msg_contents(MSG_DIR / f"{name}.msg")
    assert fields == c_structs()[name]
    assert constants == c_constants().get(name, [])


def test_the_check_finds_a_changed_file(tmp_path):
    # The check can fail: a copy with one field's type changed.
    for path in MSG_DIR.glob("*.msg"):
        (tmp_path / path.name).write_text(path.read_text())
    status = tmp_path / "Status.msg"
    status.write_text(status.read_text().replace("uint64 cycle", "uint32 cycle"))
    result = subprocess.run([sys.executable, str(SOURCE / "ros2" / "generate_interfaces.py"), str(SOURCE / "idl" / "dem"),
                             "--msg-dir", str(tmp_path), "--check"], capture_output=True, text=True)
    assert result.returncode == 1
    assert "Status.msg: differs from what idl/dem/telemetry.idl generates" in result.stdout


# --- the interface's type hashes and version (docs/DDS.md, "Evolving the wire") --------------

GENERATOR = SOURCE / "ros2" / "generate_interfaces.py"
sys.path.insert(0, str(SOURCE / "idl"))
sys.path.insert(0, str(SOURCE / "ros2"))
sys.path.insert(0, str(SOURCE / "tests" / "ros2"))


def generate(*arguments, idl_dir=SOURCE / "idl" / "dem"):
    return subprocess.run([sys.executable, str(GENERATOR), str(idl_dir), *map(str, arguments)], capture_output=True,
                          text=True)


def test_type_hashes_are_ros2s():
    # REP-2016's hash of builtin_interfaces/msg/Time as ROS 2 publishes it,
    # from the declaration in idl/dem/ros_types.idl.
    import generate_interfaces
    import idl_types
    import type_hash

    types = generate_interfaces.wire_types(idl_types.read_idl(sorted((SOURCE / "idl" / "dem").glob("*.idl"))))
    assert type_hash.rihs01("builtin_interfaces/Time", types) == \
        "RIHS01_b106235e25a4c5ed35098aa0a61a3ee9c9b18d197f398b0e4206cea9acf9c197"


def test_the_msg_files_hash_as_the_idl_does():
    # A ROS 2 node computes its hashes from the .msg files (rosidl); the
    # service from the IDL. Read each on its own: the same hash per message.
    import generate_interfaces
    import idl_types
    import msg_to_dds_idl
    import type_hash

    from_idl = generate_interfaces.wire_state(idl_types.read_idl(sorted((SOURCE / "idl" / "dem").glob("*.idl"))))
    packages = [SOURCE / "ros2" / "dem_interfaces", SOURCE / "tests" / "ros2" / "ros_msgs" / "builtin_interfaces",
                SOURCE / "tests" / "ros2" / "ros_msgs" / "geometry_msgs"]
    from_msg = msg_to_dds_idl.type_hashes(packages)
    for name, value in from_idl["hashes"].items():
        assert from_msg[f"dem_interfaces/{name}"] == value, name
    assert from_msg["builtin_interfaces/Time"] == type_hash.rihs01(
        "builtin_interfaces/Time", {"builtin_interfaces/Time": [("sec", "int32", False), ("nanosec", "uint32", False)]})


def test_the_recorded_history_holds_this_wire_as_this_version():
    result = generate("--check")
    assert result.returncode == 0, result.stdout + result.stderr


def test_a_field_appended_to_telemetry_needs_a_version_and_is_judged(tmp_path):
    # What appending to ContactStats means: the check fails until the
    # version is bumped and recorded; then a 0.3.0 reader of ContactStats
    # still reads the new samples (the fields are at its end), while Reply,
    # which embeds ContactStats before other fields, no longer meets 0.3.0.
    idl = tmp_path / "idl"
    idl.mkdir()
    for path in (SOURCE / "idl" / "dem").glob("*.idl"):
        (idl / path.name).write_text(path.read_text())
    telemetry = idl / "telemetry.idl"
    text = telemetry.read_text()
    end = "double inertial_number;     // deformation rate x diameter / sqrt(mean_stress / density)\n"
    assert end in text
    telemetry.write_text(text.replace(end, end + "        double coordination_without_rattlers;\n"))
    history = tmp_path / "history.json"
    history.write_text((SOURCE / "idl" / "interface_history.json").read_text())
    package = tmp_path / "package.xml"
    package.write_text((SOURCE / "ros2" / "dem_interfaces" / "package.xml").read_text())

    unchanged_version = generate("--check", "--history", history, "--package-xml", package, idl_dir=idl)
    assert unchanged_version.returncode == 1
    assert "the wire changed (ContactStats, Reply) while the interface version stayed 0.3.0: bump <version>" in \
        unchanged_version.stdout

    package.write_text(package.read_text().replace("<version>0.3.0</version>", "<version>0.4.0</version>"))
    unrecorded = generate("--check", "--history", history, "--package-xml", package, idl_dir=idl)
    assert unrecorded.returncode == 1 and "dem_interfaces 0.4.0 (package.xml) is not in the interface history" in \
        unrecorded.stdout
    assert generate("--record", "--history", history, "--package-xml", package, idl_dir=idl).returncode == 0
    assert generate("--check", "--history", history, "--package-xml", package, idl_dir=idl).returncode == 0

    header = tmp_path / "interface_version.h"
    assert generate("--cpp-interface", header, "--history", history, "--package-xml", package,
                    idl_dir=idl).returncode == 0
    forms = [line for line in header.read_text().splitlines() if '"0.1.0' in line or '0.3.0"' in line]
    stats = [line for line in forms if "ContactStats_" in line and '0.3.0"' in line]
    assert stats and stats[0].endswith('"lacks coordination_without_rattlers", true, false},'), forms
    reply = [line for line in forms if "Reply_" in line and '0.3.0"' in line]
    assert reply and reply[0].endswith('"lacks stats.coordination_without_rattlers", false, false},'), forms


def test_dds_md_lists_every_messages_fields(tmp_path):
    result = generate("--docs", SOURCE / "docs" / "DDS.md", "--check")
    assert result.returncode == 0, result.stdout + result.stderr
    # The check can fail: a copy with one field left out of its table.
    copy = tmp_path / "DDS.md"
    copy.write_text((SOURCE / "docs" / "DDS.md").read_text().replace("| `force` | `bool` |", "| `forced` | `bool` |", 1))
    result = generate("--docs", copy, "--check")
    assert result.returncode == 1 and "its field lists differ from the IDL's" in result.stdout
