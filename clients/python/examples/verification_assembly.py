#!/usr/bin/python3
"""Cundall & Strack's (1979) verification test through the service: the
photoelastic disc assembly (cases/ball/verification_assembly.case.txtpb,
197 discs) consolidated by four servo-controlled walls to the photoelastic
test's forces, then loaded as the seed's numerical test was, by moving its
walls - inward to stage A, on to stage B, each held while the assembly
comes to rest - the case's own stages, run through dem_server
(dem.run_programme) while the walls' stress against settlement is plotted
live from the telemetry. Writes to --out (the state at the end: stage B):

  stress_settlement.csv   every wall's settlement, normal stress and contacts at each telemetry sample
  stress_settlement.png   the live plot, refreshed as the run goes on (--show: in a window too)
  wall_forces.csv         Table 1: each wall's force components, normal force, contacts; F_H/F_V
  contacts.csv            every contact at the end
  fig11_force_chains.png  the contact forces at stage B (cf. Fig. 11(b))
"""

import csv
import sys

import numpy as np

import dem
from dem.plots import LiveStressSettlement, plot_force_chains
from dem.snapshot import State
from example_support import Stopwatch, argument_parser, case_path, say, service

VERTICAL = ("wall1_bottom", "wall3_top")
HORIZONTAL = ("wall2_right", "wall4_left")


def write_contacts(path, contacts):
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["first", "second_particle", "second_wall", "x", "y", "nx", "ny", "overlap",
                         "normal_force", "shear_force", "sliding"])
        for c in contacts:
            writer.writerow([c["first"], c["second_particle"], c["second_wall"], repr(c["point"][0]),
                             repr(c["point"][1]), repr(c["normal"][0]), repr(c["normal"][1]), repr(c["overlap"]),
                             repr(c["normal_force"]), repr(c["shear_force"]), int(c["sliding"])])


def main():
    parser = argument_parser(__doc__.splitlines()[0], "out/python/verification_assembly", 177)
    parser.add_argument("--show", action="store_true", help="also draw the live plot in a window")
    parser.add_argument("--case", default=str(case_path("ball/verification_assembly.case.txtpb")))
    args = parser.parse_args()
    clock = Stopwatch()
    args.out.mkdir(parents=True, exist_ok=True)
    case = dem.cases.load_case_file(args.case)
    with service(args, "verification") as client:
        client.load_case(args.case)
        with client.subscribe(contact_stats=False) as telemetry:
            telemetry.wait_for_publisher()
            with LiveStressSettlement(telemetry, png=args.out / "stress_settlement.png", show=args.show,
                                      title="verification assembly: consolidated, then walls moved") as live:
                for outcome in dem.run_programme(client, case, on_wait=live.update):
                    say(f'stage {outcome.index} "{outcome.name}": {outcome.cycles_run} cycles'
                        f'{", its conditions met" if outcome.condition_met else ", its cycle cap reached"}')
        live.series.write_csv(args.out / "stress_settlement.csv")
        reply = client.state()
        contacts = client.contacts()
        state = State.from_bytes(client.snapshot())

    walls = {w.name: w for w in reply.plates.walls}
    vertical = np.mean([walls[name].normal_force for name in VERTICAL])
    horizontal = np.mean([walls[name].normal_force for name in HORIZONTAL])
    with open(args.out / "wall_forces.csv", "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["wall", "F1", "F2", "normal_force", "normal_stress", "contacts"])
        for w in reply.plates.walls:
            writer.writerow([w.name, repr(w.force[0]), repr(w.force[1]), repr(w.normal_force),
                             repr(w.normal_stress), w.contacts])
        writer.writerow(["F_H/F_V", repr(horizontal / vertical), "", "", "", ""])
    write_contacts(args.out / "contacts.csv", contacts)
    plot_force_chains(state, contacts, png=args.out / "fig11_force_chains.png",
                      title=f"verification assembly, stage B, F_H/F_V = {horizontal / vertical:.2f} (cf. Fig. 11(b))")
    for w in reply.plates.walls:
        say(f"{w.name:13s} F1 {w.force[0]:+.4e}  F2 {w.force[1]:+.4e}  contacts {w.contacts}")
    say(f"stage B: F_H/F_V = {horizontal / vertical:.3f} at cycle {reply.plates.cycle} "
        f"(Table 1: 0.40; docs/VALIDATION.md); {reply.stats.contacts} contacts")
    say(f"wrote {args.out}: stress_settlement.csv/.png, wall_forces.csv, contacts.csv, fig11_force_chains.png "
        f"({clock})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
