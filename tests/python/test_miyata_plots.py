"""Miyata et al. (2002) Figs. 26-37 (dem.plots.miyata) from a run's files:
each figure drawn from a run directory written by hand
(miyata_run_files.py) shows what the files hold; the command draws every
figure a run supports and names each one it skips; and the figures of a
real dem_run of the reduced cases CS (2D) and ellipsoids (3D) are written."""

import subprocess
import sys
import types

import numpy as np
import pytest
from matplotlib.collections import PatchCollection, PolyCollection

import dem
from dem.plots.miyata import draw_miyata_directory
from dem.plots.miyata_assembly import (Assembly, _ellipsoid_shadow, assembly_snapshots, plot_force_networks,
                                       plot_rotations, rotation_between)
from dem.plots.miyata_loading import (plot_contact_ratio, plot_load_by_formation, plot_plate_contacts,
                                      plot_stress_settlement_states)
from dem.plots.miyata_moment import plot_bending_moment
from dem.plots.miyata_plates import plot_contact_map, plot_force_density, plot_load_share
from dem.plots.miyata_run import MiyataRun, MissingInput
from dem.slab_moment import moment_ratio
from miyata_run_files import DECAY, LOAD_BY_FORMATION, SNAPSHOTS, loading_curve, plate_forces, write_run
from test_plots import assert_png

FIGURES = ("fig26_stress_settlement", "fig27_force_networks", "fig28_rotations", "fig29_contact_ratio",
           "fig30_load_by_formation", "fig33_plate_contacts", "fig34_contact_map", "fig35_force_density",
           "fig36_bending_moment", "fig37_load_share")


@pytest.fixture
def run(tmp_path):
    write_run(tmp_path / "synthetic_cs")
    return MiyataRun(tmp_path / "synthetic_cs")


def suptitle(figure):
    """The figure's title (matplotlib 3.6 has no Figure.get_suptitle)."""
    return figure._suptitle.get_text() if figure._suptitle is not None else ""


def line_labelled(ax, start):
    lines = [line for line in ax.get_lines() if str(line.get_label()).startswith(start)]
    assert lines, f"no line labelled {start!r} among {[line.get_label() for line in ax.get_lines()]}"
    return lines[0]


def test_fig26_is_the_stress_settlement_curve_with_its_states_drops_and_measures(run):
    figure = plot_stress_settlement_states(run)
    axes = figure.axes
    assert len(axes) == 5  # the curve and four quasi-static measures under it
    assert "Fig. 26" in axes[0].get_title()
    curve = np.array(loading_curve())
    stress = line_labelled(axes[0], "loading plate")
    np.testing.assert_allclose(stress.get_xdata(), curve[:, 1])
    np.testing.assert_allclose(stress.get_ydata(), curve[:, 2] / 1e3)
    # The three states, each shaded over its settlements.
    shaded = [p for p in axes[0].patches if str(p.get_label()).startswith(("initial", "transition", "final"))]
    assert [p.get_label().split(":")[0] for p in shaded] == ["initial", "transition", "final"]
    assert shaded[0].get_label() == "initial: 1-50 kPa"
    # The drop: from its peak (row 100) down to its trough (row 101).
    drop = line_labelled(axes[0], "stress drops")
    np.testing.assert_allclose(drop.get_xdata(), [curve[99, 1]])
    assert f"largest {100 * (1 - curve[100, 2] / curve[99, 2]):.0f} %" in drop.get_label()
    # The final state's line has compression_states.csv's slope.
    final = line_labelled(axes[0], "final state's line")
    x, y = final.get_xdata(), final.get_ydata()
    assert (y[-1] - y[0]) / (x[-1] - x[0]) == pytest.approx(3.6e6 / 1e3)
    # The measures at compression.csv's cycles, against its settlement;
    # infinite ratios (nothing loaded) left out, log scales where apt.
    kinetic = axes[1].get_lines()[0]
    cycles = curve[:, 0]
    shown = cycles >= 1100
    np.testing.assert_allclose(kinetic.get_xdata(), curve[shown, 1])
    np.testing.assert_allclose(kinetic.get_ydata(), 1e-3 * (1 + cycles[shown] / 1e4))
    assert [ax.get_yscale() for ax in axes[1:]] == ["log", "log", "linear", "log"]
    np.testing.assert_allclose(axes[3].get_lines()[0].get_ydata(), 0.05 + cycles / 1e6)


def test_fig26_without_assembly_csv_is_the_curve_alone(run):
    (run.directory / "assembly.csv").unlink()
    assert len(plot_stress_settlement_states(MiyataRun(run.directory)).axes) == 1


def test_figs29_and_33_count_the_plates_contacts(run):
    curve = np.array(loading_curve())
    ratio = plot_contact_ratio(run).axes[0]
    assert "Fig. 29" in ratio.get_title()
    np.testing.assert_allclose(line_labelled(ratio, "loading / bottom").get_ydata(), curve[:, 3] / 20)
    counts = plot_plate_contacts(run).axes[0]
    assert "Fig. 33" in counts.get_title()
    np.testing.assert_allclose(line_labelled(counts, "top (loading)").get_ydata(), curve[:, 3])
    np.testing.assert_allclose(line_labelled(counts, "bottom (bottom)").get_ydata(), 20)
    rate = line_labelled(counts, "initial:")
    x, y = rate.get_xdata(), rate.get_ydata()
    assert (y[-1] - y[0]) / (x[-1] - x[0]) == pytest.approx(1e-4 * 1e3)  # contacts per kPa
    assert "10 contacts per 100 kPa" in rate.get_label()


def test_fig30_bars_are_the_load_shares(run):
    figure = plot_load_by_formation(run)
    formation = figure.axes[0]
    assert "Fig. 30" in suptitle(figure)
    heights = {}
    for container, state in zip(formation.containers, ("initial", "transition", "final")):
        for bar, plate in zip(container, ("top", "bottom")):
            heights[(plate, state)] = bar.get_height()
    assert heights == pytest.approx({key: 100 * load for key, (load, _) in LOAD_BY_FORMATION.items()})
    assert len(figure.axes) == 2  # load_by_state.csv beside it


def test_fig27_draws_each_contact_as_wide_as_its_force(run):
    figure = plot_force_networks(run)
    assert "Fig. 27" in suptitle(figure) and "50 and 900 kPa" in suptitle(figure)
    assert len(figure.axes) == 2
    for ax, snapshot in zip(figure.axes, (1, 6)):
        rectangles = [c for c in ax.collections if isinstance(c, PolyCollection)][0]
        corners = np.array([path.vertices[:4] for path in rectangles.get_paths()])
        widths = np.linalg.norm(corners[:, 0] - corners[:, 3], axis=1)
        # Five pairs and the plates' contacts, widths in proportion to the forces.
        forces = [force * (1 + run.snapshots()[snapshot][3] / 1e3) for force in (1.0, 2.0, 3.0, 4.0, 5.0)]
        forces += [f for plate in plate_forces(snapshot).values() for _, _, f in plate]
        assert len(widths) == len(forces)
        np.testing.assert_allclose(np.sort(widths) / widths.max(), np.sort(forces) / max(forces))
        assert "900 kPa" in figure.axes[1].get_title()


def test_fig28_greys_each_particle_by_its_rotation(run):
    figure = plot_rotations(run)
    assert "Fig. 28" in suptitle(figure)
    first, second = [c for ax in figure.axes for c in ax.collections if isinstance(c, PatchCollection)]
    # 0 -> 50 kPa: disc 5 turned 0.5 rad, disc 3 0.1 rad; 50 -> 250 kPa: 0.2 and 0.4.
    np.testing.assert_allclose(first.get_array(), np.degrees([0, 0, 0, 0.1, 0, 0.5]), atol=1e-9)
    np.testing.assert_allclose(second.get_array(), np.degrees([0, 0, 0, 0.4, 0, 0.2]), atol=1e-9)
    assert first.get_clim() == pytest.approx((0.0, np.degrees(0.5)))
    assert "from the loading's start" in figure.axes[0].get_title()


def test_fig34_maps_the_plates_contacts_at_400_kpa(run):
    figure = plot_contact_map(run)
    assert "Fig. 34" in suptitle(figure) and "target 400 kPa" in suptitle(figure)
    forces = plate_forces(3)
    largest = max(f for plate in forces.values() for _, _, f in plate)
    for ax, plate in zip(figure.axes, ("top", "bottom")):
        points = ax.collections[0]
        np.testing.assert_allclose(points.get_offsets()[:, 0], [x for _, x, _ in forces[plate]])
        # Circle area in proportion to the force, one scale for both plates.
        np.testing.assert_allclose(points.get_sizes(), 1400.0 * np.array([f for _, _, f in forces[plate]]) / largest)
    assert "target 900 kPa" in suptitle(plot_contact_map(run, stress=800e3))


def test_fig35_bars_are_the_densities_with_the_tails_fit(run):
    figure = plot_force_density(run)
    assert "Fig. 35" in suptitle(figure)
    table = run.table("force_distribution.csv")
    for ax, plate in zip(figure.axes, ("top", "bottom")):
        assert ax.get_yscale() == "log"
        rows = (table["plate"] == plate) & (table["probability_density"] > 0)
        bars = ax.containers[0]
        np.testing.assert_allclose([b.get_height() for b in bars], table["probability_density"][rows])
        beta, error = DECAY[plate]
        tail = line_labelled(ax, "tail above f = 1")
        assert f"decay {beta:.2f} ± {error:.2f}" in tail.get_label()
        f, p = tail.get_xdata(), tail.get_ydata()
        np.testing.assert_allclose(p, 3 / 9 * beta * np.exp(-beta * (f - 1.0)))


def test_fig37_is_the_load_per_class(run):
    figure = plot_load_share(run)
    ax = figure.axes[0]
    assert "Fig. 37" in ax.get_title()
    table = run.table("force_distribution.csv")
    rows = table["plate"] == "top"
    np.testing.assert_allclose(line_labelled(ax, "loading plate").get_ydata(), table["load_density"][rows])
    text = ax.texts[0].get_text()
    small = table["load_share"][rows & (table["f_high"] <= 0.5)].sum()
    assert f"loading plate: f < 0.5 carries {100 * small:.0f} %" in text


def test_fig36_sets_the_measured_moments_against_the_monte_carlo_draws(run):
    figure = plot_bending_moment(run, trials=300)
    assert "Fig. 36" in suptitle(figure)
    # No snapshot file gives the cell: the slab spans the contacts seen.
    assert "the contacts' extent" in suptitle(figure)
    xs = [x for s in SNAPSHOTS if s[4] for plate in plate_forces(s[0]).values() for _, x, _ in plate]
    low, span = min(xs), max(xs) - min(xs)
    flow = figure.axes[0]
    assert len([t for t in flow.texts if t.get_text()]) == 6  # the seed's flow, box by box
    for ax, plate in zip(figure.axes[1:], ("top", "bottom")):
        loads = [plate_forces(s[0])[plate] for s in SNAPSHOTS if s[4]]
        expected = [moment_ratio(span, np.array([x for _, x, _ in p]) - low, np.array([f for _, _, f in p]))
                    for p in loads]
        measured = [line.get_xdata()[0] for line in ax.get_lines() if line.get_color() == "tab:red" and
                    len(line.get_xdata()) == 2]
        np.testing.assert_allclose(sorted(measured), sorted(expected))
        assert "300 trials" in ax.get_title()


def test_the_assembly_of_a_snapshot_reads_its_rows(run):
    assembly = Assembly(run, run.snapshots()[1])
    np.testing.assert_array_equal(assembly.ids, [0, 1, 2, 3, 4, 5])
    contacts = assembly.contact_array()
    assert (contacts["second_wall"] >= 0).sum() == 4  # disc 5 on the top plate, three on the bottom
    assert set(contacts["second_particle"][contacts["second_wall"] < 0]) == {3, 4, 5}
    assert assembly.plate_levels() == pytest.approx({"top": loading_curve()[59][1], "bottom": 0.0})


def test_3d_rotations_and_outlines():
    ids = np.array([4, 7])
    # A quarter turn about z for particle 4, 30 degrees about x for 7.
    before = types.SimpleNamespace(dimension=3, ids=ids, row_of=lambda i: np.searchsorted(ids, i),
                                   rotations=np.array([[1.0, 0, 0, 0], [1.0, 0, 0, 0]]))
    after = types.SimpleNamespace(dimension=3, ids=ids, row_of=lambda i: np.searchsorted(ids, i),
                                  rotations=np.array([[np.cos(np.pi / 4), 0, 0, np.sin(np.pi / 4)],
                                                      [np.cos(np.pi / 12), np.sin(np.pi / 12), 0, 0]]))
    turned, degrees = rotation_between(before, after)
    np.testing.assert_array_equal(turned, [4, 7])
    np.testing.assert_allclose(degrees, [90.0, 30.0])
    # An ellipsoid of semi-axes 3, 2, 1 turned a quarter about z, seen along
    # y: across x it shows its second axis (2), up z its third (1).
    q = np.array([np.cos(np.pi / 4), 0, 0, np.sin(np.pi / 4)])
    outline = _ellipsoid_shadow((3.0, 2.0, 1.0), q, np.zeros(2), (0, 2)).get_verts()
    assert np.ptp(outline[:, 0]) == pytest.approx(4.0, rel=1e-3)
    assert np.ptp(outline[:, 1]) == pytest.approx(2.0, rel=1e-3)


def test_the_command_draws_every_figure_and_names_each_it_skips(run, tmp_path):
    out = tmp_path / "figures"
    said = []
    written = draw_miyata_directory(run.directory, out, trials=200, say=said.append)
    assert sorted(p.stem for p in written) == sorted(FIGURES)
    for path in written:
        assert_png(path)
    assert not [line for line in said if line.startswith("skipped")]
    # A run of an older dem: no whole assembly, no summaries yet.
    older = tmp_path / "older"
    write_run(older, assembly=False, summaries=False)
    said.clear()
    written = draw_miyata_directory(older, trials=200, say=said.append)
    assert [p.stem for p in written] == ["fig34_contact_map"]
    skipped = [line for line in said if line.startswith("skipped")]
    assert len(skipped) == 9
    assert any(line.startswith("skipped Fig. 27: no particles_at_stress.csv, contacts_at_stress.csv in") for line in
               skipped)
    assert any(line.startswith("skipped Fig. 26: no compression_states.csv") for line in skipped)
    # The command line: a missing directory is an error that says so.
    result = subprocess.run([sys.executable, "-m", "dem.plots", "miyata", str(tmp_path / "nowhere")],
                            capture_output=True, text=True)
    assert result.returncode == 2 and "no such directory" in result.stderr
    with pytest.raises(MissingInput, match="names both plates"):
        MiyataRun(tmp_path).plate_names()


@pytest.mark.parametrize("case, loading_figure", [("cs_reduced", "fig26"), ("ellipsoids_reduced", "fig32")])
def test_a_dem_run_gives_every_figure(tmp_path, case, loading_figure):
    """dem_run of a reduced case (2 s in 2D, 4 s in 3D), then the command."""
    run_dir = tmp_path / case
    subprocess.run([str(dem.paths.run_program()), str(dem.paths.cases_dir() / "miyata" / f"{case}.case.txtpb"), "-o",
                    str(run_dir)], check=True, capture_output=True)
    result = subprocess.run([sys.executable, "-m", "dem.plots", "miyata", str(run_dir), str(tmp_path / "png"),
                             "--trials", "200"], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert "skipped" not in result.stdout
    names = sorted(p.stem for p in (tmp_path / "png").glob("*.png"))
    assert names == sorted([loading_figure + "_stress_settlement"] + [f for f in FIGURES if not f.startswith("fig26")])
    for path in (tmp_path / "png").glob("*.png"):
        assert_png(path)
    # The whole assembly at the loading's start and each contacts_at_stress stress.
    run = MiyataRun(run_dir)
    assert run.snapshots("for_contacts") == assembly_snapshots(run)
    assert assembly_snapshots(run)[0][1] == 0
