"""The ParaView files (io/vtk_files.h, io/vtk_series.h) read back by VTK
itself (Debian's python3-vtk9), compared with the CSV tables of the same
run: dem_run --vtk-interval on a 2D disc case with plates, a periodic
superquadric case and a 3D ellipsoid case with a wall of triangle faces,
and dem_vtk on the snapshot dem_run left.

Environment: DEM_RUN and DEM_VTK (the programs), DEM_CASES (cases/),
DEM_IO_TEST_DATA (tests/io/data).
"""

import csv
import math
import os
import pathlib
import subprocess
import xml.etree.ElementTree as ElementTree

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

DEM_RUN = os.environ["DEM_RUN"]
DEM_VTK = os.environ["DEM_VTK"]
CASES = pathlib.Path(os.environ["DEM_CASES"])
DATA = pathlib.Path(os.environ["DEM_IO_TEST_DATA"])


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    assert reader.GetErrorCode() == 0, f"VTK could not read {path}"
    return reader.GetOutput()


def array(data, name, where="point"):
    found = {"point": data.GetPointData(), "cell": data.GetCellData(), "field": data.GetFieldData()}[where]
    values = found.GetArray(name)
    assert values is not None, f"no {where} array {name}"
    return vtk_to_numpy(values)


def strings(data, name, where="cell"):
    found = (data.GetCellData() if where == "cell" else data.GetFieldData()).GetAbstractArray(name)
    assert found is not None, f"no {where} string array {name}"
    return [found.GetValue(i) for i in range(found.GetNumberOfValues())]


def rows(path):
    with open(path, newline="") as source:
        return list(csv.DictReader(source))


def collection(path):
    """(timestep, file) of each DataSet of a .pvd, in file order."""
    root = ElementTree.parse(path).getroot()
    assert root.get("type") == "Collection"
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def run(arguments, expect=0):
    result = subprocess.run(arguments, capture_output=True, text=True, timeout=300)
    assert result.returncode == expect, f"{arguments} exited {result.returncode}:\n{result.stdout}\n{result.stderr}"
    return result


@pytest.fixture(scope="module")
def discs(tmp_path_factory):
    """Miyata's reduced case CS (160 discs between two plates, 71,080 cycles) with a step every 10,000 cycles."""
    out = tmp_path_factory.mktemp("discs")
    run([DEM_RUN, str(CASES / "miyata/cs_reduced.case.txtpb"), "--out", str(out), "--quiet", "--vtk-interval", "10000"])
    return out


def last_step(out, kind):
    return out / collection(out / f"{kind}.pvd")[-1][1]


def test_the_series_lists_a_step_per_interval_and_the_end(discs):
    assembly = rows(discs / "assembly.csv")
    final_cycle, final_time = int(assembly[-1]["cycle"]), float(assembly[-1]["time"])
    for kind in ("particles", "contacts", "walls"):
        steps = collection(discs / f"{kind}.pvd")
        cycles = [read_vtp(discs / f).GetFieldData().GetArray("cycle").GetValue(0) for _, f in steps]
        assert cycles[0] == 0
        assert cycles[-1] == final_cycle
        # A step at the first output row (every 100 cycles here) once 10,000 have passed, and the end.
        gaps = [b - a for a, b in zip(cycles[:-1], cycles[1:])]
        assert all(10000 <= gap <= 10100 for gap in gaps[:-1]), cycles
        assert 0 < gaps[-1] <= 10100, cycles
        times = [t for t, _ in steps]
        assert times == sorted(times)
        assert times[-1] == pytest.approx(final_time, rel=1e-12)
        for time, file in steps:
            data = read_vtp(discs / file)
            assert array(data, "TimeValue", "field")[0] == time
        assert all((discs / f).is_file() for _, f in steps)


def test_particles_hold_what_particles_csv_holds(discs):
    data = read_vtp(last_step(discs, "particles"))
    table = rows(discs / "particles.csv")
    assert data.GetNumberOfPoints() == len(table) == data.GetNumberOfVerts()
    points = vtk_to_numpy(data.GetPoints().GetData())
    ids = array(data, "id")
    np.testing.assert_array_equal(ids, [int(r["id"]) for r in table])
    # Exact: both files hold the shortest text that reads back to the same double.
    np.testing.assert_array_equal(points[:, 0], [float(r["x"]) for r in table])
    np.testing.assert_array_equal(points[:, 1], [float(r["y"]) for r in table])
    assert not points[:, 2].any()
    np.testing.assert_array_equal(array(data, "radius"), [float(r["radius"]) for r in table])
    velocity = array(data, "velocity")
    np.testing.assert_array_equal(velocity[:, 0], [float(r["vx"]) for r in table])
    np.testing.assert_array_equal(velocity[:, 1], [float(r["vy"]) for r in table])
    spin = array(data, "angular_velocity")
    np.testing.assert_array_equal(spin[:, 2], [float(r["angular_velocity"]) for r in table])
    assert not spin[:, :2].any()
    # Discs: a = b = R, n = 2; the quaternion turns about z by the rotation.
    radius = array(data, "radius")
    np.testing.assert_array_equal(array(data, "semi_axes")[:, 0], radius)
    np.testing.assert_array_equal(array(data, "exponent"), 2.0)
    q = array(data, "orientation")
    angles = 2.0 * np.arctan2(q[:, 3], q[:, 0])
    rotation = np.array([float(r["rotation"]) for r in table])
    np.testing.assert_allclose(np.angle(np.exp(1j * (angles - rotation))), 0.0, atol=1e-9)
    assert strings(data, "material_names", "field") == ["rock", "plate"]
    np.testing.assert_array_equal(array(data, "material"), 0)


def points_of(particles, ids):
    """Each particle id's point: ids stay with their particles, so after the
    case's trim they have gaps and are not the points' positions."""
    index = {int(i): k for k, i in enumerate(array(particles, "id"))}
    return np.array([index[int(i)] for i in ids], dtype=int)


def test_coordination_counts_the_contacts_of_contacts_csv(discs):
    data = read_vtp(last_step(discs, "particles"))
    expected = np.zeros(data.GetNumberOfPoints(), dtype=int)
    for contact in rows(discs / "contacts.csv"):
        expected[points_of(data, [contact["first"]])[0]] += 1
        if contact["second_kind"] == "particle":
            expected[points_of(data, [contact["second"]])[0]] += 1
    np.testing.assert_array_equal(array(data, "coordination"), expected)
    assert expected.sum() > 0


def test_contacts_are_lines_carrying_the_forces_of_contacts_csv(discs):
    data = read_vtp(last_step(discs, "contacts"))
    table = rows(discs / "contacts.csv")
    assert data.GetNumberOfLines() == len(table) > 100
    walls = {"bottom": 0, "top": 1}
    expected = sorted((int(r["first"]), r["second_kind"] == "wall",
                       walls[r["second"]] if r["second_kind"] == "wall" else int(r["second"]),
                       float(r["normal_force"]), float(r["shear_force"]), int(r["sliding"])) for r in table)
    got = sorted(zip(array(data, "first", "cell").tolist(), array(data, "wall_contact", "cell").astype(bool).tolist(),
                     array(data, "second", "cell").tolist(), array(data, "normal_force", "cell").tolist(),
                     array(data, "shear_force", "cell").tolist(), array(data, "sliding", "cell").tolist()))
    assert got == expected
    # Each line runs from the first particle's centre.
    particle_data = read_vtp(last_step(discs, "particles"))
    particles = vtk_to_numpy(particle_data.GetPoints().GetData())
    points = vtk_to_numpy(data.GetPoints().GetData())
    first = points_of(particle_data, array(data, "first", "cell"))
    lines = vtk_to_numpy(data.GetLines().GetConnectivityArray()).reshape(-1, 2)
    np.testing.assert_array_equal(points[lines[:, 0]], particles[first])


def test_a_contact_across_the_periodic_boundary_runs_to_the_nearest_image(discs):
    # Periodic in x over [0, 4): a line to a neighbour across the boundary
    # is as short as any other, not across the cell.
    crossing = 0
    for (_, particles_file), (_, contacts_file) in zip(collection(discs / "particles.pvd"),
                                                      collection(discs / "contacts.pvd")):
        particles = read_vtp(discs / particles_file)
        centres = vtk_to_numpy(particles.GetPoints().GetData())
        contacts = read_vtp(discs / contacts_file)
        points = vtk_to_numpy(contacts.GetPoints().GetData())
        lines = vtk_to_numpy(contacts.GetLines().GetConnectivityArray()).reshape(-1, 2)
        pairs = array(contacts, "wall_contact", "cell") == 0
        first = points_of(particles, array(contacts, "first", "cell")[pairs])
        second = points_of(particles, array(contacts, "second", "cell")[pairs])
        crossing += int((np.abs(centres[second, 0] - centres[first, 0]) > 2.0).sum())
        lengths = np.linalg.norm(points[lines[pairs, 1]] - points[lines[pairs, 0]], axis=1)
        radius = array(particles, "radius")
        assert (lengths <= radius[first] + radius[second]).all()
    assert crossing > 0, "no contact across the periodic boundary in any step"


def test_walls_carry_their_names_and_the_forces_of_walls_csv(discs):
    data = read_vtp(last_step(discs, "walls"))
    assert data.GetNumberOfLines() == 2
    assert strings(data, "name") == ["bottom", "top"]
    last_rows = {r["wall"]: r for r in rows(discs / "walls.csv")[-2:]}
    for wall, force, contacts in zip(strings(data, "name"), array(data, "normal_force", "cell"),
                                     array(data, "contacts", "cell")):
        assert force == float(last_rows[wall]["normal_force"])
        assert contacts == int(last_rows[wall]["contacts"])
    # The top plate's segment passes through its reference point.
    points = vtk_to_numpy(data.GetPoints().GetData())
    top = last_rows["top"]
    assert points[2:4, 1] == pytest.approx([float(top["y"])] * 2, abs=1e-12)


def test_superquadrics_show_their_axes_exponent_and_turn(tmp_path):
    run([DEM_RUN, str(DATA / "superquadrics.case.txtpb"), "--out", str(tmp_path), "--quiet", "--vtk-interval", "500"])
    # Before the trim: the two placed particles first (a = 0.05, b = 0.025,
    # n = 4, turned 90 degrees; a = 0.03, b = 0.04, n = 2.5), then 20 random ones.
    first = read_vtp(tmp_path / collection(tmp_path / "particles.pvd")[0][1])
    assert first.GetNumberOfPoints() == 22
    np.testing.assert_array_equal(array(first, "semi_axes")[0], [0.05, 0.025, 0.0])
    np.testing.assert_array_equal(array(first, "semi_axes")[1], [0.03, 0.04, 0.0])
    np.testing.assert_array_equal(array(first, "semi_axes")[2:], [[0.04, 0.02, 0.0]] * 20)
    np.testing.assert_array_equal(array(first, "exponent"), [4.0, 2.5] + [4.0] * 20)
    q = array(first, "orientation")[0]
    assert 2.0 * math.atan2(q[3], q[0]) == pytest.approx(math.pi / 2, abs=1e-12)
    # At the end: what particles.csv holds.
    data = read_vtp(last_step(tmp_path, "particles"))
    table = rows(tmp_path / "particles.csv")
    assert data.GetNumberOfPoints() == len(table) > 0
    axes = array(data, "semi_axes")
    # The tensor's first column is the body x axis scaled by a, at the particle's angle.
    tensor = array(data, "shape_tensor")
    rotation = np.array([float(r["rotation"]) for r in table])
    np.testing.assert_allclose(tensor[:, 0], axes[:, 0] * np.cos(rotation), atol=1e-12)
    np.testing.assert_allclose(tensor[:, 1], axes[:, 0] * np.sin(rotation), atol=1e-12)
    np.testing.assert_allclose(tensor[:, 3], -axes[:, 1] * np.sin(rotation), atol=1e-12)
    np.testing.assert_allclose(tensor[:, 4], axes[:, 1] * np.cos(rotation), atol=1e-12)


def test_ellipsoids_and_triangle_faces_in_3d(tmp_path):
    run([DEM_RUN, str(DATA / "ellipsoids.case.txtpb"), "--out", str(tmp_path), "--quiet", "--vtk-interval", "100"])
    data = read_vtp(last_step(tmp_path, "particles"))
    table = rows(tmp_path / "particles.csv")
    points = vtk_to_numpy(data.GetPoints().GetData())
    np.testing.assert_array_equal(points[:, 2], [float(r["z"]) for r in table])
    np.testing.assert_array_equal(array(data, "semi_axes")[0], [0.1, 0.07, 0.05])
    np.testing.assert_array_equal(array(data, "semi_axes")[1], [0.08, 0.06, 0.04])
    q = array(data, "orientation")
    expected_q = np.array([[float(r[f"rotation_{c}"]) for c in "wxyz"] for r in table])
    np.testing.assert_allclose(q, expected_q, atol=1e-15)
    # The tensor's columns are orthogonal and as long as the semi-axes.
    tensor = array(data, "shape_tensor").reshape(-1, 3, 3)  # [particle, axis, component]
    lengths = np.linalg.norm(tensor, axis=2)
    np.testing.assert_allclose(lengths, array(data, "semi_axes"), rtol=1e-12)
    for t in tensor:
        gram = t @ t.T
        np.testing.assert_allclose(gram - np.diag(np.diag(gram)), 0.0, atol=1e-15)
    walls = read_vtp(last_step(tmp_path, "walls"))
    # The floor's two triangle faces and the lid's rectangle, each a polygon named after its wall.
    assert walls.GetNumberOfPolys() == 3
    assert strings(walls, "name") == ["floor", "floor", "lid"]
    np.testing.assert_array_equal(array(walls, "wall", "cell"), [0, 0, 1])


def test_dem_vtk_converts_a_snapshot_into_the_runs_last_step(discs, tmp_path):
    result = run([DEM_VTK, str(discs / "final.snapshot"), "--out", str(tmp_path)])
    assert "wrote 1 step" in result.stdout
    for kind in ("particles", "contacts", "walls"):
        converted = read_vtp(tmp_path / collection(tmp_path / f"{kind}.pvd")[0][1])
        original = read_vtp(last_step(discs, kind))
        assert converted.GetNumberOfPoints() == original.GetNumberOfPoints()
        assert converted.GetNumberOfCells() == original.GetNumberOfCells()
        for where in ("point", "cell"):
            source = original.GetPointData() if where == "point" else original.GetCellData()
            for i in range(source.GetNumberOfArrays()):
                name = source.GetArrayName(i)
                if source.GetArray(i) is None:
                    assert strings(converted, name) == strings(original, name)
                else:
                    np.testing.assert_array_equal(array(converted, name, where), array(original, name, where))


def test_dem_vtk_names_a_file_that_is_not_a_snapshot(discs, tmp_path):
    result = run([DEM_VTK, str(discs / "walls.csv"), "--out", str(tmp_path)], expect=3)
    assert f"{discs / 'walls.csv'}: not a dem snapshot" in result.stderr


def test_dem_run_refuses_a_negative_interval(tmp_path):
    result = run([DEM_RUN, str(CASES / "ball/nine_disc_damped.case.txtpb"), "--out", str(tmp_path),
                  "--vtk-interval", "-5"], expect=2)
    assert "--vtk-interval" in result.stderr
