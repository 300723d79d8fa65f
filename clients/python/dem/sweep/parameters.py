"""A sweep's parameters and the cases built from them: a base case (a
dem.cases.Case) and, per parameter, the values it takes, combined as a grid
(every combination) or zipped (the i-th value of each).

A parameter is set by a path into the case message:

    "material[rock].friction"      the element of `material` whose name is "rock"
    "material[*].friction"         every element of `material`
    "stage[2].cycles"              the element at index 2 (from 0)
    "particles[0].random_packing.seed", "gravity.y", "time_step.fixed"

or, for what a path cannot say, by a function apply(case, value) that
changes the case in place.
"""

import itertools
import math
import re

from google.protobuf.descriptor import FieldDescriptor

_STEP = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)(?:\[([^\]]*)\])?$")


class Parameter:
    """One swept parameter: a name (the summary table's column), its values,
    and where it goes: a path into the case, or apply(case, value)."""

    def __init__(self, name, values, *, path=None, apply=None):
        if (path is None) == (apply is None):
            raise ValueError(f"parameter {name!r}: give a path or an apply function (one of them)")
        if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_.\[\]*-]*", name):
            raise ValueError(f"parameter name {name!r}: letters, digits, underscores, dots, brackets")
        self.name = name
        self.values = list(values)
        if not self.values:
            raise ValueError(f"parameter {name!r} has no values")
        for value in self.values:
            if not isinstance(value, (bool, int, float, str)):
                raise ValueError(f"parameter {name!r}: value {value!r} is not a number, a string or a bool")
        self.path = path
        self._apply = apply
        if path is not None:
            _parse(path)  # a malformed path fails here, before any case is built

    def apply(self, case, value):
        if self._apply is not None:
            self._apply(case, value)
        else:
            set_field(case, self.path, value)

    def describe(self):
        """The parameter as sweep.json keeps it."""
        return {"name": self.name, "path": self.path, "values": self.values}

    def __repr__(self):
        where = self.path if self.path is not None else "apply()"
        return f"Parameter({self.name!r}, {self.values!r}, at {where})"


def parameters_from(spec):
    """Parameters from a dict {path: values} (the name is the path's last
    field where that is unambiguous, else the path) or a list of Parameter."""
    if isinstance(spec, dict):
        last = [path.split(".")[-1].split("[")[0] for path in spec]
        return [Parameter(name if last.count(name) == 1 else path, values, path=path)
                for path, name, values in zip(spec, last, spec.values())]
    parameters = list(spec)
    for parameter in parameters:
        if not isinstance(parameter, Parameter):
            raise TypeError(f"{parameter!r} is not a dem.sweep.Parameter")
    names = [p.name for p in parameters]
    if len(set(names)) != len(names):
        raise ValueError(f"two parameters share a name: {names}")
    return parameters


def combinations(parameters, combine="grid"):
    """The tasks' values, one dict {name: value} per task: every combination
    (grid, the last parameter varying fastest) or the i-th value of each (zip)."""
    if combine == "grid":
        rows = itertools.product(*(p.values for p in parameters))
    elif combine == "zip":
        counts = {len(p.values) for p in parameters}
        if len(counts) != 1:
            raise ValueError("combine='zip' needs as many values for every parameter: "
                             + ", ".join(f"{p.name} {len(p.values)}" for p in parameters))
        rows = zip(*(p.values for p in parameters))
    else:
        raise ValueError(f"combine must be 'grid' or 'zip', not {combine!r}")
    return [dict(zip((p.name for p in parameters), row)) for row in rows]


def build_case(base, parameters, values):
    """A copy of the base case with each parameter set to its value."""
    case = type(base)()
    case.CopyFrom(base)
    for parameter in parameters:
        parameter.apply(case, values[parameter.name])
    return case


def set_field(message, path, value):
    """Sets the field a path names (see the module's text) in every message
    it reaches; KeyError naming the step that matched nothing."""
    steps = _parse(path)
    targets = [message]
    for depth, (field, selector) in enumerate(steps):
        last = depth == len(steps) - 1
        where = ".".join(f"{f}[{s}]" if s is not None else f for f, s in steps[:depth + 1])
        reached = []
        for target in targets:
            descriptor = target.DESCRIPTOR.fields_by_name.get(field)
            if descriptor is None:
                known = ", ".join(sorted(target.DESCRIPTOR.fields_by_name))
                raise KeyError(f"{path}: {target.DESCRIPTOR.name} has no field {field!r} (fields: {known})")
            repeated = descriptor.label == FieldDescriptor.LABEL_REPEATED
            if selector is not None and not repeated:
                raise KeyError(f"{where}: {field} is not a repeated field")
            if repeated and selector is None:
                raise KeyError(f"{where}: {field} is repeated: say which, {field}[name], {field}[index] or {field}[*]")
            if last:
                if descriptor.message_type is not None:
                    raise KeyError(f"{path}: {field} is a message, not a value")
                if repeated:
                    elements = getattr(target, field)
                    for index in _select(elements, selector, where, by_name=False):
                        elements[index] = _convert(descriptor, value, path)
                else:
                    setattr(target, field, _convert(descriptor, value, path))
                continue
            if descriptor.message_type is None:
                raise KeyError(f"{where}: {field} is a value, not a message")
            if repeated:
                elements = getattr(target, field)
                reached += [elements[i] for i in _select(elements, selector, where, by_name=True)]
            else:
                reached.append(getattr(target, field))
        targets = reached


def _parse(path):
    steps = []
    for part in path.split("."):
        match = _STEP.match(part)
        if not match:
            raise ValueError(f"parameter path {path!r}: cannot read {part!r} (field, field[name], field[3], field[*])")
        steps.append((match.group(1), match.group(2)))
    return steps


def _select(elements, selector, where, by_name):
    if selector == "*":
        if not len(elements):
            raise KeyError(f"{where}: the case has none")
        return list(range(len(elements)))
    if re.fullmatch(r"-?[0-9]+", selector):
        index = int(selector)
        if not -len(elements) <= index < len(elements):
            raise KeyError(f"{where}: there are {len(elements)}")
        return [index % len(elements)]
    named = by_name and len(elements) and "name" in elements[0].DESCRIPTOR.fields_by_name
    if named:
        found = [i for i, element in enumerate(elements) if element.name == selector]
        if not found:
            names = ", ".join(e.name for e in elements)
            raise KeyError(f"{where}: none is named {selector!r} (names: {names})")
        return found
    raise KeyError(f"{where}: {selector!r} is neither an index nor a name")


def _convert(descriptor, value, path):
    kind = descriptor.cpp_type
    if kind in (FieldDescriptor.CPPTYPE_DOUBLE, FieldDescriptor.CPPTYPE_FLOAT):
        if isinstance(value, (bool, str)) or not math.isfinite(float(value)):
            raise ValueError(f"{path}: {value!r} is not a finite number")
        return float(value)
    if kind in (FieldDescriptor.CPPTYPE_INT32, FieldDescriptor.CPPTYPE_INT64, FieldDescriptor.CPPTYPE_UINT32,
                FieldDescriptor.CPPTYPE_UINT64):
        if isinstance(value, bool) or int(value) != value:
            raise ValueError(f"{path}: {value!r} is not a whole number")
        return int(value)
    if kind == FieldDescriptor.CPPTYPE_BOOL:
        if not isinstance(value, bool):
            raise ValueError(f"{path}: {value!r} is not a bool")
        return value
    if kind == FieldDescriptor.CPPTYPE_ENUM:
        if isinstance(value, str):
            known = descriptor.enum_type.values_by_name
            if value not in known:
                raise ValueError(f"{path}: {value!r} is not one of {', '.join(known)}")
            return known[value].number
        return int(value)
    if kind == FieldDescriptor.CPPTYPE_STRING:
        return str(value)
    raise ValueError(f"{path}: cannot set a field of this kind")
