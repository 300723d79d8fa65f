#!/usr/bin/python3
"""Cundall & Strack's (1979) nine-disc test through the service: each variant
of cases/ball/nine_disc_*.case.txtpb is loaded into dem_server and its
stages run (dem.run_programme); every 10 cycles the force at contact C (the
case's probe) is read from the contacts. Writes to --out:

  nine_disc.csv              cycle and F_n at C for the compression variants (Figs. 6, 7)
  nine_disc_distortion.csv   cycle, F_n and F_s at C for the distortion variants (Fig. 9)
  fig5b_force_chains.png     the contact forces after fast, damped loading, at rest (Fig. 5(b))
  fig6_damping.png           F_n at C with and without damping (Fig. 6)
  fig7a_loading_speed.png    F_n at C for wall speeds 0.12 and 0.04 (Fig. 7(a))
  fig9_distortion.png        F_n and F_s at C under distortion, phi = 15 and 30 degrees (Fig. 9)
"""

import csv
import sys

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

import dem
from dem.plots import plot_contact_force_history, plot_force_chains, save_png
from dem.snapshot import State
from example_support import Stopwatch, argument_parser, case_path, say, service

COMPRESSION = {  # Figs. 6 and 7(a)
    "nine_disc_undamped": "no damping, walls 0.12/cycle (curve 1)",
    "nine_disc_contact_damping": "contact damping only",
    "nine_disc_global_damping": "global damping only",
    "nine_disc_damped": "contact and global damping (Fig. 6 curve 2)",
    "nine_disc_slow": "no damping, walls 0.04/cycle (Fig. 7(a) curve 2)",
}
DISTORTION = {  # Fig. 9
    "nine_disc_distortion_phi15_ks2_3": "phi = 15 deg, ks/kn = 2/3",
    "nine_disc_distortion_phi15_ks1": "phi = 15 deg, ks/kn = 1",
    "nine_disc_distortion_phi30_ks2_3": "phi = 30 deg, ks/kn = 2/3",
    "nine_disc_distortion_phi30_ks1": "phi = 30 deg, ks/kn = 1",
}
SAMPLE_EVERY = 10  # cycles, as the cases' output interval


def probe_of(case, name="C"):
    for probe in case.output.probe:
        if probe.name == name:
            return probe.first, probe.second
    raise SystemExit(f'case {case.name} has no contact probe "{name}"')


def force_at(contacts, first, second):
    """F_n and F_s of the contact between two particles (0, 0 when they do not touch)."""
    between = contacts[((contacts["first"] == first) & (contacts["second_particle"] == second)) |
                       ((contacts["first"] == second) & (contacts["second_particle"] == first))]
    if between.size == 0:
        return 0.0, 0.0
    return float(between["normal_force"][0]), float(between["shear_force"][0])


def follow_contact_c(client, name):
    """Runs a variant; its cycles, F_n and F_s at C, and the final state and contacts."""
    case = dem.cases.load_case_file(case_path(f"ball/{name}.case.txtpb"))
    first, second = probe_of(case)
    client.load_case(case, source_name=name)
    cycles, normal, shear = [], [], []

    def sample(stage, cycle):
        fn, fs = force_at(client.contacts(), first, second)
        cycles.append(cycle)
        normal.append(fn)
        shear.append(fs)

    dem.run_programme(client, case, sample_every=SAMPLE_EVERY, on_sample=sample)
    final = {"state": State.from_bytes(client.snapshot()), "contacts": client.contacts()}
    return cycles, normal, shear, final


def write_csv(path, histories, with_shear):
    names = list(histories)
    cycles = histories[names[0]][0]
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        header = ["cycle"]
        for name in names:
            header += [f"{name}_Fn", f"{name}_Fs"] if with_shear else [name]
        writer.writerow(header)
        for k, cycle in enumerate(cycles):
            row = [cycle]
            for name in names:
                _, fn, fs = histories[name][:3]
                row += [repr(fn[k]), repr(fs[k])] if with_shear else [repr(fn[k])]
            writer.writerow(row)


def main():
    parser = argument_parser(__doc__.splitlines()[0], "out/python/nine_disc", 175)
    args = parser.parse_args()
    clock = Stopwatch()
    histories = {}
    with service(args, "nine_disc") as client:
        for name in list(COMPRESSION) + list(DISTORTION):
            histories[name] = follow_contact_c(client, name)
            cycles, normal = histories[name][0], histories[name][1]
            say(f"{name:36s} {cycles[-1]:5d} cycles, F_n at C at the end {normal[-1]:.4g}")
    args.out.mkdir(parents=True, exist_ok=True)
    write_csv(args.out / "nine_disc.csv", {n: histories[n] for n in COMPRESSION}, with_shear=False)
    write_csv(args.out / "nine_disc_distortion.csv", {n: histories[n] for n in DISTORTION}, with_shear=True)

    final = histories["nine_disc_damped"][3]
    plot_force_chains(final["state"], final["contacts"], png=args.out / "fig5b_force_chains.png",
                      title="nine-disc test: contact forces after loading, damped (cf. Fig. 5(b))")
    fig6 = {COMPRESSION[n]: histories[n][:2] for n in
            ("nine_disc_undamped", "nine_disc_contact_damping", "nine_disc_global_damping", "nine_disc_damped")}
    plot_contact_force_history(fig6, start_cycle=40, png=args.out / "fig6_damping.png",
                               title="Damping effects at contact C (cf. Fig. 6)")
    fig7 = {COMPRESSION[n]: histories[n][:2] for n in ("nine_disc_undamped", "nine_disc_slow")}
    plot_contact_force_history(fig7, png=args.out / "fig7a_loading_speed.png", marks=(40, 120),
                               title="Speed of loading, k_n = k_s = 1.35e9 (cf. Fig. 7(a))")

    figure = Figure(figsize=(11, 8.5))
    FigureCanvasAgg(figure)
    for row, phi in enumerate(("15", "30")):
        for column, (component, label) in enumerate(((1, "normal force F_n at C"), (2, "shear force F_s at C"))):
            curves = {DISTORTION[n]: (histories[n][0], histories[n][component]) for n in DISTORTION
                      if f"phi{phi}_" in n}
            plot_contact_force_history(curves, ax=figure.add_subplot(2, 2, 2 * row + column + 1), ylabel=label,
                                       marks=(120, 1620),
                                       title=f"({'ab'[row]}) phi_mu = {phi} deg (cf. Fig. 9)")
    figure.tight_layout()
    save_png(figure, args.out / "fig9_distortion.png")
    say(f"wrote {args.out}: nine_disc.csv, nine_disc_distortion.csv, fig5b_force_chains.png, fig6_damping.png, "
        f"fig7a_loading_speed.png, fig9_distortion.png ({clock})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
