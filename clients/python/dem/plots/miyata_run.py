"""The files of a run with Miyata's plate loading analyses
(output.compression, docs/CASES.md "The files"), as `dem_run CASE -o DIR`,
`dem_validate miyata-compression --out DIR` and a one-shot `dem_server`
write them, read as columns of numpy arrays."""

import csv
import functools
import pathlib

import numpy as np

from ..snapshot import unframe

STATES = ("initial", "transition", "final")


class MissingInput(Exception):
    """A figure's input is not in the run's directory; says which."""


def read_table(path):
    """A CSV file as {column: array}: numbers as floats, other text as str."""
    with open(path, newline="") as source:
        reader = csv.reader(source)
        header = next(reader, [])
        rows = list(reader)
    columns = {}
    for k, name in enumerate(header):
        cells = [row[k] if k < len(row) else "" for row in rows]
        try:
            columns[name] = np.array([float(c) if c != "" else np.nan for c in cells], dtype=float)
        except ValueError:
            columns[name] = np.array(cells, dtype=str)
    return columns


def select(table, mask):
    """The rows of a table where ``mask`` holds."""
    return {name: values[mask] for name, values in table.items()}


class MiyataRun:
    """A run's directory: each table read once, on first use."""

    def __init__(self, directory):
        self.directory = pathlib.Path(directory)
        if not self.directory.is_dir():
            raise MissingInput(f"{self.directory}: no such directory")
        self._tables = {}

    def has(self, name):
        return (self.directory / name).is_file()

    def table(self, name):
        """The table ``name`` (e.g. "compression.csv"); MissingInput when absent."""
        if name not in self._tables:
            if not self.has(name):
                raise MissingInput(f"no {name} in {self.directory}")
            self._tables[name] = read_table(self.directory / name)
        return self._tables[name]

    @property
    def name(self):
        return self.directory.name

    @functools.cached_property
    def dimension(self):
        """3 when a table with positions has z, else 2."""
        for name, column in (("plate_contacts.csv", "z"), ("particles_at_stress.csv", "z"),
                             ("particles.csv", "z"), ("walls.csv", "fz")):
            if self.has(name):
                with open(self.directory / name, newline="") as source:
                    return 3 if column in next(csv.reader(source), []) else 2
        return 2

    def states(self):
        """compression_states.csv as {state: row dict}, the states with samples only."""
        table = self.table("compression_states.csv")
        return {str(state): {name: values[k] for name, values in table.items()}
                for k, state in enumerate(table["state"]) if table["samples"][k] > 0}

    def snapshots(self, plate_flag=None):
        """The snapshots of plate_contacts.csv, in the order taken: (index,
        target_stress, cycle, stress); ``plate_flag`` ("for_contacts" or
        "for_distribution") keeps those it marks (MissingInput for files
        written before the column)."""
        table = self.table("plate_contacts.csv")
        if plate_flag is not None and plate_flag not in table:
            raise MissingInput(f"plate_contacts.csv in {self.directory} has no {plate_flag} column (written by an "
                               "older dem)")
        seen = {}
        for k, index in enumerate(table["snapshot"]):
            if plate_flag is not None and not table[plate_flag][k]:
                continue
            seen.setdefault(int(index), (int(index), table["target_stress"][k], int(table["cycle"][k]),
                                         table["stress"][k]))
        return [seen[i] for i in sorted(seen)]

    def plate_names(self):
        """(loading plate, bottom plate): the summaries list the loading
        plate first, and so does each snapshot of plate_contacts.csv that
        has contacts on both."""
        for name in ("load_by_formation.csv", "load_by_state.csv", "force_tail.csv"):
            if self.has(name):
                plates = list(dict.fromkeys(self.table(name)["plate"]))
                if len(plates) == 2:
                    return plates[0], plates[1]
        if self.has("plate_contacts.csv"):
            table = self.table("plate_contacts.csv")
            for index in dict.fromkeys(table["snapshot"]):
                plates = list(dict.fromkeys(table["plate"][table["snapshot"] == index]))
                if len(plates) == 2:
                    return plates[0], plates[1]
        raise MissingInput(f"no table in {self.directory} names both plates")

    def cell(self):
        """The periodic cell (low, high) along each axis from the run's final
        snapshot (final.snapshot or last_good.snapshot), or None: neither is
        there, or the cell is not periodic along x."""
        for name in ("final.snapshot", "last_good.snapshot"):
            if self.has(name):
                from .. import snapshot_pb2

                message = snapshot_pb2.Snapshot()
                message.ParseFromString(unframe((self.directory / name).read_bytes()))
                settings = message.settings
                if settings.periodic_axes and settings.periodic_axes[0]:
                    return np.array(settings.periodic_min), np.array(settings.periodic_max)
                return None
        return None
