"""Cases (idl/dem/case.proto) in Python: build them with the protobuf-generated
classes, or read and write them in protobuf text format as the files in
cases/ are.

    case = dem.cases.load_case_file("cases/ball/nine_disc_damped.case.txtpb")
    case.damping.global_alpha = 0
    text = dem.cases.to_text(case)

    case = dem.cases.Case(name="drop", dimension=3)
    case.material.add(name="steel", density=7800, youngs_modulus=210e9, poisson_ratio=0.28)

The server validates a case when it is loaded and answers a bad one with
``invalid_case`` and messages naming the field (a ServerError); here only
the text format itself is checked.
"""

import pathlib

from google.protobuf import text_format

from . import case_pb2
from .errors import CaseFileError

# The schema's messages, by name: dem.cases.Case, dem.cases.Wall, ...
Case = case_pb2.Case
Vector = case_pb2.Vector
Material = case_pb2.Material
ContactModel = case_pb2.ContactModel
Particle = case_pb2.Particle
ParticleSource = case_pb2.ParticleSource
Lattice = case_pb2.Lattice
RandomPacking = case_pb2.RandomPacking
Wall = case_pb2.Wall
WallMotion = case_pb2.WallMotion
Servo = case_pb2.Servo
Stage = case_pb2.Stage
Until = case_pb2.Until


def from_text(text, source_name="<text>"):
    """A Case from protobuf text; CaseFileError naming source:line:column."""
    try:
        return text_format.Parse(text, case_pb2.Case())
    except text_format.ParseError as error:
        line, column = error.GetLine(), error.GetColumn()
        where = f"{source_name}:{line}:{column}" if line else source_name
        raise CaseFileError(f"{where}: {_without_location(str(error))}") from None


def load_case_file(path):
    """The case in a text-format file (cases/**/*.case.txtpb)."""
    path = pathlib.Path(path)
    try:
        text = path.read_text()
    except OSError as error:
        raise CaseFileError(f"cannot read case file {path}: {error.strerror}") from None
    return from_text(text, str(path))


def to_text(case):
    """The case in protobuf text format, as the server and dem_run read it."""
    return text_format.MessageToString(case)


def save_case_file(case, path):
    path = pathlib.Path(path)
    path.write_text(to_text(case))
    return path


def wall_named(case, name):
    """The case's wall of that name; KeyError listing the walls otherwise."""
    for wall in case.wall:
        if wall.name == name:
            return wall
    raise KeyError(f'case {case.name!r} has no wall "{name}" (walls: {", ".join(w.name for w in case.wall)})')


def _without_location(message):
    # ParseError's text starts with "line:column : "; the location is given once, above.
    head, separator, rest = message.partition(" : ")
    return rest if separator and head.replace(":", "").isdigit() else message
