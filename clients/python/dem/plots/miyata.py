"""python3 -m dem.plots miyata RUN_DIR [OUT_DIR]: every figure of Miyata et
al. (2002), 3.2-3.3 (Figs. 26-37), that a run's outputs support, as PNG
files, from the directory `dem_run CASE -o DIR`, `dem_validate
miyata-compression --case CASE --out DIR` or a one-shot `dem_server`
writes for a case with output.compression (docs/CASES.md). A figure whose
inputs the run did not write is skipped with a line saying why."""

import pathlib

from .figure import save_png
from .miyata_assembly import plot_force_networks, plot_rotations
from .miyata_loading import (plot_contact_ratio, plot_load_by_formation, plot_plate_contacts,
                             plot_stress_settlement_states)
from .miyata_moment import plot_bending_moment
from .miyata_plates import plot_contact_map, plot_force_density, plot_load_share
from .miyata_run import MiyataRun, MissingInput


def figures(run, map_stress=None, trials=10000):
    """(seed figure, file name, what it needs, how to draw it) for each figure."""
    loading = 32 if run.dimension == 3 else 26
    return (
        (loading, f"fig{loading}_stress_settlement.png", ("compression.csv", "compression_states.csv"),
         lambda: plot_stress_settlement_states(run)),
        (27, "fig27_force_networks.png", ("particles_at_stress.csv", "contacts_at_stress.csv"),
         lambda: plot_force_networks(run)),
        (28, "fig28_rotations.png", ("particles_at_stress.csv", "contacts_at_stress.csv"),
         lambda: plot_rotations(run)),
        (29, "fig29_contact_ratio.png", ("compression.csv", "compression_states.csv"),
         lambda: plot_contact_ratio(run)),
        (30, "fig30_load_by_formation.png", ("load_by_formation.csv",), lambda: plot_load_by_formation(run)),
        (33, "fig33_plate_contacts.png", ("compression.csv", "compression_states.csv"),
         lambda: plot_plate_contacts(run)),
        (34, "fig34_contact_map.png", ("plate_contacts.csv",), lambda: plot_contact_map(run, stress=map_stress)),
        (35, "fig35_force_density.png", ("force_distribution.csv",), lambda: plot_force_density(run)),
        (36, "fig36_bending_moment.png", ("plate_contacts.csv", "force_distribution.csv"),
         lambda: plot_bending_moment(run, trials=trials)),
        (37, "fig37_load_share.png", ("force_distribution.csv",), lambda: plot_load_share(run)),
    )


def draw_miyata_directory(directory, out=None, *, map_stress=None, trials=10000, say=print):
    """Draws every figure the run in ``directory`` supports into ``out``
    (default: the run's directory); returns the PNG paths written. Each
    figure skipped is reported through ``say``."""
    run = MiyataRun(directory)
    out = pathlib.Path(out) if out else run.directory
    written = []
    for number, name, inputs, draw in figures(run, map_stress, trials):
        missing = [n for n in inputs if not run.has(n)]
        if missing:
            say(f"skipped Fig. {number}: no {', '.join(missing)} in {run.directory}")
            continue
        try:
            figure = draw()
        except MissingInput as reason:
            say(f"skipped Fig. {number}: {reason}")
            continue
        written.append(save_png(figure, out / name))
        say(f"wrote {out / name} (Fig. {number})")
    return written


def main(argv=None):
    """python3 -m dem.plots miyata RUN_DIR [OUT_DIR]: Miyata et al. (2002)
    Figs. 26-37 from a run's plate loading analyses."""
    import argparse

    parser = argparse.ArgumentParser(prog="python3 -m dem.plots miyata", description=main.__doc__)
    parser.add_argument("run", help="the directory of dem_run -o, dem_validate miyata-compression --out or a "
                                    "one-shot dem_server's case")
    parser.add_argument("out", nargs="?", help="where the PNG files go (default: RUN_DIR)")
    parser.add_argument("--map-stress", type=float, help="Fig. 34 at the contacts_at_stress snapshot nearest this "
                                                         "stress, kPa (default: the seed's 400)")
    parser.add_argument("--trials", type=int, default=10000, help="Monte Carlo trials of Fig. 36 (default 10000)")
    args = parser.parse_args(argv)
    if args.trials < 1:
        parser.exit(2, f"{parser.prog}: error: --trials must be at least 1\n")
    try:
        written = draw_miyata_directory(args.run, args.out,
                                        map_stress=None if args.map_stress is None else 1e3 * args.map_stress,
                                        trials=args.trials)
    except (MissingInput, OSError, ValueError) as error:
        parser.exit(2, f"{parser.prog}: error: {error}\n")
    if not written:
        parser.exit(1, f"{parser.prog}: no figure drawn: {args.run} holds none of the plate loading analyses' "
                       "files\n")
