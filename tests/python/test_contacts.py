"""Contacts come back as numpy structured arrays of the right shapes, holding
exactly what the C++ client returns: demctl (the C++ client library's own
program) queries the same server at the same moment and writes every value
in the shortest form that reads back to the same double."""

import csv
import os
import subprocess

import numpy as np
import pytest

import dem
from conftest import DOMAINS, case_file
from dem.errors import DemError
from dem.snapshot import State


def demctl_contacts(client, csv_path, *options):
    """The contacts as the C++ client returns them (demctl contacts --csv)."""
    subprocess.run([str(dem.paths.demctl_program()), "--server", client.server, "--domain", str(client.domain),
                    "--timeout", "20", "contacts", "--csv", str(csv_path), "--limit", "0", *options],
                   check=True, capture_output=True, env=os.environ)
    with open(csv_path) as table:
        return list(csv.DictReader(table))


def test_the_contact_array_equals_the_cpp_clients_contacts(serve, out):
    client = serve("contacts_match_the_cpp_client")
    client.load_case(case_file("verification_assembly"))
    # The loose random packing, pressed by four servo walls until it is a
    # few hundred contacts.
    for wall in ("wall1_bottom", "wall2_right", "wall3_top", "wall4_left"):
        client.set_wall_servo(wall, 5e5)
    client.cycle(20000)
    contacts = client.contacts()
    assert contacts.dtype == dem.CONTACT_DTYPE
    assert contacts.ndim == 1 and contacts.shape == (client.state().stats.contacts,)
    assert contacts["point"].shape == (contacts.size, 3) and contacts["normal"].shape == (contacts.size, 3)
    assert contacts.size > 100

    walls = {w.id: w.name for w in client.state().plates.walls}
    rows = demctl_contacts(client, out / "contacts.csv")
    assert len(rows) == contacts.size
    for row, c in zip(rows, contacts):
        assert int(row["first"]) == c["first"]
        if row["second_kind"] == "wall":
            assert c["second_particle"] == -1 and walls[int(c["second_wall"])] == row["second"]
        else:
            assert c["second_wall"] == -1 and int(row["second"]) == c["second_particle"]
        assert [float(row[k]) for k in ("x", "y", "z")] == list(c["point"])
        assert [float(row[k]) for k in ("nx", "ny", "nz")] == list(c["normal"])
        for field in ("overlap", "normal_force", "shear_force", "normal_damping", "shear_damping"):
            assert float(row[field]) == c[field], field
        assert bool(int(row["sliding"])) == c["sliding"]
        assert [float(row[k]) for k in ("tangential_x", "tangential_y", "tangential_z")] == list(c["tangential_force"])
        assert [float(row[k]) for k in ("force_x", "force_y", "force_z")] == list(c["force"])
        assert int(row["formed_cycle"]) == c["formed_cycle"]
    # 2D: z is 0, normals are unit vectors.
    assert np.all(contacts["point"][:, 2] == 0.0)
    np.testing.assert_allclose(np.linalg.norm(contacts["normal"], axis=1), 1.0, rtol=1e-12)

    # A snapshot taken now holds the same contact table: its touching rows,
    # read in Python, are the query's array, value for value.
    data = client.snapshot()
    state = State.from_bytes(data)
    assert state.contacts.dtype == dem.CONTACT_DTYPE
    np.testing.assert_array_equal(state.contacts, contacts)
    # The snapshot's frame refuses a changed byte, rather than reading another state.
    corrupt = bytearray(data)
    corrupt[len(corrupt) // 2] ^= 0x10
    with pytest.raises(DemError, match="corrupt snapshot: its SHA-256 checksum"):
        State.from_bytes(bytes(corrupt))


def test_filters_and_an_empty_result(serve):
    client = serve("contacts_filters")
    client.load_case(case_file("nine_disc_damped"))
    # The discs of the lattice touch without pressing: a contact at cycle 0
    # has no more than a round-off overlap.
    loaded = client.contacts()
    assert loaded.dtype == dem.CONTACT_DTYPE
    assert np.all(loaded["overlap"] < 1e-9 * 50.0)
    dem.run_programme(client, dem.cases.load_case_file(case_file("nine_disc_damped")))

    every = client.contacts()
    assert every.size == 24  # 12 between the discs, 12 with the walls
    top_id = client.state().plates.wall("top").id
    on_top = client.contacts(wall="top")
    assert on_top.shape == (3,) and np.all(on_top["second_wall"] == top_id)
    strong = client.contacts(min_force=float(np.median(every["normal_force"])))
    assert 0 < strong.size < every.size and np.all(strong["normal_force"] > np.median(every["normal_force"]))
    left_half = client.contacts(box=((-1, -1), (150, 301)))
    assert 0 < left_half.size < every.size and np.all(left_half["point"][:, 0] <= 150)
    with pytest.raises(ValueError, match="2 or 3 components"):
        client.contacts(box=((0,), (1, 1)))
    # A particle's contacts by its id: those of the query that name it, and
    # an id the case never had is an error naming it, not another particle.
    middle = client.contacts(particle=4)
    naming = every[(every["first"] == 4) | (every["second_particle"] == 4)]
    assert middle.size == naming.size > 0
    np.testing.assert_array_equal(middle, naming)
    with pytest.raises(DemError, match="no particle 99"):
        client.contacts(particle=99)

    # The state in a snapshot: the nine discs, their radii and the walls.
    state = State.from_bytes(client.snapshot())
    assert state.dimension == 2 and state.cycle == 3000
    assert state.positions.shape == (9, 2) and state.velocities.shape == (9, 2)
    assert state.angular_velocities.shape == (9,) and state.rotations.shape == (9,)
    assert np.all(state.radii == 50.0)
    assert [w.name for w in state.walls] == ["bottom", "right", "top", "left"]
    np.testing.assert_allclose(state.wall("top").normal(), [0.0, -1.0], atol=1e-15)
    assert DOMAINS["contacts_filters"] == client.domain
