#!/usr/bin/env python3
"""The service's messages in C++, generated from the IDL (idl/dem/*.idl),
which stays the one definition of every field:

    generate_messages.py IDL_DIR --header DIR/dem/protocol/message_types.h --conversions DIR/c_conversions.h

--header: every IDL struct as a plain C++ struct in dem::protocol (public),
each <Name>_Constants module that a table below names as an enum class with
to_string and a checked conversion from its wire value, and Fields<T>: the
members of each struct in IDL order, by name, member pointer and the IDL's
comment, for code that goes over every field (tests, bindings).
--conversions: to_c and from_c between each C++ struct and the C struct
idlc generates from the same IDL (private to protocol/src/type_support.cpp).

The C++ side follows the IDL member for member; the few places where it
reads better otherwise are the tables below, each checked against the IDL
(a name that is not there stops the generator). Adding a field is one edit
to the IDL.
"""

import argparse
import pathlib
import re
import sys
import textwrap

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "idl"))
import idl_types  # noqa: E402

# C++ names of IDL structs ("<package>/<Name>") other than <Name>.
TYPE_NAMES = {
    "builtin_interfaces/Time": "Stamp",
    "dem_interfaces/LoadCase": "LoadCaseArgs",
    "dem_interfaces/WallVelocity": "WallVelocityArgs",
    "dem_interfaces/WallServo": "WallServoArgs",
    "dem_interfaces/Cycle": "CycleArgs",
    "dem_interfaces/RunUntil": "RunUntilArgs",
    "dem_interfaces/ContactQuery": "ContactQueryArgs",
    "dem_interfaces/Snapshot": "SnapshotArgs",
    "dem_interfaces/Parameter": "ParameterArgs",
    "dem_interfaces/Programme": "ProgrammeArgs",
    "dem_interfaces/ProgrammeSteps": "ProgrammeStepsArgs",
}

# <Name>_Constants modules as C++ enums: the struct they belong to -> the
# enum's name and the constant a value read off the wire that is none of
# them becomes (None: kept as it is; to_string names it "unknown").
ENUMS = {
    "dem_interfaces/Status": ("ServerState", "ERROR"),
    "dem_interfaces/Command": ("CommandKind", None),
    "dem_interfaces/Reply": ("ReplyStatus", None),
}

# Members typed with one of those enums in C++ ("<package>/<Name>.<member>").
# Command.kind and Reply.kind stay raw, so an unknown kind can be answered.
ENUM_MEMBERS = {
    "dem_interfaces/Status.state": "ServerState",
    "dem_interfaces/Reply.status": "ReplyStatus",
}

# A boolean member that says whether another is set: the two are one
# std::optional in C++ (member -> its flag).
OPTIONALS = {
    "dem_interfaces/RunUntil.stress": "stress_set",
    "dem_interfaces/RunUntil.settlement": "settlement_set",
    "dem_interfaces/RunUntil.kinetic_energy": "kinetic_energy_set",
    "dem_interfaces/ContactQuery.min_normal_force": "force_set",
    "dem_interfaces/ContactQuery.particle": "particle_set",
}

# String members that carry the name of an enum member of the same struct:
# written from it, not kept in C++ (member -> the enum member).
NAMES_OF = {
    "dem_interfaces/Status.state_name": "state",
}

# C++ initial values other than zero, false or empty (-1: no such id).
DEFAULTS = {
    "dem_interfaces/WallForce.id": "-1",
    "dem_interfaces/WallVelocity.wall_id": "-1",
    "dem_interfaces/WallServo.wall_id": "-1",
    "dem_interfaces/RunUntil.wall_id": "-1",
    "dem_interfaces/ContactQuery.wall_id": "-1",
    "dem_interfaces/ContactEntry.first": "-1",
    "dem_interfaces/ContactEntry.second_particle": "-1",
    "dem_interfaces/ContactEntry.second_wall": "-1",
    "dem_interfaces/Reply.last": "true",  # a reply in one piece
}

# Member functions of a C++ struct.
METHODS = {
    "dem_interfaces/Reply": ["bool ok() const { return status == ReplyStatus::kOk; }"],
}

# .msg primitive (idl_types' reading) -> C++ type.
CPP_PRIMITIVES = {
    "bool": "bool", "uint8": "std::uint8_t", "int8": "std::int8_t", "int16": "std::int16_t",
    "uint16": "std::uint16_t", "int32": "std::int32_t", "uint32": "std::uint32_t", "int64": "std::int64_t",
    "uint64": "std::uint64_t", "float32": "float", "float64": "double", "string": "std::string",
}


class Model:
    """The IDL's structs in dependency order, with the tables applied."""

    def __init__(self, messages):
        self.messages = messages
        self._check_tables()
        self.order = []  # each struct after those it uses
        for message in messages.values():
            self._place(message)

    def _place(self, message):
        if message in self.order:
            return
        for field in message.fields:
            struct = self.struct_of(message, field)
            if struct is not None:
                self._place(struct)
        self.order.append(message)

    def _check_tables(self):
        members = {f"{m.full_name}.{f.name}" for m in self.messages.values() for f in m.fields}
        for table, keys in (("TYPE_NAMES", TYPE_NAMES), ("ENUMS", ENUMS), ("METHODS", METHODS)):
            for key in keys:
                if key not in self.messages:
                    raise idl_types.IdlError(f"{table} names {key}, no IDL struct")
        for table, keys in (("ENUM_MEMBERS", ENUM_MEMBERS), ("OPTIONALS", OPTIONALS), ("NAMES_OF", NAMES_OF),
                            ("DEFAULTS", DEFAULTS)):
            for key in keys:
                if key not in members:
                    raise idl_types.IdlError(f"{table} names {key}, no IDL member")
        for key, flag in OPTIONALS.items():
            if f"{key.rsplit('.', 1)[0]}.{flag}" not in members:
                raise idl_types.IdlError(f"OPTIONALS: {key}'s flag {flag} is no IDL member")
        for full_name, (enum, fallback) in ENUMS.items():
            names = [c.name for c in self.messages[full_name].constants]
            if fallback is not None and fallback not in names:
                raise idl_types.IdlError(f"ENUMS: {enum} has no constant {fallback}")

    def struct_of(self, message, field):
        if field.type in CPP_PRIMITIVES:
            return None
        full_name = field.type if "/" in field.type else f"{message.package}/{field.type}"
        if full_name not in self.messages:
            raise idl_types.IdlError(f"{message.full_name}.{field.name}: no definition of {full_name}")
        return self.messages[full_name]

    @staticmethod
    def cpp_name(message):
        return TYPE_NAMES.get(message.full_name, message.name)

    @staticmethod
    def c_name(message):
        return f"{message.package}_msg_dds__{message.name}_"

    def members(self, message):
        """(field, role) of the C++ struct: role is "plain", "optional" or "enum"; flags and names are left out."""
        flags = {OPTIONALS[k] for k in OPTIONALS if k.rsplit(".", 1)[0] == message.full_name}
        for field in message.fields:
            key = f"{message.full_name}.{field.name}"
            if field.name in flags or key in NAMES_OF:
                continue
            yield field, "optional" if key in OPTIONALS else "enum" if key in ENUM_MEMBERS else "plain"

    def cpp_type(self, message, field):
        key = f"{message.full_name}.{field.name}"
        if key in ENUM_MEMBERS:
            return ENUM_MEMBERS[key]
        if field.sequence and field.idl_type == "octet":
            return "std::string"  # bytes
        struct = self.struct_of(message, field)
        element = self.cpp_name(struct) if struct else CPP_PRIMITIVES[field.type]
        if field.sequence:
            return f"std::vector<{element}>"
        if key in OPTIONALS:
            return f"std::optional<{element}>"
        return element


def enum_member(constant):
    """LOAD_CASE -> kLoadCase"""
    return "k" + "".join(part.capitalize() for part in constant.split("_"))


def snake(name):
    """CommandKind -> command_kind"""
    return re.sub(r"(?<!^)([A-Z])", r"_\1", name).lower()


def comment_lines(text):
    return [f"// {line}" for line in textwrap.wrap(text, 100)]


def header(model, idl_names):
    out = [f"// Generated from {idl_names} by protocol/generate_messages.py: edit the",
           "// IDL, not this file. The service's messages as plain C++ values (see",
           "// dem/protocol/messages.h).",
           "#pragma once", "",
           "#include <cstdint>", "#include <optional>", "#include <string>", "#include <string_view>",
           "#include <tuple>", "#include <vector>", "", "namespace dem::protocol {", ""]
    for full_name, (enum, fallback) in ENUMS.items():
        message = model.messages[full_name]
        underlying = CPP_PRIMITIVES[message.constants[0].type]
        out.append(f"// {message.name}_Constants in idl/dem/{message.source}.")
        out.append(f"enum class {enum} : {underlying} {{")
        for constant in message.constants:
            note = f"  // {constant.comment}" if constant.comment else ""
            out.append(f"  {enum_member(constant.name)} = {constant.value},{note}")
        out += ["};", ""]
        unknown = fallback.lower() if fallback else "unknown"
        out.append(f"// \"{message.constants[0].name.lower()}\", ...; \"{unknown}\" for a value that is none of them.")
        out.append(f"// String literals: the views are NUL-terminated.")
        out.append(f"constexpr std::string_view to_string({enum} value) {{")
        out.append("  switch (value) {")
        for constant in message.constants:
            out.append(f"    case {enum}::{enum_member(constant.name)}: return \"{constant.name.lower()}\";")
        out += ["  }", f"  return \"{unknown}\";", "}", ""]
        out.append(f"// The {enum} of a wire value, or nothing.")
        out.append(f"constexpr std::optional<{enum}> {snake(enum)}({underlying} value) {{")
        out.append("  switch (value) {")
        for constant in message.constants:
            out.append(f"    case {constant.value}: return {enum}::{enum_member(constant.name)};")
        out += ["  }", "  return std::nullopt;", "}", ""]

    for message in model.order:
        name = model.cpp_name(message)
        out += comment_lines(message.comment)
        out.append(f"// idl/dem/{message.source}: {message.package}::msg::dds_::{message.name}_")
        out.append(f"struct {name} {{")
        for field, role in model.members(message):
            key = f"{message.full_name}.{field.name}"
            scalar = role == "enum" or (role == "plain" and not field.sequence and field.type in CPP_PRIMITIVES
                                        and field.type != "string")
            initial = f" = {DEFAULTS[key]}" if key in DEFAULTS else "{}" if scalar else ""
            note = f"  // {field.comment}" if field.comment else ""
            out.append(f"  {model.cpp_type(message, field)} {field.name}{initial};{note}")
        for method in METHODS.get(message.full_name, []):
            out += ["", f"  {method}"]
        out.append(f"  friend bool operator==(const {name}&, const {name}&) = default;")
        out += ["};", ""]

    out += ["// One member of a message: its IDL name, where it is, and the IDL's comment.",
            "template <class Message, class Member>",
            "struct Field {",
            "  std::string_view name;",
            "  Member Message::*member;",
            "  std::string_view comment;",
            "};",
            "template <class Message, class Member>",
            "Field(std::string_view, Member Message::*, std::string_view) -> Field<Message, Member>;", "",
            "// Fields<T>::list: a tuple of every member of T, in IDL order (an optional",
            "// stands for its flag and value).",
            "template <class T>", "struct Fields;", ""]
    for message in model.order:
        name = model.cpp_name(message)
        entries = [f"      Field{{\"{f.name}\", &{name}::{f.name}, {cpp_string(f.comment)}}}"
                   for f, _ in model.members(message)]
        out.append("template <>")
        out.append(f"struct Fields<{name}> {{")
        out.append("  static constexpr auto list = std::make_tuple(")
        out.append(",\n".join(entries) + ");")
        out += ["};", ""]
    out += ["// The structs above: what travels as a DDS sample.",
            "template <class T>", "concept Message = requires { Fields<T>::list; };", "",
            "// Every message, each after those it uses.",
            "using Messages = std::tuple<" + ", ".join(model.cpp_name(m) for m in model.order) + ">;", "",
            "}  // namespace dem::protocol", ""]
    return "\n".join(out)


def cpp_string(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def conversions(model, idl_files):
    includes = [f"#include \"dem/{path.stem}.h\"" for path in idl_files]
    out = ["// Generated from idl/dem/*.idl by protocol/generate_messages.py: edit the",
           "// IDL, not this file. Each message between its C++ struct and the C struct",
           "// idlc generates: to_c borrows the C++ value's memory (see c_values.h),",
           "// from_c copies. Included by protocol/src/type_support.cpp only.",
           "#pragma once", ""] + includes + ["", "#include \"c_values.h\"", "#include \"dem/protocol/messages.h\""]
    out += ["", "namespace dem::protocol {", "",
            "// The C struct and topic descriptor of each message.",
            "template <class T>", "struct CType;"]
    for message in model.order:
        out += ["template <>",
                f"struct CType<{model.cpp_name(message)}> {{",
                f"  using type = {model.c_name(message)};",
                f"  static constexpr const dds_topic_descriptor_t* descriptor = &{model.c_name(message)}_desc;",
                "};"]
    out.append("")
    out.append("// Enum values as they travel; a value that is no member when read becomes the fallback, if any.")
    for full_name, (enum, fallback) in ENUMS.items():
        underlying = CPP_PRIMITIVES[model.messages[full_name].constants[0].type]
        out.append(f"inline void to_c({enum} value, {underlying}& c, Borrowed&) {{ c = static_cast<{underlying}>(value); }}")
        if fallback:
            read = f"{snake(enum)}(c).value_or({enum}::{enum_member(fallback)})"
        else:
            read = f"static_cast<{enum}>(c)"
        out.append(f"inline void from_c({underlying} c, {enum}& value) {{ value = {read}; }}")
    out.append("")
    for message in model.order:
        out.append(f"inline void to_c(const {model.cpp_name(message)}& m, {model.c_name(message)}& c, Borrowed& borrowed);")
        out.append(f"inline void from_c(const {model.c_name(message)}& c, {model.cpp_name(message)}& m);")
    out.append("")
    for message in model.order:
        names_of = {k.rsplit(".", 1)[1]: v for k, v in NAMES_OF.items() if k.rsplit(".", 1)[0] == message.full_name}
        flag_of = {k.rsplit(".", 1)[1]: v for k, v in OPTIONALS.items() if k.rsplit(".", 1)[0] == message.full_name}
        out.append(f"inline void to_c(const {model.cpp_name(message)}& m, {model.c_name(message)}& c, "
                   "[[maybe_unused]] Borrowed& borrowed) {")
        for field, role in model.members(message):
            if role == "optional":
                out.append(f"  to_c(m.{field.name}, c.{flag_of[field.name]}, c.{field.name}, borrowed);")
            else:
                out.append(f"  to_c(m.{field.name}, c.{field.name}, borrowed);")
        for name, enum_field in names_of.items():
            out.append(f"  c.{name} = const_cast<char*>(to_string(m.{enum_field}).data());")
        out.append("}")
        out.append(f"inline void from_c(const {model.c_name(message)}& c, {model.cpp_name(message)}& m) {{")
        for field, role in model.members(message):
            if role == "optional":
                out.append(f"  from_c(c.{flag_of[field.name]}, c.{field.name}, m.{field.name});")
            else:
                out.append(f"  from_c(c.{field.name}, m.{field.name});")
        out.append("}")
    out += ["", "}  // namespace dem::protocol", "",
            "// X(T) for every message T: the explicit instantiations of what is generic over them.",
            "#define DEM_PROTOCOL_FOR_EACH_MESSAGE(X) \\"]
    out.append(" \\\n".join(f"  X({model.cpp_name(m)})" for m in model.order))
    out.append("")
    return "\n".join(out)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("idl_dir", type=pathlib.Path)
    parser.add_argument("--header", type=pathlib.Path, help="the public C++ message types")
    parser.add_argument("--conversions", type=pathlib.Path, help="to_c and from_c for type_support.cpp")
    args = parser.parse_args(argv)
    idl_files = sorted(args.idl_dir.glob("*.idl"))
    if not idl_files:
        parser.error(f"no .idl files in {args.idl_dir}")
    try:
        model = Model(idl_types.read_idl(idl_files))
    except idl_types.IdlError as error:
        sys.exit(f"generate_messages.py: {error}")
    if args.header:
        idl_types.write_if_changed(args.header, header(model, "idl/dem/*.idl"))
    if args.conversions:
        idl_types.write_if_changed(args.conversions, conversions(model, idl_files))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
