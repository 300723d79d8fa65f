#!/usr/bin/env python3
"""The ROS 2 interface package's message files, and the schemas the
recorder and the bridge send, generated from the service's IDL
(idl/dem/*.idl), which stays the one definition of every field
(docs/ROS2.md); and the interface's version and history (docs/DDS.md,
"Evolving the wire"):

    generate_interfaces.py IDL_DIR --msg-dir ros2/dem_interfaces/msg   # write the .msg files
    generate_interfaces.py IDL_DIR --msg-dir ros2/dem_interfaces/msg --check   # exit 1 if they differ,
                                          # or the wire changed and the version did not
    generate_interfaces.py IDL_DIR --record   # the wire of package.xml's version into the history
    generate_interfaces.py IDL_DIR --cpp-schemas FILE.h    # ros2msg schemas as C++ string constants
    generate_interfaces.py IDL_DIR --python-schemas FILE.py  # ... and as a Python dict
    generate_interfaces.py IDL_DIR --cpp-interface FILE.h   # the version, type hashes and known older forms
    generate_interfaces.py IDL_DIR --docs docs/DDS.md        # write its field lists from the IDL
    generate_interfaces.py IDL_DIR --docs docs/DDS.md --check   # exit 1 if they differ
"""

import argparse
import json
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "idl"))
import idl_types  # noqa: E402
import type_hash  # noqa: E402

PACKAGE = "dem_interfaces"
PACKAGE_XML = ROOT / "ros2" / PACKAGE / "package.xml"
HISTORY = ROOT / "idl" / "interface_history.json"
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


# --- the interface's version and history -----------------------------------

def interface_version(package_xml=PACKAGE_XML):
    match = re.search(r"<version>([^<]+)</version>", pathlib.Path(package_xml).read_text())
    if not match:
        raise idl_types.IdlError(f"{package_xml}: no <version>")
    return match.group(1)


def wire_types(messages):
    """The messages as type_hash takes them: {"pkg/Name": [(field, type, is_sequence)]}."""
    def full(message, field):
        if field.type in type_hash.FIELD_TYPE_IDS or "/" in field.type:
            return field.type
        return f"{message.package}/{field.type}"
    return {m.full_name: [(f.name, full(m, f), f.sequence) for f in m.fields] for m in messages.values()}


def wire_state(messages):
    """{"hashes": {Name: hash}, "forms": {hash: {"message", "fields"}}} of the package's messages."""
    types = wire_types(messages)
    hashes, forms = {}, {}
    for name in sorted(types):
        package, short = name.split("/")
        if package != PACKAGE:
            continue
        hashes[short] = type_hash.rihs01(name, types)
        forms[hashes[short]] = {"message": short, "fields": [list(p) for p in type_hash.paths(name, types)]}
    return {"hashes": hashes, "forms": forms}


def read_history(path=HISTORY):
    path = pathlib.Path(path)
    return json.loads(path.read_text()) if path.exists() else {"states": [], "forms": {}}


def write_history(history, path=HISTORY):
    idl_types.write_if_changed(path, json.dumps(history, indent=1, sort_keys=False) + "\n")


def history_problems(state, version, history):
    """Why the history does not hold this wire as this version (none: it does)."""
    recorded = [s for s in history["states"] if s["version"] == version]
    if not recorded:
        return [f"dem_interfaces {version} (package.xml) is not in the interface history: record it "
                f"(ros2/generate_interfaces.py idl/dem --record)"]
    if recorded[-1]["hashes"] != state["hashes"]:
        changed = sorted(n for n in state["hashes"] if recorded[-1]["hashes"].get(n) != state["hashes"][n])
        return [f"the wire changed ({', '.join(changed)}) while the interface version stayed {version}: bump "
                f"<version> in ros2/dem_interfaces/package.xml and record it (ros2/generate_interfaces.py "
                f"idl/dem --record); docs/DDS.md, \"Evolving the wire\""]
    return []


def record(state, version, history):
    """Adds this wire as `version`; a version recorded with another wire is refused."""
    recorded = [s for s in history["states"] if s["version"] == version]
    if recorded and recorded[-1]["hashes"] != state["hashes"]:
        raise idl_types.IdlError(f"dem_interfaces {version} is recorded with another wire: bump the version")
    if not recorded:
        history["states"].append({"version": version, "hashes": state["hashes"]})
    history["forms"].update(state["forms"])
    return history


def _since(states, hash_value, name):
    """"0.1.0 (b169459 to aca0bd5)": the recorded states that had this form of `name`."""
    having = [s for s in states if s["hashes"].get(name) == hash_value]
    versions = []
    for s in having:
        if s["version"] not in versions:
            versions.append(s["version"])
    labels = []
    for version in versions:
        commits = [s["commit"] for s in having if s["version"] == version and "commit" in s]
        if not commits:
            labels.append(version)
        elif len(commits) == 1:
            labels.append(f"{version} as of {commits[0]}")
        else:
            labels.append(f"{version} as of {commits[0]} to {commits[-1]}")
    return ", ".join(labels)


def _difference(older, current, prefix=""):
    """What a form lacks, has and changes against the current one, by field
    (a nested message's fields named when only some of them differ)."""
    def groups(fields):
        result = {}
        for path, atom in fields:
            head, _, rest = path.partition(".")
            result.setdefault(head, []).append((rest, atom))
        return result
    old, new = groups(older), groups(current)
    lacks = [prefix + name for name in new if name not in old]
    extra = [prefix + name for name in old if name not in new]
    changes = []
    for name in (n for n in new if n in old and old[n] != new[n]):
        leaf = len(new[name]) == 1 and not new[name][0][0]
        if leaf or len(old[name]) == 1 and not old[name][0][0]:
            changes.append(prefix + name)
        else:
            nested = _difference(old[name], new[name], prefix + name + ".")
            lacks += nested[0]
            extra += nested[1]
            changes += nested[2]
    if prefix:
        return lacks, extra, changes
    parts = [f"lacks {', '.join(lacks)}"] if lacks else []
    parts += [f"has {', '.join(extra)}, no longer on the wire"] if extra else []
    parts += [f"differs in {', '.join(changes)}"] if changes else []
    return "; ".join(parts) or "its fields are in another order"


def cpp_interface(messages, version, history):
    """The C++ header protocol/ builds with: the version, each message's
    type hash, and every older form the history knows with whether it still
    meets the current one (a reader of the older form reads the current
    writes; a reader of the current form reads the older writes)."""
    state = wire_state(messages)
    lines = ["// Generated from idl/dem/*.idl, ros2/dem_interfaces/package.xml and",
             "// idl/interface_history.json by ros2/generate_interfaces.py (docs/DDS.md,",
             "// \"Evolving the wire\"): edit those, not this file.",
             "#pragma once", "", "#include <array>", "#include <string_view>", "",
             "namespace dem::protocol {", "",
             f"inline constexpr std::string_view kInterfaceVersion = \"{version}\";", "",
             "// Each message's DDS type name and its ROS 2 type hash (REP-2016), as a",
             "// ROS 2 node computes it from the package's .msg files.",
             "struct TypeHash {", "  std::string_view type_name;", "  std::string_view hash;", "};",
             f"inline constexpr std::array<TypeHash, {len(state['hashes'])}> kTypeHashes{{{{"]
    for name, value in state["hashes"].items():
        lines.append(f"    {{\"{PACKAGE}::msg::dds_::{name}_\", \"{value}\"}},")
    lines += ["}};", "",
              "// A form of a message that an older (or other) build of the package had:",
              "// which versions, what it lacks or has against the current one, and",
              "// whether the two still read each other (plain CDR: a reader reads a",
              "// writer whose fields begin with all of its own).",
              "struct OlderForm {", "  std::string_view type_name;", "  std::string_view hash;",
              "  std::string_view versions;  // \"0.1.0 as of b169459 to aca0bd5\"",
              "  std::string_view difference;  // \"lacks force, query.particle_set\"",
              "  bool reads_current;  // its reader reads what the current form writes",
              "  bool read_by_current;  // the current form's reader reads what it writes", "};"]
    older = []
    for hash_value, form in history["forms"].items():
        name = form["message"]
        if name not in state["hashes"] or hash_value == state["hashes"][name]:
            continue
        current = state["forms"][state["hashes"][name]]["fields"]
        older_layout = [atom for _, atom in form["fields"]]
        current_layout = [atom for _, atom in current]
        older.append((name, hash_value, _since(history["states"], hash_value, name),
                      _difference(form["fields"], current), type_hash.reads(older_layout, current_layout),
                      type_hash.reads(current_layout, older_layout)))
    lines.append(f"inline constexpr std::array<OlderForm, {len(older)}> kOlderForms{{{{")
    for name, hash_value, since, difference, reads_current, read_by_current in older:
        lines.append(f"    {{\"{PACKAGE}::msg::dds_::{name}_\", \"{hash_value}\", \"{since}\", \"{difference}\", "
                     f"{str(reads_current).lower()}, {str(read_by_current).lower()}}},")
    lines += ["}};", "", "}  // namespace dem::protocol", ""]
    return "\n".join(lines)


# --- the field lists of docs/DDS.md -------------------------------------------

DOCS_BEGIN = "<!-- The messages' fields, generated from idl/dem/*.idl by ros2/generate_interfaces.py --docs: edit the IDL. -->"
DOCS_END = "<!-- End of the generated field lists. -->"


def docs_block(messages):
    """Every message's fields, in wire order, as tables: the .msg type and the IDL's comment."""
    lines = [DOCS_BEGIN, ""]
    for message in sorted((m for m in messages.values() if m.package == PACKAGE), key=lambda m: m.name):
        lines += [f"**{message.name}** (`{PACKAGE}/msg/{message.name}`, idl/dem/{message.source})", ""]
        if message.constants:
            constants = ", ".join(f"{c.name} = {c.value}" for c in message.constants)
            lines += [f"Constants: {constants}.", ""]
        lines += ["| field | type | meaning |", "|---|---|---|"]
        for field in message.fields:
            type_ = f"{field.type}[]" if field.sequence else field.type
            meaning = field.comment.replace("|", "\\|")
            lines.append(f"| `{field.name}` | `{type_}` | {meaning} |")
        lines.append("")
    lines.append(DOCS_END)
    return "\n".join(lines)


def docs_text(current, messages):
    """The document with its block of field lists made anew (None: it has no block)."""
    if DOCS_BEGIN not in current or DOCS_END not in current:
        return None
    head, rest = current.split(DOCS_BEGIN, 1)
    _, tail = rest.split(DOCS_END, 1)
    return head + docs_block(messages) + tail


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("idl_dir", type=pathlib.Path)
    parser.add_argument("--msg-dir", type=pathlib.Path)
    parser.add_argument("--check", action="store_true", help="compare the message files instead of writing them")
    parser.add_argument("--cpp-schemas", type=pathlib.Path)
    parser.add_argument("--python-schemas", type=pathlib.Path)
    parser.add_argument("--record", action="store_true",
                        help="record the wire as package.xml's version in idl/interface_history.json")
    parser.add_argument("--cpp-interface", type=pathlib.Path)
    parser.add_argument("--docs", type=pathlib.Path, help="a document with the block of field lists (docs/DDS.md)")
    parser.add_argument("--package-xml", type=pathlib.Path, default=PACKAGE_XML, help="the version's file")
    parser.add_argument("--history", type=pathlib.Path, default=HISTORY, help="the recorded versions' file")
    args = parser.parse_args(argv)
    idl_files = sorted(args.idl_dir.glob("*.idl"))
    if not idl_files:
        parser.error(f"no .idl files in {args.idl_dir}")
    try:
        messages = idl_types.read_idl(idl_files)
    except idl_types.IdlError as error:
        sys.exit(f"generate_interfaces.py: {error}")

    status = 0
    version = interface_version(args.package_xml)
    history = read_history(args.history)
    state = wire_state(messages)
    if args.record:
        try:
            write_history(record(state, version, history), args.history)
        except idl_types.IdlError as error:
            sys.exit(f"generate_interfaces.py: {error}")
    elif args.check:
        for problem in history_problems(state, version, history):
            print(problem)
            status = 1
    if args.docs:
        current = args.docs.read_text()
        wanted = docs_text(current, messages)
        if wanted is None:
            print(f"{args.docs}: no block of field lists ({DOCS_BEGIN} ... {DOCS_END})")
            status = 1
        elif args.check and wanted != current:
            print(f"{args.docs}: its field lists differ from the IDL's (ros2/generate_interfaces.py idl/dem --docs "
                  f"{args.docs})")
            status = 1
        elif not args.check:
            idl_types.write_if_changed(args.docs, wanted)
    if args.cpp_interface:
        idl_types.write_if_changed(args.cpp_interface, cpp_interface(messages, version, history))
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
