#!/usr/bin/python3
"""A uniaxial compression with a loading plate, through the service, on the
sample of any case file (2D or 3D; discs, spheres, and the superquadrics
and ellipsoids of cases/miyata/ as they land). After the sample is prepared,
every wall but the loading plate stands still and the plate moves along its
normal at a constant speed (first faster, until it touches) until its stress
reaches the target; on the way the contacts on the loading and bottom
plates are taken at evenly spaced stresses and pooled into the distribution
of the normalised contact force (Miyata et al. 2002, 3.2-3.3).

Preparation (--preparation):
  case    the case's own stages before the one that moves the plate, run
          by the server's programme (dem.run_programme) (default; auto is
          the same);
  server  the server runs the case's whole programme itself, loading
          included (dem_server --case FILE --run-and-exit); the script
          follows the telemetry and takes the plates' contacts as the
          stress passes each snapshot stress; the force chains come from
          the server's final.snapshot;
  settle  only let the sample settle under gravity until its kinetic energy
          falls below a value (the case's first kinetic_energy_below);
  none    load as it is.

What the case says is used where the options leave it open: the plates
(output.compression.loading_plate / bottom_plate), the speed (the loading
stage's plate velocity), the target (its wall_stress_above) and the stresses
of the force distribution (output.compression.force_distribution).

Writes to --out:
  stress_settlement.csv/.png   the plates' stress against settlement from first contact (live)
  plate_contacts.csv           the contacts on the plates at each snapshot stress
  force_distribution.csv/.png  P(f) per plate, with the q-model (eq. 62) and Mueth's fit (eq. 61)
  force_chains.png             the contact forces at the end (Cundall & Strack Fig. 11 style)
"""

import csv
import math
import pathlib
import sys

import numpy as np

import dem
from dem.force_distribution import ForceDistribution, mueth_density, q_model_density
from dem.plots import LiveStressSettlement, plot_force_chains, plot_force_distribution
from dem.programme import has
from dem.snapshot import State
from example_support import Stopwatch, argument_parser, case_path, fail, say, service


def pick_wall(case, given, compression_field, hints):
    """The wall named by the option, by output.compression, or by its name."""
    names = [w.name for w in case.wall]
    if given:
        if given not in names:
            raise SystemExit(f'the case has no wall "{given}" (walls: {", ".join(names)})')
        return given
    compression = case.output.compression if has(case.output, "compression") else None
    if compression is not None and getattr(compression, compression_field):
        return getattr(compression, compression_field)
    for hint in hints:
        for name in names:
            if hint in name.lower():
                return name
    return None


def loading_stage(case, plate):
    """The index of the first stage that moves or places the plate, or None."""
    for index, stage in enumerate(case.stage):
        if has(stage, "place_wall") and stage.place_wall.wall == plate:
            return index
        for command in stage.wall:
            velocity = command.motion.velocity
            if command.wall == plate and (velocity.x or velocity.y or velocity.z):
                return index
    return None


def prepare(client, case, plate, how, settle_energy, on_wait):
    stages = case.stage
    loading = loading_stage(case, plate)
    if how == "case":
        indices = list(range(len(stages) if loading is None else loading))
        for outcome in dem.run_programme(client, case, stages=indices, on_wait=on_wait):
            say(f'  stage {outcome.index} "{outcome.name}": {outcome.cycles_run} cycles')
    elif how == "settle":
        energy = settle_energy
        if energy is None:
            energy = next((s.until.kinetic_energy_below for s in stages if has(s.until, "kinetic_energy_below")),
                          None)
        if energy is None:
            raise SystemExit("--preparation settle needs --settle-kinetic-energy "
                             "(the case sets no kinetic_energy_below)")
        cap = max([s.cycles for s in stages] + [100000])
        reply = client.run_until(kinetic_energy=energy, max_cycles=cap, check_interval=100, on_wait=on_wait)
        say(f"  settled: {reply.cycles_run} cycles, {reply.message}")
    return loading


def main():
    parser = argument_parser(__doc__.splitlines()[0], "out/python/plate_compression", 178, telemetry_cycles=20)
    parser.add_argument("--case", default=str(case_path("ball/verification_assembly.case.txtpb")),
                        help="the case whose sample is compressed")
    parser.add_argument("--plate", help="the loading plate (default: the case's, or a wall named top/plate)")
    parser.add_argument("--bottom", help="the bottom plate (default: the case's, or a wall named bottom/floor)")
    parser.add_argument("--preparation", choices=("auto", "case", "server", "settle", "none"), default="auto")
    parser.add_argument("--settle-kinetic-energy", type=float, help="J, for --preparation settle")
    parser.add_argument("--speed", type=float,
                        help="plate speed, m/s (default: the case's loading speed, else a millionth of the "
                             "sample's height per time step)")
    parser.add_argument("--approach-speed", type=float, help="speed until the first contact (default 10 x speed)")
    parser.add_argument("--stress", type=float, help="target stress, Pa (default: the case's, else 3 x the "
                                                      "plate's stress after preparation)")
    parser.add_argument("--snapshots", type=int, help="contact snapshots for the force distribution (default 10)")
    parser.add_argument("--window", type=float, nargs=2, metavar=("FROM", "TO"),
                        help="stresses of the snapshots, Pa (default: the case's, else half the target to it)")
    parser.add_argument("--max-cycles", type=int, default=2_000_000, help="cap on each run")
    parser.add_argument("--show", action="store_true", help="also draw the live plot in a window")
    args = parser.parse_args()
    clock = Stopwatch()
    args.out.mkdir(parents=True, exist_ok=True)

    case = dem.cases.load_case_file(args.case)
    plate = pick_wall(case, args.plate, "loading_plate", ("top", "plate", "lid"))
    if plate is None:
        return fail(f"which wall is the loading plate? (--plate; walls: {', '.join(w.name for w in case.wall)})")
    bottom = pick_wall(case, args.bottom, "bottom_plate", ("bottom", "floor", "base"))
    plates = [plate] + ([bottom] if bottom and bottom != plate else [])

    if args.preparation == "auto":
        args.preparation = "case"
    if args.preparation == "server":
        return compress_on_server(args, case, plate, plates, clock)

    with service(args, "compression", read_dirs=[pathlib.Path(args.case).resolve().parent]) as client:
        # The server reads the file itself, so paths inside it resolve against its directory.
        loaded = client.load_case(args.case, on_server=True)
        say(f"{loaded.message}; loading plate {plate}, bottom plate {bottom or '-'}")
        with client.subscribe(contact_stats=False) as telemetry:
            telemetry.wait_for_publisher()
            say(f"preparing the sample ({args.preparation})")
            loading = prepare(client, case, plate, args.preparation, args.settle_kinetic_energy,
                              on_wait=telemetry.drain)
            telemetry.drain()

            state = State.from_bytes(client.snapshot())
            normal = state.wall(plate).normal()  # towards the particles
            stage = case.stage[loading] if loading is not None else None
            speed = args.speed
            if speed is None and stage is not None:
                command = next((c for c in stage.wall if c.wall == plate), None)
                if command is not None:
                    v = command.motion.velocity
                    speed = math.sqrt(v.x ** 2 + v.y ** 2 + v.z ** 2) or None
            if speed is None:
                # Slow enough to stay quasi-static: Miyata's plate (0.01 m/s, a
                # time step of 1.7e-4 s, a 2.7 m sample) moves 6e-7 of the
                # sample's height per step.
                heights = state.positions @ normal
                height = float(heights.max() - heights.min() + 2.0 * state.radii.mean())
                speed = 1e-6 * height / state.time_step
            start = client.state().plates.wall(plate)
            target = args.stress
            if target is None and stage is not None and has(stage.until, "wall_stress_above"):
                target = stage.until.wall_stress_above.value
            if target is None:
                if not start.normal_stress > 0:
                    return fail(f"the plate {plate} carries nothing after preparation: give --stress")
                target = 3.0 * start.normal_stress
            window, count = snapshot_window(case, args, target)
            say(f"loading: plate {plate} at {speed:.4g} m/s to {target:.4g} Pa; "
                f"{count} contact snapshots from {window[0]:.4g} to {window[1]:.4g} Pa")

            # Uniaxial: every other wall stands still (their servos stop).
            for wall in case.wall:
                if wall.name != plate:
                    client.set_wall_velocity(wall.name, (0.0,) * 3, (0.0,) * 3 if state.dimension == 3 else 0.0)

            if not start.contacts:
                client.set_wall_velocity(plate, tuple((args.approach_speed or 10 * speed) * normal))
                reply = client.run_until(wall=plate, stress=1e-6 * target, max_cycles=args.max_cycles,
                                         on_wait=telemetry.drain)
                say(f"  approach: {reply.cycles_run} cycles to the first contact")
                if not reply.condition_met:
                    return fail(f"the plate {plate} found no particle within {args.max_cycles} cycles")
            origin = {w.name: w.settlement for w in client.state().plates.walls}
            client.set_wall_velocity(plate, tuple(speed * normal))
            telemetry.drain()

            distributions = {name: ForceDistribution(name) for name in plates}
            snapshot_rows = []
            levels = list(np.linspace(window[0], window[1], count)) if count > 1 else [window[1]]
            with LiveStressSettlement(telemetry, plates, png=args.out / "stress_settlement.png", show=args.show,
                                      title=f"{case.name}: uniaxial compression by {plate}") as live:
                live.series.origin = origin
                for level in [lv for lv in levels if lv <= target] + ([target] if target > levels[-1] else []):
                    reply = client.run_until(wall=plate, stress=level, max_cycles=args.max_cycles,
                                             on_wait=live.update)
                    if not reply.condition_met:
                        return fail(f"the plate's stress did not reach {level:.4g} Pa within {args.max_cycles} "
                                    f"cycles ({reply.message})")
                    if level in levels:
                        reached = client.state().plates.wall(plate).normal_stress
                        for name in plates:
                            contacts = client.contacts(wall=name)
                            distributions[name].add_snapshot(contacts["normal_force"])
                            snapshot_rows += [(levels.index(level), level, reached, name, c)
                                              for c in contacts]
                    say(f"  {reply.message} ({reply.cycles_run} cycles)")
            live.series.write_csv(args.out / "stress_settlement.csv")
            contacts = client.contacts()
            state = State.from_bytes(client.snapshot())

    write_results(args, case, snapshot_rows, distributions, (window, count), state, contacts, clock)
    return 0


def write_results(args, case, snapshot_rows, distributions, snapshots, state, contacts, clock):
    (low, high), count = snapshots
    taken = max(d.snapshots for d in distributions.values())
    write_plate_contacts(args.out / "plate_contacts.csv", snapshot_rows)
    write_distribution(args.out / "force_distribution.csv", distributions.values())
    plot_force_distribution(list(distributions.values()), png=args.out / "force_distribution.png",
                            title=f"{case.name}: {taken} of {count} snapshots, {low:.3g} to {high:.3g} Pa\n"
                                  "(cf. Miyata et al. 2002, Fig. 35)")
    plot_force_chains(state, contacts, png=args.out / "force_chains.png")
    say(f"wrote {args.out}: stress_settlement.csv/.png, plate_contacts.csv, force_distribution.csv/.png, "
        f"force_chains.png ({clock})")


def snapshot_window(case, args, target):
    """The stresses of the contact snapshots: the options, else the case's
    output.compression.force_distribution, else half the target to it."""
    settings = (case.output.compression.force_distribution
                if has(case.output, "compression") and has(case.output.compression, "force_distribution") else None)
    window = args.window or ((settings.stress_from, settings.stress_to) if settings else (0.5 * target, target))
    count = args.snapshots or (settings.snapshots if settings else 0) or 10
    return tuple(window), count


def compress_on_server(args, case, plate, plates, clock):
    """The server runs the case's whole programme (--run-and-exit) while this
    script watches: the loading plate's stress against its settlement from
    the telemetry, live, and the contacts on the plates queried as the stress
    passes each snapshot stress (the server answers between cycles). The
    stress of a snapshot is its own: the contacts' normal forces on the plate
    over its area."""
    if args.server:
        return fail("--preparation server starts its own dem_server (one-shot); leave out --server")
    loading = next((i for i, s in enumerate(case.stage) if has(s, "place_wall") and s.place_wall.wall == plate),
                   None)
    target = args.stress
    if target is None and loading is not None and has(case.stage[loading].until, "wall_stress_above"):
        target = case.stage[loading].until.wall_stress_above.value
    if target is None:
        return fail("the case's loading stage has no wall_stress_above: give --stress")
    window, count = snapshot_window(case, args, target)
    levels = list(np.linspace(window[0], window[1], count)) if count > 1 else [window[1]]
    say(f"the server runs {case.name}'s {len(case.stage)} stages itself; {count} contact snapshots from "
        f"{window[0]:.4g} to {window[1]:.4g} Pa")
    distributions = {name: ForceDistribution(name) for name in plates}
    snapshot_rows = []
    server_out = args.out / "server"
    server = dem.ServerProcess("compression", args.domain, server_out, telemetry_cycles=args.telemetry_cycles,
                               extra_arguments=["--case", str(pathlib.Path(args.case).resolve()), "--run-and-exit"],
                               overwrite=True)
    with server:
        with server.connect() as client, client.subscribe(contact_stats=False) as telemetry, \
                LiveStressSettlement(telemetry, [plate], png=args.out / "stress_settlement.png", show=args.show,
                                     title=f"{case.name}: uniaxial compression by {plate}") as live:
            areas = {}
            missed = 0
            while server.process.poll() is None and levels:
                sample = telemetry.get(0.05)
                if sample is None or not hasattr(sample, "walls"):
                    live.update()
                    continue
                live.series.add(sample)
                areas = {w.name: w.area for w in sample.walls}
                stress = sample.wall(plate).normal_stress
                if stress < levels[0]:
                    continue
                level = levels.pop(0)
                try:
                    taken = {name: client.contacts(wall=name, timeout=5) for name in plates}
                except dem.DemError as error:  # the programme ended between the sample and the query
                    say(f"  no snapshot at {level:.4g} Pa: {error}")
                    break
                reached = float(taken[plate]["normal_force"].sum()) / areas[plate]
                for name, contacts in taken.items():
                    distributions[name].add_snapshot(contacts["normal_force"])
                    snapshot_rows += [(count - len(levels) - 1, level, reached, name, c) for c in contacts]
                while levels and reached >= levels[0]:  # passed during the query: one snapshot stands for them
                    levels.pop(0)
                    missed += 1
                say(f"  contacts at {reached:.4g} Pa (snapshot stress {level:.4g} Pa): "
                    + ", ".join(f"{name} {contacts.size}" for name, contacts in taken.items()))
            code = server.process.wait()
            live.update()
        live.series.write_csv(args.out / "stress_settlement.csv")
    if code != 0:
        return fail(f"dem_server's programme ended with exit code {code} (see {server.log_file})")
    if levels or missed:
        say(f"  {len(levels) + missed} snapshot stresses passed without a snapshot of their own")
    state = State.from_file(server_out / case.name / "final.snapshot")
    say(f"programme complete at cycle {state.cycle}; {state.contacts.size} contacts in the final snapshot")
    write_results(args, case, snapshot_rows, distributions, (window, count), state, state.contacts, clock)
    return 0


def write_plate_contacts(path, rows):
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["snapshot", "target_stress", "stress", "plate", "particle", "x", "y", "z",
                         "normal_force", "shear_force"])
        for snapshot, target, stress, plate, c in rows:
            writer.writerow([snapshot, repr(float(target)), repr(stress), plate, c["first"], *map(repr, c["point"]),
                             repr(c["normal_force"]), repr(c["shear_force"])])


def write_distribution(path, distributions, bin_width=0.25):
    """Per plate and class [f_low, f_high): contacts, probability density, and
    the two model densities at the class middle."""
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["plate", "f_low", "f_high", "contacts", "probability_density", "q_model", "mueth"])
        for distribution in distributions:
            if distribution.f.size == 0:
                continue
            edges, density = distribution.histogram(bin_width)
            counts, _ = np.histogram(distribution.f, bins=edges)
            for low, high, n, p in zip(edges[:-1], edges[1:], counts, density):
                middle = 0.5 * (low + high)
                writer.writerow([distribution.plate, repr(float(low)), repr(float(high)), int(n), repr(float(p)),
                                 repr(float(q_model_density(middle))), repr(float(mueth_density(middle)))])


if __name__ == "__main__":
    sys.exit(main())
