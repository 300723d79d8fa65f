"""dem.release: the anatomy of a plate loading's stress release (Miyata et al.
2002, 3.2(3), Fig. 32) from a run's compression.csv and ParaView frames,
checked on a hand-made run whose answer is known."""

import math

import numpy as np
import pytest

from dem.release import largest_release, main, read_vtp, rotation_angles, take_apart


def data_array(name, values, kind="Float64", components=1):
    flat = " ".join(repr(float(v)) if kind == "Float64" else str(int(v)) for v in np.ravel(values))
    extra = f' NumberOfComponents="{components}"' if components > 1 else ""
    return f'<DataArray type="{kind}" Name="{name}"{extra} format="ascii">{flat}</DataArray>'


def write_frame(directory, cycle, positions, velocities, orientations, contacts):
    """Particles and contacts as io/src/vtk_files.cpp writes them (ASCII)."""
    n = len(positions)
    particles = f"""<?xml version="1.0"?>
<VTKFile type="PolyData" version="1.0"><PolyData>
<FieldData><DataArray type="String" Name="material_names" NumberOfTuples="1" format="ascii">114 0</DataArray></FieldData>
<Piece NumberOfPoints="{n}"><PointData>
{data_array("id", range(n), "Int32")}
{data_array("velocity", velocities, components=3)}
{data_array("orientation", orientations, components=4)}
</PointData><Points>{data_array("Points", positions, components=3)}</Points></Piece></PolyData></VTKFile>"""
    (directory / f"particles_{cycle:010d}.vtp").write_text(particles)
    first, second, wall, force, point = zip(*contacts) if contacts else ((), (), (), (), ())
    body = f"""<?xml version="1.0"?>
<VTKFile type="PolyData" version="1.0"><PolyData><Piece NumberOfPoints="{len(contacts)}"><CellData>
{data_array("normal_force", force)}
{data_array("first", first, "Int32")}
{data_array("second", second, "Int32")}
{data_array("wall_contact", wall, "UInt8")}
{data_array("point", point, components=3)}
</CellData></Piece></PolyData></VTKFile>"""
    (directory / f"contacts_{cycle:010d}.vtp").write_text(body)


def test_the_largest_release_is_measured_from_the_running_peak():
    stresses = [0.0, 100.0, 400.0, 350.0, 500.0, 50.0, 600.0]
    assert largest_release(list(range(7)), stresses, 300.0) == (4, 5, pytest.approx(0.9))
    # None counts before the peak has passed the stress asked for.
    assert largest_release(list(range(4)), [0.0, 200.0, 20.0, 250.0], 300.0)[2] == 0.0


def test_rotation_angles_of_unit_quaternions():
    turn = [math.cos(0.25), 0.0, 0.0, math.sin(0.25)]  # half a radian about z
    angles = rotation_angles(np.array([[1.0, 0, 0, 0], [1.0, 0, 0, 0]]), np.array([turn, [-1.0, 0, 0, 0]]))
    assert angles == pytest.approx([0.5, 0.0], abs=1e-12)


@pytest.fixture
def run(tmp_path):
    """Three particles stacked on a wall under a plate; from cycle 100 to 300
    the top one drops 6 mm across the cell's edge at x = 5 and turns 0.2 rad,
    and the two strong contacts of the peak (forces 9 and 6, mean 5) lose
    their force while the plate's stress falls from 800 to 40 kPa."""
    (tmp_path / "compression.csv").write_text(
        "stage,cycle,time,settlement,stress\n2,100,0,0,800000\n2,200,0,0,400000\n2,300,0,0,40000\n2,400,0,0,90000\n")
    vtk = tmp_path / "vtk"
    vtk.mkdir()
    still = [1.0, 0.0, 0.0, 0.0]
    turned = [math.cos(0.1), math.sin(0.1), 0.0, 0.0]
    positions = [[1.0, 1.0, 0.2], [1.0, 1.0, 0.6], [4.999, 1.0, 1.0]]
    moved = [[1.0, 1.0, 0.2], [1.0, 1.0, 0.6], [0.001, 1.0, 0.994]]
    contacts = [(0, 0, 1, 9.0, [1, 1, 0]), (0, 1, 0, 6.0, [1, 1, 0.4]), (1, 2, 0, 1.0, [1, 1, 0.8]),
                (2, 1, 1, 4.0, [1, 1, 1.2])]
    write_frame(vtk, 100, positions, np.zeros((3, 3)), [still] * 3, contacts)
    write_frame(vtk, 200, positions, [[0, 0, 0], [0, 0, 0.01], [0, 0, -0.3]], [still] * 3, contacts[:1] + contacts[2:])
    write_frame(vtk, 300, moved, [[0, 0, 0], [0, 0, 0], [0, 0, -0.1]], [still, still, turned],
                [(0, 0, 1, 2.0, [1, 1, 0]), (2, 1, 1, 0.5, [1, 1, 1.2])])
    return tmp_path


def test_read_vtp_gives_points_and_arrays(run):
    frame = read_vtp(run / "vtk" / "particles_0000000100.vtp")
    assert frame["points"].shape == (3, 3)
    assert frame["orientation"].shape == (3, 4)
    assert list(frame["id"]) == [0, 1, 2]


def test_the_release_taken_apart(run):
    release = take_apart(str(run), after_stress=300e3, period=(5.0, 5.0), layer=0.5)
    assert (release.peak_cycle, release.trough_cycle) == (100, 300)
    assert release.fraction == pytest.approx(0.95)
    assert release.strong_contacts == 2  # forces 9 and 6 above the mean of 5
    assert [line.strong_lost for line in release.frames] == [0, 1, 2]
    assert release.frames[1].lost_height == pytest.approx(0.4)
    assert release.frames[1].fastest_speed == pytest.approx(0.3)
    assert release.frames[1].fastest_height == pytest.approx(1.0)
    # The top particle moved 2 mm along x through the periodic edge, 6 mm down.
    top = release.layers[-1]
    assert top[2:5] == pytest.approx((0.002, 0.0, -0.006))
    assert top[6] == pytest.approx(0.2)
    assert release.median_rotation == 0.0


def test_the_command_reports_or_names_what_is_missing(run, tmp_path_factory, capsys):
    assert main([str(run), "--period", "5", "5"]) == 0
    printed = capsys.readouterr().out
    assert "800 kPa at cycle 100 -> 40 kPa at cycle 300 (95.0 %)" in printed
    assert main([str(run), "--after-stress", "900e3"]) == 1
    assert "no fall of the plate's stress after 900000 Pa" in capsys.readouterr().err
    empty = tmp_path_factory.mktemp("empty")
    (empty / "compression.csv").write_text("stage,cycle,time,settlement,stress\n2,1,0,0,5e5\n2,2,0,0,1e5\n")
    assert main([str(empty)]) == 1
    assert "run with --vtk-interval" in capsys.readouterr().err
