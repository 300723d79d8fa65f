"""What identifies a message's wire form, and how two forms meet:

- its ROS 2 type hash (REP-2016, "RIHS01_<sha256>"): the hash of its type
  description - its fields' names and types and those of every message it
  uses - as rosidl computes it from the .msg files and as ROS 2 (Iron and
  later) puts it in each endpoint's USER_DATA ("typehash=RIHS01_...;");
- its layout: the primitives it puts on the wire in order, nested messages
  inlined (plain CDR of final types, as ROS 2 and the service send them),
  a sequence one item holding its element's layout. A reader whose layout
  is a prefix of the writer's reads the writer's samples (the fields
  appended after it are skipped); a longer one cannot (the sample ends
  early).

Types are given neutrally, so the service's IDL (ros2/generate_interfaces.py)
and a package's .msg files (tests/ros2/msg_to_dds_idl.py) are hashed by the
same code: {"pkg/Name": [(field name, type, is_sequence)]}, a type being a
.msg primitive ("float64", "uint8", "string", ...) or "pkg/Name".
"""

import hashlib
import json

# type_description_interfaces/msg/FieldType: the primitives' ids; a
# sequence adds 144 (unbounded), a nested type is 1.
FIELD_TYPE_IDS = {
    "int8": 2, "uint8": 3, "int16": 4, "uint16": 5, "int32": 6, "uint32": 7, "int64": 8, "uint64": 9,
    "float32": 10, "float64": 11, "char": 13, "bool": 15, "byte": 16, "string": 17,
}
NESTED_TYPE = 1
UNBOUNDED_SEQUENCE = 144


def _ros_name(type_name):
    """"pkg/Name" -> "pkg/msg/Name", the name type descriptions use."""
    package, name = type_name.split("/")
    return f"{package}/msg/{name}"


def _description(type_name, types):
    fields = []
    for name, type_, sequence in types[type_name]:
        nested = type_ not in FIELD_TYPE_IDS
        type_id = NESTED_TYPE if nested else FIELD_TYPE_IDS[type_]
        fields.append({"name": name, "type": {
            "type_id": type_id + (UNBOUNDED_SEQUENCE if sequence else 0), "capacity": 0, "string_capacity": 0,
            "nested_type_name": _ros_name(type_) if nested else ""}})
    return {"type_name": _ros_name(type_name), "fields": fields}


def _used(type_name, types, seen=None):
    """Every type `type_name` uses, directly or not."""
    seen = set() if seen is None else seen
    for _, type_, _ in types[type_name]:
        if type_ not in FIELD_TYPE_IDS and type_ not in seen:
            if type_ not in types:
                raise KeyError(f"{type_name} uses {type_}, which is not given")
            seen.add(type_)
            _used(type_, types, seen)
    return seen


def rihs01(type_name, types):
    """REP-2016's hash: sha256 of the type description (the type, then the
    types it uses sorted by name; default values left out) as compact JSON."""
    hashed = {"type_description": _description(type_name, types),
              "referenced_type_descriptions": [_description(t, types)
                                               for t in sorted(_used(type_name, types), key=_ros_name)]}
    text = json.dumps(hashed, separators=(", ", ": "))
    return "RIHS01_" + hashlib.sha256(text.encode("utf-8")).hexdigest()


def layout(type_name, types):
    """The wire's primitives in order, each a string: "float64",
    "seq<uint32>", "seq<string,int32,float64,...>" for a sequence of a
    message. Field names do not travel."""
    atoms = []
    for _, type_, sequence in types[type_name]:
        inner = [type_] if type_ in FIELD_TYPE_IDS else layout(type_, types)
        atoms += [f"seq<{','.join(inner)}>"] if sequence else inner
    return atoms


def paths(type_name, types, prefix=""):
    """(field path, wire primitive) in wire order: "query.particle", "walls[]"."""
    result = []
    for name, type_, sequence in types[type_name]:
        path = prefix + name
        if sequence:
            inner = [type_] if type_ in FIELD_TYPE_IDS else layout(type_, types)
            result.append((path + "[]", f"seq<{','.join(inner)}>"))
        elif type_ in FIELD_TYPE_IDS:
            result.append((path, type_))
        else:
            result += paths(type_, types, path + ".")
    return result


def reads(reader_layout, writer_layout):
    """Whether a reader of `reader_layout` reads samples written with `writer_layout`."""
    return list(writer_layout[: len(reader_layout)]) == list(reader_layout)
