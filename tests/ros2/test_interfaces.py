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
