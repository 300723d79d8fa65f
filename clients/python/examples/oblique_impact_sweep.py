#!/usr/bin/python3
"""The oblique impact sweep of Randall (1989), 5.4, through the service: a
steel sphere hits a steel wall at 0.4 m/s (Hertz with the Mindlin-Deresiewicz
history) at angles from 0 to 87.5 degrees. Each impact is a case built in
Python from cases/validation/oblique_impact_30deg.case.txtpb with the protobuf
classes (the incident velocity turned to the angle), loaded into dem_server,
run, and read back from a snapshot: the sphere's velocity and spin give the
contact point's rebound. Writes to --out:

  oblique_impact.csv   angle_deg, psi1, psi2, restitution, cycles
  psi2_psi1.png        psi2 against psi1 (cf. Randall Fig. 5.10, Maw et al. Fig. 5.6)
"""

import copy
import csv
import math
import sys

import numpy as np

import dem
from dem.impact import maw_chi, maw_psi, psi1_of_angle
from dem.plots import plot_psi2_against_psi1
from dem.snapshot import State
from example_support import Stopwatch, argument_parser, case_path, say, service

SPEED = 0.4  # m/s (Randall 5.4)


def impact_case(base, angle_deg):
    """The base case with the sphere arriving angle_deg from the wall's normal
    (the wall's normal is +z: the sphere moves along +x and down)."""
    case = copy.deepcopy(base)
    case.name = f"oblique_impact_{angle_deg:g}deg"
    case.description = f"Steel sphere on a steel wall at {SPEED} m/s, {angle_deg:g} degrees from the normal"
    sphere = case.particles[0].particle
    sphere.velocity.x = SPEED * math.sin(math.radians(angle_deg))
    sphere.velocity.y = 0.0
    sphere.velocity.z = -SPEED * math.cos(math.radians(angle_deg))
    return case


def left_the_wall(client):
    moving_away = State.from_bytes(client.snapshot()).velocities[0][2] > 0
    return moving_away and client.state().stats.wall_contacts == 0


def rebound(client):
    """The sphere's velocity, and its contact point's velocity, after the impact."""
    state = State.from_bytes(client.snapshot())
    v, w, r = state.velocities[0], state.angular_velocities[0], state.radii[0]
    # The point that touched the wall: v + omega x (-r e_z) (the wall's normal is e_z).
    contact_point = v + np.cross(w, np.array([0.0, 0.0, -r]))
    return v, contact_point


def main():
    parser = argument_parser(__doc__.splitlines()[0], "out/python/oblique_impact", 176)
    parser.add_argument("--step", type=float, default=2.5, help="angle step, degrees")
    args = parser.parse_args()
    clock = Stopwatch()
    base = dem.cases.load_case_file(case_path("validation/oblique_impact_30deg.case.txtpb"))
    steel = base.material[0]
    nu, mu = steel.poisson_ratio, steel.friction
    chi = maw_chi(nu)  # Randall eq. (5.14), solid sphere
    rows = []
    with service(args, "oblique") as client:
        for angle in np.arange(0.0, 90.0 - 1e-9, args.step):
            case = impact_case(base, float(angle))
            client.load_case(case)
            dem.run_programme(client, case)
            cycles = sum(stage.cycles for stage in case.stage)
            # Near grazing the sphere needs longer to arrive: run on until it
            # has touched and left (moving away, no contact with the wall).
            while not left_the_wall(client):
                client.cycle(1000)
                cycles += 1000
                if cycles > 100000:
                    raise SystemExit(f"the sphere at {angle:g} degrees has not bounced off the wall")
            v, point = rebound(client)
            # Randall eqs. (5.15), (5.16): psi from the incident and the rebound
            # tangential/normal velocity ratios, the tangential one along +x.
            psi1 = psi1_of_angle(nu, mu, angle)
            psi2 = maw_psi(nu, mu, point[0] / v[2])
            restitution = np.linalg.norm(v) / SPEED
            rows.append((float(angle), psi1, psi2, restitution, cycles))
            say(f"{angle:5.1f} deg  psi1 {psi1:7.3f}  psi2 {psi2:+7.3f}  restitution {restitution:.4f}")
    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "oblique_impact.csv", "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["angle_deg", "psi1", "psi2", "restitution", "cycles"])
        writer.writerows([[repr(v) if isinstance(v, float) else v for v in row] for row in rows])
    plot_psi2_against_psi1([r[1] for r in rows], [r[2] for r in rows], chi, png=args.out / "psi2_psi1.png",
                           title=f"Oblique impact, steel sphere, mu = {mu}, nu = {nu} (cf. Randall Fig. 5.10)")
    say(f"chi = {chi:.4f}, 4 chi - 1 = {4 * chi - 1:.3f}")
    say(f"wrote {args.out}: oblique_impact.csv, psi2_psi1.png ({len(rows)} impacts, {clock})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
