"""The dem IDL (idl/dem/*.idl) as Python values: the modules, constants and
structs of the small IDL subset the service uses - @final structs of
primitive, string, sequence and nested members, and `<Type>_Constants`
modules - read by a small tokenizer, so every generator starts from the one
definition: the ROS 2 message files and schemas (ros2/generate_interfaces.py,
docs/ROS2.md) and the C++ messages with their conversions to idlc's C types
(protocol/generate_messages.py). tests/ros2/test_interfaces.py holds this
reading against idlc's own, field by field.

    types = read_idl([pathlib.Path("idl/dem/command.idl"), ...])
    types["dem_interfaces/PlateForces"].fields  # [Field("server", "string", ...), ...]
"""

import dataclasses
import pathlib
import re

# IDL primitive -> ROS 2 .msg type. octet is uint8 on the wire (rosidl maps
# both .msg byte and uint8 to an IDL octet).
PRIMITIVES = {
    "boolean": "bool",
    "octet": "uint8",
    "uint8": "uint8",
    "int8": "int8",
    "int16": "int16",
    "uint16": "uint16",
    "int32": "int32",
    "uint32": "uint32",
    "int64": "int64",
    "uint64": "uint64",
    "float": "float32",
    "double": "float64",
    "string": "string",
}


@dataclasses.dataclass
class Field:
    name: str
    type: str          # a .msg type: "float64", "string", "geometry_msgs/Vector3", "WallForce"
    sequence: bool     # an unbounded array: "type[]"
    comment: str = ""
    idl_type: str = ""  # as the IDL writes it: "double", "octet", "WallForce_", "geometry_msgs::msg::dds_::Vector3_"
    key: bool = False   # @key: DDS keeps a history per value of the type's keys (a .msg has no keys; ROS 2 ignores it)

    def msg_line(self):
        text = f"{self.type}{'[]' if self.sequence else ''} {self.name}"
        return f"{text}  # {self.comment}" if self.comment else text


@dataclasses.dataclass
class Constant:
    name: str
    type: str
    value: str
    comment: str = ""


@dataclasses.dataclass
class Message:
    package: str       # "dem_interfaces"
    name: str          # "PlateForces"
    fields: list
    constants: list
    comment: str = ""  # the comment block above the struct
    source: str = ""   # the IDL file's name

    @property
    def full_name(self):
        return f"{self.package}/{self.name}"


class IdlError(ValueError):
    """The IDL does not read as the subset this module knows; the message names file and line."""


_TOKEN = re.compile(r"""
    (?P<comment>//[^\n]*)
  | (?P<preprocessor>\#[^\n]*)
  | (?P<space>\s+)
  | (?P<annotation>@\w+)
  | (?P<scoped>(?:::)?\w+(?:::\w+)+)
  | (?P<word>\w+)
  | (?P<number>-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)
  | (?P<string>"[^"]*")
  | (?P<symbol>[{};<>=,])
""", re.VERBOSE)


def _tokens(path):
    text = path.read_text()
    line = 1
    position = 0
    pending_comment = []
    while position < len(text):
        match = _TOKEN.match(text, position)
        if not match:
            raise IdlError(f"{path}:{line}: cannot read {text[position:position + 20]!r}")
        kind = match.lastgroup
        value = match.group()
        if kind == "comment":
            pending_comment.append((line, value[2:].strip()))
        elif kind not in ("space", "preprocessor"):
            yield kind, value, line, pending_comment
            pending_comment = []
        line += value.count("\n")
        position = match.end()


def _msg_type(idl_type, path, line):
    """A member's IDL type as a .msg type."""
    if idl_type in PRIMITIVES:
        return PRIMITIVES[idl_type]
    parts = idl_type.strip(":").split("::")
    # <package>::msg::dds_::<Type>_ is ROS 2's DDS name of <package>/msg/<Type>.
    if len(parts) == 4 and parts[1] == "msg" and parts[2] == "dds_" and parts[3].endswith("_"):
        return f"{parts[0]}/{parts[3][:-1]}"
    if len(parts) == 1 and parts[0].endswith("_"):
        return parts[0][:-1]  # a type of the same module
    raise IdlError(f"{path}:{line}: the type {idl_type} has no ROS 2 message form")


def _trailing_comments(path):
    """line -> the comment at the end of that line (a member's meaning)."""
    comments = {}
    for number, text in enumerate(path.read_text().splitlines(), start=1):
        code, _, comment = text.partition("//")
        if comment and code.strip():
            comments[number] = comment.strip()
    return comments


def read_idl(paths):
    """Every struct under <package>::msg::dds_ of the files, by "<package>/<Name>"."""
    messages = {}
    constants = {}  # (package, Name) -> [Constant]
    for path in paths:
        path = pathlib.Path(path)
        trailing = _trailing_comments(path)
        tokens = list(_tokens(path))
        scope = []
        i = 0
        struct = None
        next_key = False  # the member that follows is a @key
        block_comment = ""

        def expect(value):
            nonlocal i
            kind, got, line, _ = tokens[i]
            if got != value:
                raise IdlError(f"{path}:{line}: expected {value!r}, found {got!r}")
            i += 1

        while i < len(tokens):
            kind, value, line, comments = tokens[i]
            if value == "module":
                scope.append(tokens[i + 1][1])
                i += 2
                expect("{")
            elif value == "struct":
                name = tokens[i + 1][1]
                block_comment = " ".join(text for _, text in comments) or block_comment
                if len(scope) != 3 or scope[1] != "msg" or scope[2] != "dds_" or not name.endswith("_"):
                    raise IdlError(f"{path}:{line}: struct {name} is not in <package>::msg::dds_ as <Name>_")
                struct = Message(scope[0], name[:-1], [], [], block_comment, path.name)
                block_comment = ""
                i += 2
                expect("{")
            elif value == "const":
                # const <type> <NAME> = <value>; inside <package>::msg::<Name>_Constants
                _, idl_type, _, _ = tokens[i + 1]
                _, name, _, _ = tokens[i + 2]
                i += 3
                expect("=")
                _, literal, _, _ = tokens[i]
                i += 1
                expect(";")
                owner = scope[-1]
                if len(scope) != 3 or scope[1] != "msg" or not owner.endswith("_Constants"):
                    raise IdlError(f"{path}:{line}: constant {name} is not in <package>::msg::<Name>_Constants")
                constants.setdefault((scope[0], owner[: -len("_Constants")]), []).append(
                    Constant(name, _msg_type(idl_type, path, line), literal, trailing.get(line, "")))
            elif value == "}":
                i += 1
                expect(";")
                if struct is not None:
                    messages[struct.full_name] = struct
                    struct = None
                else:
                    scope.pop()
            elif kind == "annotation" and struct is not None:
                # A member's annotation: only @key (the DDS instance; the wire and the ROS 2 message are the same).
                if value != "@key":
                    raise IdlError(f"{path}:{line}: {value}: of member annotations only @key is known")
                next_key = True
                i += 1
            elif kind == "annotation":
                if value != "@final":
                    raise IdlError(f"{path}:{line}: {value}: only @final types have a ROS 2 message form")
                block_comment = " ".join(text for _, text in comments)
                i += 1
            elif struct is not None:
                # <type> <name>; or sequence<<type>> <name>;
                if value == "sequence":
                    i += 1
                    expect("<")
                    _, idl_type, _, _ = tokens[i]
                    i += 1
                    expect(">")
                    sequence = True
                else:
                    idl_type = value
                    sequence = False
                    i += 1
                _, name, name_line, _ = tokens[i]
                i += 1
                expect(";")
                struct.fields.append(Field(name, _msg_type(idl_type, path, line), sequence, trailing.get(name_line, ""),
                                           idl_type, next_key))
                next_key = False
            else:
                raise IdlError(f"{path}:{line}: unexpected {value!r}")
    for (package, name), values in constants.items():
        key = f"{package}/{name}"
        if key not in messages:
            raise IdlError(f"constants {name}_Constants belong to no struct {name}_")
        messages[key].constants = values
    return messages


def dependencies(message, messages):
    """The messages `message` uses, directly or not, each once, in first use order."""
    seen = []

    def visit(current):
        for field in current.fields:
            if field.type in PRIMITIVES.values():
                continue
            full = field.type if "/" in field.type else f"{current.package}/{field.type}"
            if full in seen:
                continue
            if full not in messages:
                raise IdlError(f"{current.full_name}.{field.name}: no definition of {full}")
            seen.append(full)
            visit(messages[full])

    visit(message)
    return [messages[name] for name in seen]


def msg_text(message, comments=True):
    """The .msg file's text: constants first, then the fields, as rosidl reads them."""
    lines = []
    if comments and message.comment:
        lines += [f"# {message.comment}", ""]
    for constant in message.constants:
        line = f"{constant.type} {constant.name}={constant.value}"
        lines.append(f"{line}  # {constant.comment}" if comments and constant.comment else line)
    for field in message.fields:
        lines.append(field.msg_line() if comments else field.msg_line().split("  #")[0])
    return "\n".join(lines) + "\n"


def ros2msg_schema(message, messages):
    """The message's definition with those it uses, in the "ros2msg" form of
    MCAP files and Foxglove channels (the way rosbag2 stores them): each
    dependency after a line of 80 '=' and "MSG: <package>/<Name>"."""
    parts = [msg_text(message, comments=False)]
    for dependency in dependencies(message, messages):
        parts.append("=" * 80 + "\n" + f"MSG: {dependency.full_name}\n" + msg_text(dependency, comments=False))
    return "".join(parts)


def write_if_changed(path, text):
    """Writes a generated file only when its text changes, so what depends on it is not rebuilt."""
    path = pathlib.Path(path)
    if not path.exists() or path.read_text() != text:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
