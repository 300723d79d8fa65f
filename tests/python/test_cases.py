"""Cases built in Python with the protobuf classes, or read from text format,
loaded into dem_server: a disc dropped on a floor comes to rest carrying
its weight."""

import math

import pytest

import dem
from conftest import case_file


def dropped_disc():
    """One disc of radius 0.1 m dropped 0.05 m onto a floor, damped (2D)."""
    case = dem.cases.Case(name="dropped_disc", description="a disc falls on a floor and comes to rest")
    case.material.add(name="rock", density=2000, friction=0.5)
    case.contact_model.add().linear.CopyFrom(dem.cases.case_pb2.LinearLaw(normal_stiffness=1e7,
                                                                          shear_stiffness=1e7))
    disc = case.particles.add().particle
    disc.position.x, disc.position.y = 0.0, 0.15
    disc.radius = 0.1
    disc.material = "rock"
    case.wall.add(name="floor", angle_deg=0, h1=-1, h2=1, material="rock")
    case.gravity.y = -9.81
    case.damping.global_alpha = 20
    case.time_step.fraction = 0.2
    return case


def test_a_case_built_in_python_runs_on_the_server(serve):
    client = serve("cases_built_in_python")
    case = dropped_disc()
    reply = client.load_case(case)
    assert reply.state.case_name == "dropped_disc" and reply.state.particles == 1 and reply.state.walls == 1
    done = client.run_until(kinetic_energy=1e-12, max_cycles=200000, check_interval=100)
    assert done.condition_met, done.message
    floor = client.state().plates.wall("floor")
    weight = 2000 * math.pi * 0.1 ** 2 * 9.81  # per unit depth: the disc has unit thickness
    assert floor.normal_force == pytest.approx(weight, rel=1e-4)
    assert floor.normal_stress == pytest.approx(weight / 2.0, rel=1e-4)  # the floor is 2 m long
    contact = client.contacts(wall="floor")
    assert contact.shape == (1,) and contact["normal_force"][0] == pytest.approx(weight, rel=1e-4)

    # The same case through text format loads to the same state.
    text = dem.cases.to_text(case)
    assert dem.cases.from_text(text) == case
    client.load_case(text=text, source_name="dropped_disc.case.txtpb")
    assert client.state().state.particles == 1


def test_case_files_and_their_errors(serve, tmp_path):
    case = dem.cases.load_case_file(case_file("nine_disc_damped"))
    assert case.name == "nine_disc_damped" and len(case.stage) == 2
    assert dem.cases.wall_named(case, "top").angle_deg == 180
    with pytest.raises(KeyError, match='no wall "roof" \\(walls: bottom, right, top, left\\)'):
        dem.cases.wall_named(case, "roof")

    broken = tmp_path / "broken.case.txtpb"
    broken.write_text('name: "broken"\nmaterial { name: "x" densty: 1 }\n')
    with pytest.raises(dem.CaseFileError, match=f"{broken}:2:.*densty"):
        dem.cases.load_case_file(broken)
    with pytest.raises(dem.CaseFileError, match="cannot read case file"):
        dem.cases.load_case_file(tmp_path / "missing.case.txtpb")

    # Parsed, but wrong: the server's validation names the field.
    client = serve("cases_invalid")
    bad = dropped_disc()
    bad.particles[0].particle.radius = -1
    with pytest.raises(dem.ServerError) as invalid:
        client.load_case(bad)
    assert invalid.value.status == "invalid_case"
    assert "particles[0].particle.radius" in invalid.value.message
    assert client.status.state == "idle"
