"""Randall's (1989) chapter 6 figures, every one a dem_validate randall-*,
randall-centripetal or hopper directory holds (``python3 -m dem.plots
randall DIR [OUT]``): the plots of granular.py, randall_centripetal.py,
randall_contact_stresses.py, randall_damping.py and randall_lattice.py."""

import pathlib

from .figure import save_png
from .granular import (plot_discharge, plot_obliquity_histogram, plot_rose, plot_shear_series, plot_stress_path,
                       plot_velocity_field, read_rows)
from .randall_centripetal import draw_centripetal_directory
from .randall_contact_stresses import plot_contact_stress_histograms, plot_size_contacts
from .randall_damping import plot_con1_sweep
from .randall_lattice import plot_contact_lattice


def draw_randall_directory(directory, out=None):
    """Every figure a dem_validate randall-*, randall-centripetal or hopper directory holds;
    returns the PNG paths written."""
    directory = pathlib.Path(directory)
    out = pathlib.Path(out) if out else directory
    written = []
    if (directory / "roses.csv").exists():
        rows = read_rows(directory / "roses.csv")
        groups = {}
        for row in rows:
            groups.setdefault((row["state"], row["kind"]), []).append(row)
        for (state, kind), bins in groups.items():
            if not any(float(b["share"]) > 0 for b in bins):
                continue
            name = f"rose_{state}_{kind}".replace(" ", "_").replace("%", "percent").replace(".", "_")
            written.append(save_png(plot_rose(bins, title=f"{kind} at {state}"), out / f"{name}.png"))
    if (directory / "obliquity.csv").exists():
        bins = read_rows(directory / "obliquity.csv")
        written.append(save_png(plot_obliquity_histogram(bins), out / "obliquity.png"))
    if (directory / "randall.csv").exists():
        rows = read_rows(directory / "randall.csv")
        if rows:
            written.append(save_png(plot_shear_series(rows), out / "shear.png"))
            written.append(save_png(plot_stress_path(rows), out / "stress_path.png"))
    if (directory / "contact_stresses.csv").exists():
        written.append(save_png(plot_contact_stress_histograms(read_rows(directory / "contact_stresses.csv")),
                                out / "fig6_42_43_contact_stresses.png"))
        if (directory / "size_contacts.csv").exists():
            written.append(save_png(plot_size_contacts(read_rows(directory / "size_contacts.csv")),
                                    out / "size_contacts.png"))
    lattice = [directory / state / table for state in ("at_100_kPa", "strain_0.1_percent")
               for table in ("particles.csv", "contacts.csv")]
    if all(path.is_file() for path in lattice):
        written.append(save_png(plot_contact_lattice(*(read_rows(path) for path in lattice)),
                                out / "fig6_35_contact_lattice.png"))
    if (directory / "con1.csv").exists():
        written.append(save_png(plot_con1_sweep(directory), out / "fig6_22_con1.png"))
    if (directory / "centripetal.csv").exists():
        written.extend(draw_centripetal_directory(directory, out, say=print))
    if (directory / "hopper.csv").exists():
        written.append(save_png(plot_discharge(read_rows(directory / "hopper.csv")), out / "discharge.png"))
    # The states dem_validate keeps (at_100_kPa, strain_0.005_percent, a
    # hopper run part-way through its discharge), each a particles.csv.
    for state in sorted(p for p in directory.iterdir() if (p / "particles.csv").is_file()):
        rows = read_rows(state / "particles.csv")
        name = "velocity_" + state.name.replace(" ", "_").replace(",", "").replace(".", "_")
        written.append(save_png(plot_velocity_field(rows, title=f"velocities, {state.name}"), out / f"{name}.png"))
    return written


def main(argv):
    """python3 -m dem.plots randall DIR [OUT]"""
    if not argv:
        raise SystemExit("usage: python3 -m dem.plots randall DIR [OUT]")
    for path in draw_randall_directory(argv[0], argv[1] if len(argv) > 1 else None):
        print(path)
