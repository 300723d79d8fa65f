"""A sweep's results gathered from its tasks' tables into numpy arrays and
one summary table (Sweep.results):

    results.parameters    structured array: each task's parameter values
    results.settlement    (tasks, samples) float, NaN past each task's end: the
    results.stress        loading plate's settlement (m) and normal stress (Pa)
    results.cycle         from compression.csv (from the loading stage on), else walls.csv
    results.lengths       samples of each task
    results.final         structured array of final measures (FINAL_FIELDS)
    results.states        each task's state (done, failed, ...)
    results.rows()        the summary table: one dict per task
    results.write_summary(path)   as CSV

A task that is not done contributes what its tables hold so far (a
running or stopped task's series up to where it is), and NaN elsewhere.
"""

import csv
import math

import numpy as np

from ..programme import has

# Final measures of each task, in the summary table's order.
FINAL_FIELDS = (
    ("cycles", "the last cycle"),
    ("time", "s, simulated"),
    ("settlement", "m, the loading plate's, at the end"),
    ("stress", "Pa, the loading plate's normal stress at the end"),
    ("max_stress", "Pa, the largest on the way"),
    ("loading_contacts", "contacts on the loading plate at the end (compression.csv)"),
    ("bottom_stress", "Pa, the bottom plate's at the end (compression.csv)"),
    ("bottom_contacts", "contacts on the bottom plate at the end (compression.csv)"),
    ("contacts", "contacts in the assembly at the end (assembly.csv)"),
    ("sliding_contacts", "of them sliding"),
    ("kinetic_energy", "J, at the end"),
    ("stiffness_initial", "Pa/m, secant stiffness of the initial state (compression_states.csv)"),
    ("stiffness_transition", "Pa/m, of the transition state"),
    ("stiffness_final", "Pa/m, of the final state"),
)


class Results:
    def __init__(self, sweep, plate=None):
        self.sweep = sweep
        self.names = [p["name"] for p in sweep.parameters]
        statuses = sweep.status()
        self.states = np.array([t.state for t in statuses])
        self.exit_codes = [t.exit_code for t in statuses]
        self.attempts = [t.attempt for t in statuses]
        self.plates = []
        series, finals = [], []
        for task in statuses:
            plate_name = plate or _loading_plate(sweep.case(task.index))
            self.plates.append(plate_name)
            tables = _Tables(task.output_dir())
            points = tables.series(plate_name)
            series.append(points)
            finals.append(tables.final(points))
        count = len(statuses)
        longest = max((len(s[0]) for s in series), default=0)
        self.lengths = np.array([len(s[0]) for s in series], dtype=int)
        self.cycle = np.full((count, longest), np.nan)
        self.settlement = np.full((count, longest), np.nan)
        self.stress = np.full((count, longest), np.nan)
        for i, (cycles, settlements, stresses) in enumerate(series):
            self.cycle[i, :len(cycles)] = cycles
            self.settlement[i, :len(settlements)] = settlements
            self.stress[i, :len(stresses)] = stresses
        self.final = np.array([tuple(f[name] for name, _ in FINAL_FIELDS) for f in finals],
                              dtype=[(name, float) for name, _ in FINAL_FIELDS])
        self.parameters = _parameter_array(self.names, sweep.tasks)

    def __len__(self):
        return len(self.states)

    def curve(self, index):
        """(settlement, stress) of one task, without the padding."""
        n = self.lengths[index]
        return self.settlement[index, :n], self.stress[index, :n]

    def label(self, index):
        """"friction=0.35" for task index: its parameters' values."""
        return ", ".join(f"{name}={value}" for name, value in self.sweep.tasks[index].items())

    def rows(self):
        """The summary table: per task, its index, parameters, server, state,
        exit code, attempts, plate and final measures."""
        rows = []
        for i in range(len(self)):
            row = {"task": i, **self.sweep.tasks[i], "server": self.sweep.server_name(i), "state": self.states[i],
                   "exit_code": "" if self.exit_codes[i] is None else self.exit_codes[i], "attempts": self.attempts[i],
                   "plate": self.plates[i] or "", "samples": int(self.lengths[i])}
            row.update({name: float(self.final[name][i]) for name, _ in FINAL_FIELDS})
            rows.append(row)
        return rows

    def write_summary(self, path):
        rows = self.rows()
        columns = list(rows[0]) if rows else ["task"]
        with open(path, "w", newline="") as out:
            writer = csv.DictWriter(out, columns)
            writer.writeheader()
            for row in rows:
                writer.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in row.items()})
        return path


def _loading_plate(case):
    """The case's loading plate: output.compression.loading_plate, else a
    wall named like one."""
    if has(case.output, "compression") and case.output.compression.loading_plate:
        return case.output.compression.loading_plate
    for hint in ("top", "plate", "lid"):
        for wall in case.wall:
            if hint in wall.name.lower():
                return wall.name
    return None


def _parameter_array(names, tasks):
    columns = []
    for name in names:
        values = [task[name] for task in tasks]
        if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
            kind = float
        elif all(isinstance(v, bool) for v in values):
            kind = bool
        else:
            kind = f"U{max(len(str(v)) for v in values)}"
        columns.append((name, kind, values))
    array = np.zeros(len(tasks), dtype=[(name, kind) for name, kind, _ in columns])
    for name, _, values in columns:
        array[name] = values
    return array


class _Tables:
    """The CSV tables of one task's output directory (any may be missing)."""

    def __init__(self, directory):
        self.directory = directory

    def read(self, name):
        if self.directory is None:
            return []
        try:
            with open(self.directory / name, newline="") as table:
                return list(csv.DictReader(table))
        except FileNotFoundError:
            return []

    def series(self, plate):
        """(cycles, settlements, stresses) of the loading plate: compression.csv
        when the case analyses its plate loading, else the plate's rows of walls.csv."""
        rows = self.read("compression.csv")
        if rows:
            return ([_number(r["cycle"]) for r in rows], [_number(r["settlement"]) for r in rows],
                    [_number(r["stress"]) for r in rows])
        rows = [r for r in self.read("walls.csv") if r.get("wall") == plate]
        return ([_number(r["cycle"]) for r in rows], [_number(r["settlement"]) for r in rows],
                [_number(r["normal_stress"]) for r in rows])

    def final(self, series):
        cycles, settlements, stresses = series
        final = {name: math.nan for name, _ in FINAL_FIELDS}
        if settlements:
            final["settlement"] = settlements[-1]
            final["stress"] = stresses[-1]
            final["max_stress"] = max(stresses)
        assembly = self.read("assembly.csv")
        if assembly:
            last = assembly[-1]
            for name in ("cycle", "time", "contacts", "sliding_contacts", "kinetic_energy"):
                final["cycles" if name == "cycle" else name] = _number(last.get(name))
        compression = self.read("compression.csv")
        if compression:
            last = compression[-1]
            for name in ("loading_contacts", "bottom_stress", "bottom_contacts"):
                final[name] = _number(last.get(name))
        for row in self.read("compression_states.csv"):
            if f"stiffness_{row.get('state')}" in final:
                final[f"stiffness_{row['state']}"] = _number(row.get("secant_stiffness"))
        return final


def _number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan
