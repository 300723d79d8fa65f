#!/usr/bin/env python3
"""The ROS 2 interface package's message files, and the schemas the
recorder and the bridge send, generated from the service's IDL
(idl/dem/*.idl), which stays the one definition of every field
(docs/ROS2.md):

    generate_interfaces.py IDL_DIR --msg-dir ros2/dem_interfaces/msg   # write the .msg files
    generate_interfaces.py IDL_DIR --msg-dir ros2/dem_interfaces/msg --check   # exit 1 if they differ
    generate_interfaces.py IDL_DIR --cpp-schemas FILE.h    # ros2msg schemas as C++ string constants
    generate_interfaces.py IDL_DIR --python-schemas FILE.py  # ... and as a Python dict
"""

import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "idl"))
import idl_types  # noqa: E402

PACKAGE = "dem_interfaces"
HEADER = ("# Generated from idl/dem/{source} by ros2/generate_interfaces.py:\n"
          "# edit the IDL, not this file.\n")


def msg_files(messages):
    """File name -> text of every message of the package."""
    return {f"{m.name}.msg": HEADER.format(source=m.source) + idl_types.msg_text(m)
            for m in messages.values() if m.package == PACKAGE}


def schemas(messages):
    """"dem_interfaces/msg/<Name>" -> its ros2msg schema, for every message of the package."""
    return {f"{m.package}/msg/{m.name}": idl_types.ros2msg_schema(m, messages)
            for m in messages.values() if m.package == PACKAGE}


def cpp_header(messages):
    lines = ["// Generated from idl/dem/*.idl by ros2/generate_interfaces.py: the ros2msg",
             "// schema of each dem_interfaces message (its definition, then those it uses),",
             "// as MCAP files and Foxglove channels carry them.",
             "#pragma once", "", "#include <string_view>", "", "namespace dem::interfaces {", ""]
    for name, text in schemas(messages).items():
        identifier = "k" + name.rsplit("/", 1)[1] + "Schema"
        lines.append(f"inline constexpr std::string_view {identifier} = R\"schema({text})schema\";")
    lines += ["", "}  // namespace dem::interfaces", ""]
    return "\n".join(lines)


def python_module(messages):
    lines = ['"""Generated from idl/dem/*.idl by ros2/generate_interfaces.py: the ros2msg',
             "schema of each dem_interfaces message, by its ROS 2 name.\"\"\"", "", "SCHEMAS = {"]
    for name, text in schemas(messages).items():
        lines.append(f"    {name!r}: {text!r},")
    lines += ["}", ""]
    return "\n".join(lines)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("idl_dir", type=pathlib.Path)
    parser.add_argument("--msg-dir", type=pathlib.Path)
    parser.add_argument("--check", action="store_true", help="compare the message files instead of writing them")
    parser.add_argument("--cpp-schemas", type=pathlib.Path)
    parser.add_argument("--python-schemas", type=pathlib.Path)
    args = parser.parse_args(argv)
    idl_files = sorted(args.idl_dir.glob("*.idl"))
    if not idl_files:
        parser.error(f"no .idl files in {args.idl_dir}")
    try:
        messages = idl_types.read_idl(idl_files)
    except idl_types.IdlError as error:
        sys.exit(f"generate_interfaces.py: {error}")

    status = 0
    if args.msg_dir:
        wanted = msg_files(messages)
        if args.check:
            present = {p.name for p in args.msg_dir.glob("*.msg")}
            for name, text in sorted(wanted.items()):
                path = args.msg_dir / name
                if not path.exists():
                    print(f"{path}: missing (run ros2/generate_interfaces.py)")
                    status = 1
                elif path.read_text() != text:
                    print(f"{path}: differs from what idl/dem/{messages[PACKAGE + '/' + name[:-4]].source} generates")
                    status = 1
            for name in sorted(present - wanted.keys()):
                print(f"{args.msg_dir / name}: no IDL struct generates it")
                status = 1
        else:
            for name, text in wanted.items():
                idl_types.write_if_changed(args.msg_dir / name, text)
            for stale in set(p.name for p in args.msg_dir.glob("*.msg")) - wanted.keys():
                (args.msg_dir / stale).unlink()
    if args.cpp_schemas:
        idl_types.write_if_changed(args.cpp_schemas, cpp_header(messages))
    if args.python_schemas:
        idl_types.write_if_changed(args.python_schemas, python_module(messages))
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
