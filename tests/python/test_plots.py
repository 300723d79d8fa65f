"""Every plot function writes a non-empty PNG, headless; the live plot
rewrites its PNG and frames as samples come; the force-chain rectangles have
BALL's geometry (Cundall & Strack 1979, Fig. 5(b))."""

import csv
import subprocess
import sys
import types

import numpy as np
import pytest
from matplotlib.image import imread

import dem
from dem.force_distribution import ForceDistribution
from dem.plots import (LiveStressSettlement, StressSettlementSeries, plot_contact_force_history, plot_force_chains,
                       plot_force_distribution, plot_psi2_against_psi1, plot_stress_settlement)
from dem.plots.force_chains import force_rectangles
from dem.snapshot import State, WallState


def assert_png(path, min_bytes=5000):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    assert len(data) > min_bytes, f"{path} has only {len(data)} bytes"
    image = imread(path)
    assert image.shape[0] > 100 and image.shape[1] > 100
    # Something is drawn: not one colour throughout.
    assert np.ptp(image[..., :3]) > 0.5


def plate_forces(cycle, settlement, stress, name="top"):
    wall = types.SimpleNamespace(name=name, settlement=settlement, normal_stress=stress, contacts=3)
    return types.SimpleNamespace(cycle=cycle, time=0.01 * cycle, walls=[wall])


def nine_discs():
    """Three by three discs of radius 50 at spacing 100 in a 300 box."""
    x, y = np.meshgrid([50.0, 150.0, 250.0], [50.0, 150.0, 250.0])
    walls = tuple(WallState(name, np.array(p), np.array(d), -200.0, 200.0, np.empty(0), 0.0, 0.0)
                  for name, p, d in (("bottom", (150, 0), (1, 0)), ("right", (300, 150), (0, 1)),
                                     ("top", (150, 300), (-1, 0)), ("left", (0, 150), (0, -1))))
    return State("nine", 2, 3000, 30.0, 0.01, np.column_stack([x.ravel(), y.ravel()]), np.full(9, 50.0),
                 np.zeros((9, 2)), np.zeros(9), np.zeros(9), np.empty(0), walls)


def contacts(rows):
    array = np.zeros(len(rows), dtype=dem.CONTACT_DTYPE)
    for k, (first, second, wall, point, normal, fn, fs) in enumerate(rows):
        array[k] = (first, second, wall, point + (0.0,), normal + (0.0,), 0.01, fn, fs, (0.0, 0.0, 0.0), 0.0, 0.0,
                    False, 0, (0.0, 0.0, 0.0))
    return array


NINE_DISC_CONTACTS = contacts([
    (4, 5, -1, (200.0, 150.0), (1.0, 0.0), 2.8e9, 0.0),       # contact C
    (4, 7, -1, (150.0, 200.0), (0.0, 1.0), 1.4e9, 0.7e9),
    (1, -1, 0, (150.0, 0.0), (0.0, -1.0), 2.0e9, 0.0),        # disc 1 on the bottom wall
])


def test_force_rectangles_have_ball_s_geometry():
    corners, forces = force_rectangles(nine_discs(), NINE_DISC_CONTACTS, max_width=20.0)
    assert corners.shape == (3, 4, 2)
    np.testing.assert_allclose(forces, [2.8e9, np.hypot(1.4e9, 0.7e9), 2.0e9])
    # C: centred on the contact, along the force, R1 + R2 = 100 long, the widest.
    c = corners[0]
    np.testing.assert_allclose(c, [[150, 160], [250, 160], [250, 140], [150, 140]])
    # A force with a shear part is turned by atan(F_s/F_n) from the normal,
    # its width in proportion: 20 * |F| / max |F|.
    along = corners[1][1] - corners[1][0]
    assert np.linalg.norm(along) == pytest.approx(100.0)
    assert np.degrees(np.arctan2(abs(along[0]), abs(along[1]))) == pytest.approx(np.degrees(np.arctan(0.5)))
    assert np.linalg.norm(corners[1][0] - corners[1][3]) == pytest.approx(20.0 * forces[1] / forces[0])
    # A wall contact: from the contact point into the disc, one radius long.
    np.testing.assert_allclose(corners[2][:, 1], [0.0, 50.0, 50.0, 0.0], atol=1e-9)


def test_every_plot_function_writes_a_png(out):
    series = StressSettlementSeries(["top"])
    for k in range(1, 50):
        series.add(plate_forces(10 * k, 0.001 * k, 1e4 * k ** 1.5))
    plot_stress_settlement(series, png=out / "stress.png")
    assert_png(out / "stress.png")

    rng = np.random.default_rng(2002)
    top, bottom = ForceDistribution("top"), ForceDistribution("bottom")
    for _ in range(10):
        top.add_snapshot(rng.gamma(3.0, 1.0, 60))
        bottom.add_snapshot(rng.exponential(1.0, 120))
    plot_force_distribution([top, bottom], png=out / "distribution.png")
    assert_png(out / "distribution.png")

    plot_force_chains(nine_discs(), NINE_DISC_CONTACTS, png=out / "chains.png")
    assert_png(out / "chains.png")

    cycles = np.arange(10, 3001, 10)
    plot_contact_force_history({"damped": (cycles, 2.8e9 * (1 - np.exp(-cycles / 300.0)))}, start_cycle=40,
                               png=out / "history.png")
    assert_png(out / "history.png")

    psi1 = np.linspace(0.0, 12.0, 30)
    plot_psi2_against_psi1(psi1, np.where(psi1 < 5.86, -0.3 * psi1, psi1 - 5.86), 1.465, png=out / "psi.png")
    assert_png(out / "psi.png")


class FakeSubscription:
    """Hands out prepared plate-force samples as a Subscription would."""

    def __init__(self, samples):
        self.samples = list(samples)

    def drain(self):
        taken, self.samples = self.samples[:5], self.samples[5:]
        return taken

    def get(self, timeout):
        return self.samples.pop(0) if self.samples else None


def test_the_live_plot_rewrites_its_png_headless(out):
    feed = FakeSubscription(plate_forces(10 * k, 0.001 * k, 1e4 * k) for k in range(1, 21))
    live = LiveStressSettlement(feed, ["top"], png=out / "live.png", frames=out / "frames", redraw_interval=0.0)
    assert live.update() == 5
    assert_png(out / "live.png")
    while live.update():
        pass
    live.finish()
    assert len(live.series) == 20
    frames = sorted((out / "frames").glob("stress_settlement_*.png"))
    assert len(frames) >= 4
    for frame in frames:
        assert_png(frame)
    assert not list(out.glob("*.partial")), "a PNG was left half-written"


def test_a_monitor_recording_becomes_a_stress_settlement_png(out):
    # The columns demctl monitor --csv writes (clients/cpp/demctl/monitor.cpp).
    recording = out / "monitor.csv"
    recording.write_text(
        "cycle,time,top_stress,top_settlement,bottom_stress,bottom_settlement,contacts,coordination_number,"
        "sliding_fraction,mean_normal_force,max_normal_force,kinetic_energy,out_of_balance\n"
        + "".join(f"{100 * k},{0.01 * k},{1e4 * k},{0.002 * k},{1.1e4 * k},0,50,3.1,0.1,10,40,1.5,0.01\n"
                  for k in range(1, 31)))
    series = StressSettlementSeries.from_monitor_csv(recording, ["top"])
    assert series.names() == ["top"]
    np.testing.assert_allclose(series.column("top", "stress"), 1e4 * np.arange(1, 31))
    np.testing.assert_allclose(series.column("top", "settlement"), 0.002 * np.arange(1, 31))
    with pytest.raises(ValueError, match="no plate left"):
        StressSettlementSeries.from_monitor_csv(recording, ["left"])
    from dem.plots.stress_settlement import main
    main([str(recording), str(out / "curve.png")])
    assert_png(out / "curve.png")
    assert len(StressSettlementSeries.from_monitor_csv(recording)) == 60  # both plates


def test_a_monitor_recording_draws_the_quasi_static_measures_under_the_curve(out):
    # demctl monitor --csv with the quasi-static columns (monitor_columns.h).
    recording = out / "monitor.csv"
    recording.write_text(
        "cycle,time,top_stress,top_settlement,contacts,kinetic_to_elastic,unbalanced_force,inertial_number\n"
        + "".join(f"{100 * k},{0.01 * k},{1e4 * k},{0.002 * k},50,{1.0 / k},{0.1 / k},{1e-3 / k}\n"
                  for k in range(1, 31)))
    series = StressSettlementSeries.from_monitor_csv(recording, ["top"])
    assert sorted(series.measures) == ["inertial_number", "kinetic_to_elastic", "unbalanced_force"]
    np.testing.assert_allclose(series.measures["kinetic_to_elastic"], 1.0 / np.arange(1, 31))
    from dem.plots.stress_settlement import plot_stress_settlement
    figure = plot_stress_settlement(series, png=out / "curve.png")
    assert len(figure.axes) == 4  # the curve and three panels
    drawn = figure.axes[1].get_lines()[0]  # kinetic / elastic against the settlement
    np.testing.assert_allclose(drawn.get_xdata(), 0.002 * np.arange(1, 31))
    np.testing.assert_allclose(drawn.get_ydata(), 1.0 / np.arange(1, 31))
    assert_png(out / "curve.png")


def test_dem_runs_own_tables_become_stress_settlement_pngs(out):
    # Miyata's reduced case CS through dem_run: walls.csv and compression.csv.
    subprocess.run([str(dem.paths.run_program()), str(dem.paths.cases_dir() / "miyata" / "cs_reduced.case.txtpb"),
                    "--out", str(out / "run"), "--quiet"], check=True, timeout=120)
    with open(out / "run" / "walls.csv", newline="") as source:
        top = [row for row in csv.DictReader(source) if row["wall"] == "top"]
    series = StressSettlementSeries.from_file(out / "run" / "walls.csv", ["top"])
    np.testing.assert_array_equal(series.column("top", "stress"), [float(r["normal_stress"]) for r in top])
    np.testing.assert_array_equal(series.column("top", "settlement"), [float(r["settlement"]) for r in top])
    assert series.column("top", "stress").max() >= 900e3  # loaded to 900 kPa
    loading = StressSettlementSeries.from_file(out / "run" / "compression.csv")
    assert loading.names() == ["loading plate"]
    assert loading.column("loading plate", "stress").max() >= 900e3
    for table in ("walls.csv", "compression.csv"):
        result = subprocess.run([sys.executable, "-m", "dem.plots", "stress-settlement", str(out / "run" / table),
                                 str(out / f"{table}.png")], capture_output=True, text=True, timeout=120)
        assert result.returncode == 0, result.stderr
        assert_png(out / f"{table}.png")


def test_a_file_without_stress_and_settlement_is_named(out):
    table = out / "assembly.csv"
    table.write_text("cycle,time,kinetic_energy\n1,0.1,2\n")
    result = subprocess.run([sys.executable, "-m", "dem.plots", "stress-settlement", str(table), str(out / "x.png")],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 2
    assert f"{table}: no plate stress and settlement in it (columns: cycle, time, kinetic_energy)" in result.stderr


def test_randall_chapter_6_figures_from_a_dem_validate_directory(tmp_path):
    """Roses, obliquities, the shear series and the stress path (Randall
    1989, Figs. 6.15-6.29) from the tables dem_validate randall-* writes,
    the velocity field of a state it keeps (6.31), and the hopper's
    discharge (6.2)."""
    with open(tmp_path / "roses.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["state", "kind", "angle_low", "angle_high", "contacts", "share"])
        for kind in ("contacts", "normal force"):
            for k in range(36):
                low = 2 * np.pi * k / 36
                rows.writerow(["100 kPa", kind, low, low + 2 * np.pi / 36, 10, (1 + 0.3 * np.cos(2 * low)) / 36])
    with open(tmp_path / "obliquity.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["state", "kind", "obliquity_low", "obliquity_high", "contacts", "share"])
        for k in range(20):
            rows.writerow(["100 kPa", "obliquity", -1 + 0.1 * k, -0.9 + 0.1 * k, 5, 0.05])
    with open(tmp_path / "randall.csv", "w", newline="") as out:
        rows = csv.writer(out)
        columns = ["cycle", "deviator_strain", "volumetric_strain", "out_of_balance", "region", "stress_1", "stress_2",
                   "sin_phi", "tangential_share", "sliding_fraction", "anisotropy", "coordination"]
        rows.writerow(columns)
        for k in range(30):
            strain = 1e-4 * k
            rows.writerow([1000 * k, strain, 0, 0.01, "circle", 1e5 * (1 + 4 * strain), 1e5 * (1 - 2 * strain),
                           0.3 * (1 - np.exp(-k / 5)), 0.12, 0.2, 0.05 + strain, 3.6 - strain])
    with open(tmp_path / "hopper.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["run", "half_angle_deg", "orifice", "time", "discharged"])
        for k in range(20):
            rows.writerow(["30 deg, 10 mm", 30, 0.01, 0.005 * k, 25 * k])
    (tmp_path / "strain_0.005_percent").mkdir()
    with open(tmp_path / "strain_0.005_percent" / "particles.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["id", "x", "y", "radius", "vx", "vy", "angular_velocity", "rotation", "material"])
        for k in range(25):
            x, y = 0.002 * (k % 5), 0.002 * (k // 5)
            rows.writerow([k, x, y, 0.001, -0.01 * x, 0.01 * y, 0, 0, "glass"])
    from dem.plots import draw_randall_directory

    written = draw_randall_directory(tmp_path, tmp_path / "png")
    assert {p.name for p in written} >= {"rose_100_kPa_contacts.png", "rose_100_kPa_normal_force.png",
                                         "obliquity.png", "shear.png", "stress_path.png", "discharge.png",
                                         "velocity_strain_0_005_percent.png"}
    for path in written:
        assert_png(path)
    result = subprocess.run([sys.executable, "-m", "dem.plots", "randall", str(tmp_path), str(tmp_path / "cli")],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "cli" / "shear.png").exists()


def test_randall_contact_stress_figures_from_a_dem_validate_directory(tmp_path):
    """Figs. 6.42-6.43 (the mean normal contact stresses at 0, 0.1 and 0.2 %
    deviator strain) and each size's contacts (Randall 4.6) from the tables
    dem_validate randall-shear writes."""
    random = np.random.default_rng(1989)
    with open(tmp_path / "contact_stresses.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["state", "deviator_strain", "normal_force", "contact_radius", "normal_stress", "shear_stress",
                       "radius_ratio", "overlap_ratio"])
        for state, strain, spread in (("0 %", 0, 1.3e8), ("0.1 %", 0.001, 1.7e8), ("0.2 %", 0.002, 2e8)):
            for stress in random.normal(5e8, spread, 150):
                rows.writerow([state, strain, 0.15, 1e-5, abs(stress), 1e7, 0.03, 0.001])
    with open(tmp_path / "size_contacts.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["state", "deviator_strain", "radius", "particles", "contacts", "coordination", "share",
                       "without_contacts"])
        for radius, particles, contacts in ((0.00031, 3, 6), (0.00046, 30, 95), (0.00092, 5, 28)):
            rows.writerow(["0 %", 0, radius, particles, contacts, contacts / particles, contacts / 129, 0])
    from dem.plots import draw_randall_directory

    written = draw_randall_directory(tmp_path, tmp_path / "png")
    assert {p.name for p in written} == {"fig6_42_43_contact_stresses.png", "size_contacts.png"}
    for path in written:
        assert_png(path)


def test_randall_contact_lattice_from_the_two_states_dem_validate_keeps(tmp_path):
    """Fig. 6.35: the contacts at the start of the shear (at_100_kPa/) and
    at 0.1 % (strain_0.1_percent/), kept, broken and formed."""
    states = {"at_100_kPa": [(0, 1), (1, 2), (0, 3)], "strain_0.1_percent": [(1, 2), (0, 3), (2, 3)]}
    for state, pairs in states.items():
        (tmp_path / state).mkdir()
        with open(tmp_path / state / "particles.csv", "w", newline="") as out:
            rows = csv.writer(out)
            rows.writerow(["id", "x", "y", "radius", "vx", "vy", "angular_velocity", "rotation", "material"])
            for k, (x, y) in enumerate(((0, 0), (0.002, 0), (0.002, 0.002), (0, 0.002))):
                rows.writerow([k, x, y, 0.001, 0, 0, 0, 0, "glass"])
        with open(tmp_path / state / "contacts.csv", "w", newline="") as out:
            rows = csv.writer(out)
            rows.writerow(["first", "second_kind", "second", "x", "y", "normal_force"])
            for a, b in pairs:
                rows.writerow([a, "particle", b, 0, 0, 0.1])
            rows.writerow([0, "wall", 0, 0, 0, 0.1])
    from dem.plots import draw_randall_directory, plot_contact_lattice

    written = draw_randall_directory(tmp_path, tmp_path / "png")
    assert "fig6_35_contact_lattice.png" in {p.name for p in written}
    assert_png(tmp_path / "png" / "fig6_35_contact_lattice.png")
    read = lambda state, table: list(csv.DictReader(open(tmp_path / state / table)))
    figure = plot_contact_lattice(read("at_100_kPa", "particles.csv"), read("at_100_kPa", "contacts.csv"),
                                  read("strain_0.1_percent", "particles.csv"),
                                  read("strain_0.1_percent", "contacts.csv"))
    assert "2 kept, 1 broken (dashed), 1 new (thick)" in figure.axes[0].get_title()


def test_randall_con1_sweep_figure_from_a_dem_validate_directory(tmp_path):
    """Fig. 6.22 (sin phi and the isotropic stress for each CON1, with Delta
    F / F and the perturbation velocities over the field's) from the tables
    dem_validate randall-shear --con1 writes: con1.csv naming each run's
    directory, and its randall.csv and perturbation.csv."""
    with open(tmp_path / "con1.csv", "w", newline="") as out:
        summary = csv.writer(out)
        summary.writerow(["con1", "packing_seed", "directory", "end_strain", "peak_sin_phi", "peak_strain",
                          "mean_stress_start", "mean_stress_end", "largest_out_of_balance", "smallest_ratio",
                          "largest_ratio", "ratio_0.05_percent", "ratio_0.1_percent", "ratio_0.2_percent",
                          "ratio_0.5_percent", "ratio_2_percent"])
        for con1 in (0.99, 0.25):
            for seed in (1989, 1):
                directory = tmp_path / f"con1_{con1:g}" / f"packing_{seed}"
                directory.mkdir(parents=True)
                summary.writerow([con1, seed, f"con1_{con1:g}/packing_{seed}", 0.002, 0.3, 0.001, 9e4, 1.3e5, 0.01,
                                  0.01, 0.2, 0.1, 0.05, 0.03, "", ""])
                with open(directory / "randall.csv", "w", newline="") as table:
                    rows = csv.writer(table)
                    rows.writerow(["cycle", "deviator_strain", "volumetric_strain", "out_of_balance", "region",
                                   "stress_1", "stress_2", "sin_phi"])
                    for k in range(20):
                        strain = 1e-4 * k
                        for region in ("circle_74", "all"):
                            rows.writerow([1000 * k, strain, 0, 0.01, region, 1e5 * (1 + (3 - con1) * strain),
                                           1e5 * (1 - strain), 0.3 * (1 - np.exp(-k / 4))])
                with open(directory / "perturbation.csv", "w", newline="") as table:
                    rows = csv.writer(table)
                    rows.writerow(["cycle", "deviator_strain", "out_of_balance", "perturbation_rms", "field_rms",
                                   "perturbation_ratio"])
                    for k in range(1, 20):
                        rows.writerow([1000 * k, 1e-4 * k, 0.01 * con1, 1e-5 / k, 1e-4, 0.1 * con1 / k])
    from dem.plots import draw_randall_directory

    written = draw_randall_directory(tmp_path, tmp_path / "png")
    assert {p.name for p in written} == {"fig6_22_con1.png"}
    assert_png(written[0])


def test_randall_centripetal_figures_from_a_dem_validate_directory(tmp_path):
    """Randall's 6.4.2 (Figs. 6.4-6.8) from the tables dem_validate
    randall-centripetal writes: the contact forces after the compaction and
    at 100 kPa with the circles, the porosity by radius, sin(phi) and the
    volumetric strain of each circle against its deviator strain; a figure
    whose files are missing is skipped with a line naming them."""
    with open(tmp_path / "circles.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["region", "centre_x", "centre_y", "radius"])
        for name, radius in (("circle_15", 0.002), ("circle_34", 0.003), ("circle_62", 0.004)):
            rows.writerow([name, 0.005, 0.005, radius])
    with open(tmp_path / "profile.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["state", "radius_low", "radius_high", "porosity", "contacts", "mean_normal_force"])
        for k in range(12):
            rows.writerow(["compacted", 0.0005 * k, 0.0005 * (k + 1), 0.13 + 0.002 * k, 10, 0.1 - 0.005 * k])
    with open(tmp_path / "centripetal.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["cycle", "box_deviator_strain", "out_of_balance", "region", "volumetric_strain",
                       "deviator_strain", "sin_phi"])
        for name, sign in (("circle_15", -1.0), ("circle_62", 1.0)):
            for k in range(30):
                strain = 5e-4 * k
                rows.writerow([1000 * k, strain, 0.01, name, sign * strain * (0.005 - strain), strain,
                               0.3 * (1 - np.exp(-k / 5))])
    (tmp_path / "compacted").mkdir()
    with open(tmp_path / "compacted" / "particles.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["id", "x", "y", "radius", "vx", "vy", "angular_velocity", "rotation", "material"])
        for k in range(25):
            rows.writerow([k, 0.002 * (k % 5) + 0.001, 0.002 * (k // 5) + 0.001, 0.001, 0, 0, 0, 0, "glass"])
    with open(tmp_path / "compacted" / "contacts.csv", "w", newline="") as out:
        rows = csv.writer(out)
        rows.writerow(["first", "second_kind", "second", "x", "y", "normal_force"])
        for k in range(24):
            if k % 5 != 4:
                rows.writerow([k, "particle", k + 1, 0, 0, 0.1 * (1 + k % 3)])
        rows.writerow([0, "wall", 0, 0.001, 0.0, 0.05])
    from dem.plots import draw_centripetal_directory

    said = []
    written = draw_centripetal_directory(tmp_path, tmp_path / "png", say=said.append)
    assert {p.name for p in written} == {"fig6_4_forces_compacted.png", "fig6_5_porosity.png", "fig6_7_sin_phi.png",
                                         "fig6_8_volumetric_strain.png"}
    for path in written:
        assert_png(path)
    assert said == [f"skipped Fig. 6.6: no at_100_kPa/particles.csv, at_100_kPa/contacts.csv in {tmp_path}"]
    result = subprocess.run([sys.executable, "-m", "dem.plots", "randall", str(tmp_path), str(tmp_path / "cli")],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "cli" / "fig6_8_volumetric_strain.png").exists()
    assert "skipped Fig. 6.6" in result.stdout
