#!/usr/bin/env python3
"""ROS 2 message files to the DDS IDL that ROS 2 derives from them - as
rosidl_adapter (.msg to .idl) and rosidl_generator_dds_idl (.idl to
<package>/msg/dds_/<Type>_.idl) write it - so a test can build its types
from the message files alone, with no help from the project's own IDL:

    msg_to_dds_idl.py OUT_DIR PACKAGE_DIR...   (each PACKAGE_DIR/msg/*.msg)

Per rosidl: module <package>::msg::dds_, struct <Type>_ with members
<name>_, constants in module <Type>_Constants as <NAME>_, uint8/byte as
octet, int32 as long, uint32 as unsigned long, int64 as long long, uint64
as unsigned long long, float64 as double, bool as boolean, T[] as
sequence<T>, a nested type as <package>::msg::dds_::<Type>_. No
annotations: the extensibility is the IDL compiler's default.
"""

import pathlib
import re
import sys

IDL_TYPES = {
    "bool": "boolean", "byte": "octet", "char": "uint8", "uint8": "octet", "int8": "octet",
    "int16": "short", "uint16": "unsigned short", "int32": "long", "uint32": "unsigned long",
    "int64": "long long", "uint64": "unsigned long long", "float32": "float", "float64": "double",
    "string": "string",
}
FIELD = re.compile(r"^(?P<type>[\w/]+)(?P<array>\[\])?\s+(?P<name>[a-z][a-z0-9_]*)\s*(?:#.*)?$")
CONSTANT = re.compile(r"^(?P<type>\w+)\s+(?P<name>[A-Z][A-Z0-9_]*)\s*=\s*(?P<value>[^#]+?)\s*(?:#.*)?$")


def parse(path, package):
    fields, constants = [], []
    for number, raw in enumerate(path.read_text().splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        constant = CONSTANT.match(line)
        field = FIELD.match(line)
        if constant:
            constants.append((constant["type"], constant["name"], constant["value"]))
        elif field:
            type_ = field["type"]
            if type_ not in IDL_TYPES and "/" not in type_:
                type_ = f"{package}/{type_}"
            fields.append((type_, bool(field["array"]), field["name"]))
        else:
            sys.exit(f"{path}:{number}: not a field or constant: {raw!r}")
    return fields, constants


def idl_type(type_):
    if type_ in IDL_TYPES:
        return IDL_TYPES[type_]
    package, name = type_.split("/")
    return f"{package}::msg::dds_::{name}_"


def convert(path, package, out):
    name = path.stem
    fields, constants = parse(path, package)
    includes = sorted({f"{t.split('/')[0]}/msg/dds_/{t.split('/')[1]}_.idl"
                       for t, _, _ in fields if t not in IDL_TYPES})
    guard = f"__{package}__msg__{name}__idl__"
    lines = [f"// generated as rosidl_generator_dds_idl does, from {package}/msg/{path.name}",
             f"#ifndef {guard}", f"#define {guard}", ""]
    lines += [f'#include "{include}"' for include in includes]
    lines += ["", f"module {package} {{", "module msg {", "module dds_ {", ""]
    if constants:
        lines.append(f"module {name}_Constants {{")
        for type_, constant, value in constants:
            lines.append(f"const {IDL_TYPES[type_]} {constant}_ = {value};")
        lines += ["};", ""]
    lines.append(f"struct {name}_ {{")
    for type_, array, member in fields:
        lines.append(f"sequence<{idl_type(type_)}> {member}_;" if array else f"{idl_type(type_)} {member}_;")
    lines += ["};", "", "};  // module dds_", "};  // module msg", f"}};  // module {package}", "", f"#endif  // {guard}", ""]
    target = out / package / "msg" / "dds_" / f"{name}_.idl"
    target.parent.mkdir(parents=True, exist_ok=True)
    text = "\n".join(lines)
    if not target.exists() or target.read_text() != text:
        target.write_text(text)


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    out = pathlib.Path(argv[0])
    for package_dir in map(pathlib.Path, argv[1:]):
        package = package_dir.name
        messages = sorted((package_dir / "msg").glob("*.msg"))
        if not messages:
            sys.exit(f"{package_dir}/msg: no message files")
        for path in messages:
            convert(path, package, out)


if __name__ == "__main__":
    main(sys.argv[1:])
