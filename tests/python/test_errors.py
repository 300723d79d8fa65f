"""A server's error reply becomes dem.ServerError carrying its status and the
server's own message; no server, dem.NoSuchServer; no reply in time,
dem.ReplyTimeout; and an interrupted wait stops the run it waited for."""

import _thread
import threading
import time

import pytest

import dem
from conftest import DOMAINS, case_file


def test_error_replies_carry_the_servers_status_and_message(serve):
    client = serve("errors_server_messages")
    with pytest.raises(dem.ServerError) as refused:
        client.cycle(10)
    assert refused.value.status == "refused"
    assert refused.value.command == "cycle"
    assert refused.value.message == "cycle refused: no case is loaded: load a case or a snapshot first"

    client.load_case(case_file("nine_disc_damped"))
    before = client.state().state_hash
    with pytest.raises(dem.ServerError) as unknown:
        client.set_wall_velocity("roof", (0, -1))
    assert unknown.value.status == "not_found"
    assert unknown.value.message == 'no wall "roof" (walls: bottom, right, top, left)'
    assert str(unknown.value) == 'set_wall_velocity -> not_found: no wall "roof" (walls: bottom, right, top, left)'
    assert unknown.value.reply.status == "not_found"

    with pytest.raises(dem.ServerError) as negative:
        client.cycle(-5)
    assert negative.value.status == "bad_request"
    assert negative.value.message == "cycle.cycles: must be > 0, got -5"

    with pytest.raises(dem.ServerError) as invalid:
        client.load_case(text='material { name: "x" }\nwall { name: "w" h1: 1 h2: 1 material: "x" }\n',
                         source_name="broken.case.txtpb")
    assert invalid.value.status == "invalid_case"
    assert "broken.case.txtpb:2:" in invalid.value.message
    assert "wall[0].h2: must be greater than h1" in invalid.value.message

    with pytest.raises(dem.ServerError) as garbage:
        client.load_snapshot(b"not a snapshot")
    assert garbage.value.status == "invalid_snapshot"

    # Bad input changed nothing, and the server still serves.
    assert client.state().state_hash == before
    assert client.cycle(10).cycles_run == 10
    found = dict(dem.list_servers(client.domain))
    assert found[client.server].case_name == "nine_disc_damped"


def test_a_reply_that_does_not_come_in_time_and_an_interrupted_wait(serve):
    client = serve("errors_timeouts_and_interrupts")
    client.load_case(case_file("verification_assembly"))
    # A run far too long for its timeout: ReplyTimeout, and the run goes on
    # (as with the C++ client) until stopped.
    started = time.monotonic()
    with pytest.raises(dem.ReplyTimeout, match='no reply from server "py_errors_timeouts_and_interrupts" to cycle'):
        client.cycle(10 ** 9, timeout=0.5)
    assert 0.4 < time.monotonic() - started < 5.0
    assert client.status.state == "running"
    assert "stopped cycle" in client.stop().message

    # An exception raised while waiting (as Ctrl-C raises KeyboardInterrupt)
    # stops the run on the server before it propagates.
    class Interrupted(Exception):
        pass

    deadline = time.monotonic() + 0.5

    def interrupt():
        if time.monotonic() > deadline:
            raise Interrupted

    with pytest.raises(Interrupted):
        client.cycle(10 ** 9, on_wait=interrupt)
    assert client.wait_for_status(lambda s: s.state == "loaded", timeout=5.0) is not None
    assert client.state().state.command == ""

    # Ctrl-C itself: SIGINT's KeyboardInterrupt surfaces from the wait, and
    # the run is stopped as demctl stops it.
    threading.Timer(0.5, _thread.interrupt_main).start()
    with pytest.raises(KeyboardInterrupt):
        client.run_until(wall="wall3_top", stress=1e30, max_cycles=10 ** 9)
    assert client.wait_for_status(lambda s: s.state == "loaded", timeout=5.0) is not None


def test_no_such_server():
    started = time.monotonic()
    with pytest.raises(dem.NoSuchServer, match=f'no server "nobody" on DDS domain {DOMAINS["errors_no_server"]}'):
        dem.Client("nobody", DOMAINS["errors_no_server"], timeout=0.5)
    assert time.monotonic() - started < 5.0
    with pytest.raises(ValueError, match="is not a server name"):
        dem.Client("not a name", DOMAINS["errors_no_server"], timeout=0.5)
