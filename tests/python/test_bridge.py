"""dem.bridge end to end: a dem_server loading its top wall, the bridge on
the same DDS domain, and its two kinds of client - its own page in headless
Chromium (Debian's chromium and chromium-driver through python3-selenium),
which must show the stress-settlement curve growing while the server runs,
and a Foxglove WebSocket client from the npm registry (@foxglove/ws-protocol),
which must be offered the server's channels with their ros2msg schemas and
receive its plate forces as CDR that decodes to the samples of the run.

Environment (ctest): DEM_NPM_DIR, where tests/npm/install.sh put the npm
packages and scripts.
"""

import asyncio
import base64
import json
import os
import pathlib
import signal
import subprocess
import sys
import tempfile
import time

import pytest

from dem import _schemas
from dem.recording import CdrDecoder

from conftest import DOMAINS, case_file

NPM_DIR = pathlib.Path(os.environ.get("DEM_NPM_DIR", ""))


@pytest.fixture
def bridged(serve, request):
    """A server with the nine-disc test loaded, and a bridge for its domain:
    (client, server name, bridge URL)."""
    key = request.param
    press = serve(key, telemetry_cycles=10)
    press.load_case(case_file("nine_disc_damped"))
    bridge = subprocess.Popen([sys.executable, "-m", "dem.bridge", "--domain", str(DOMAINS[key]), "--port", "0"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = bridge.stdout.readline()
    assert "dashboard http://" in line, line + bridge.stderr.read()
    url = line.split("dashboard ")[1].split(" ")[0]
    yield press, f"py_{key}", url
    bridge.send_signal(signal.SIGTERM)
    assert bridge.wait(timeout=20) == 0, bridge.stderr.read()


def load_the_top_wall(press):
    """Lowers the top wall to 1 MPa: about 70 cycles, telemetry every 10."""
    press.set_wall_velocity("top", (0, -0.5))
    return press.run_until(wall="top", stress=1e6, max_cycles=2000)


@pytest.fixture
def chromium():
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    # Chromium writes into ~/.config, ~/.cache and /tmp unless told otherwise
    # (../shared/BROWSER.md): a directory of this test's own, short enough
    # for the unix sockets Chromium makes in it (108 characters at most).
    with tempfile.TemporaryDirectory(prefix="dem-chromium-", dir="/tmp") as home:
        env = dict(os.environ, TMPDIR=home, XDG_CONFIG_HOME=home, XDG_CACHE_HOME=home, HOME=home)
        options = webdriver.ChromeOptions()
        options.binary_location = "/usr/bin/chromium"
        for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1200,900"):
            options.add_argument(argument)
        driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver", env=env), options=options)
        try:
            yield driver
        finally:
            driver.quit()


def wait_for(driver, script, timeout=30.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = driver.execute_script(script)
        if value:
            return value
        time.sleep(0.1)
    raise AssertionError(f"in {timeout} s the page never gave: {script}")


@pytest.mark.parametrize("bridged", ["bridge_page"], indirect=True)
def test_the_page_shows_the_curve_growing_while_the_server_runs(bridged, chromium, tmp_path):
    press, server, url = bridged
    driver = chromium
    driver.get(url)
    assert wait_for(driver, "return window.demDashboard && window.demDashboard.protocol") == \
        "foxglove.websocket.v1"
    wait_for(driver, f"return document.getElementById('server-{server}') !== null")
    assert driver.execute_script(f"return window.demDashboard.points('{server}', 'top')") == 0
    reply = load_the_top_wall(press)
    assert reply.condition_met
    # A sample every 10 cycles of the loading and the last at its end
    # (about 70 cycles: 0.005 m a cycle to 1 MPa).
    end = reply.state.cycle
    assert 50 < end < 100
    expected = list(range(10, end, 10)) + [end]
    wait_for(driver, f"return window.demDashboard.points('{server}', 'top') >= {len(expected)}")
    seen = driver.execute_script(f"return window.demDashboard.servers['{server}'].walls.top")
    assert [p["cycle"] for p in seen] == expected
    top = next(w for w in press.state().plates.walls if w.name == "top")
    assert seen[-1]["y"] == top.normal_stress / 1000  # kPa, the same double
    # The status and statistics lines follow the server.
    status = driver.find_element("css selector", f"#server-{server} .status").text
    assert "nine_disc_damped" in status and f"cycle {end}" in status
    contacts = press.state().stats.contacts
    assert f"cycle {end}: {contacts} contacts" in driver.find_element("css selector", f"#server-{server} .stats").text
    # And the chart is drawn: pixels of the top wall's colour (#1f77b4) on its canvas.
    time.sleep(0.5)  # the charts redraw four times a second
    drawn = driver.execute_script(f"""
        const canvas = document.querySelector('#server-{server} canvas');
        const pixels = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
        let count = 0;
        for (let i = 0; i < pixels.length; i += 4)
          if (Math.abs(pixels[i] - 0x1f) < 30 && Math.abs(pixels[i + 1] - 0x77) < 30 &&
              Math.abs(pixels[i + 2] - 0xb4) < 30 && pixels[i + 3] > 200) count++;
        return count;""")
    assert drawn > 100, f"{drawn} pixels of the top wall's curve"
    driver.save_screenshot(str(tmp_path / "dashboard.png"))


@pytest.mark.skipif(not (NPM_DIR / "node_modules").is_dir(), reason="the npm packages are not installed "
                    "(ctest runs tests/npm/install.sh first)")
@pytest.mark.parametrize("bridged", ["bridge_foxglove"], indirect=True)
def test_a_foxglove_client_from_npm_receives_the_channels_and_messages(bridged):
    press, server, url = bridged
    ws_url = url.replace("http://", "ws://").rstrip("/")
    client = subprocess.Popen(["node", str(NPM_DIR / "foxglove_client.mjs"), ws_url, "/plate_forces", "6"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = client.stderr.readline()
    assert line.startswith(f"subscribed to /dem/{server}/plate_forces"), line + client.stderr.read()
    time.sleep(0.2)  # the subscribe request on its way to the bridge
    load_the_top_wall(press)
    stdout, stderr = client.communicate(timeout=90)
    assert client.returncode == 0, stderr
    seen = json.loads(stdout)
    assert seen["protocol"] == "foxglove.websocket.v1"
    assert seen["serverInfo"]["name"] == "dem bridge"
    topics = {c["topic"]: c for c in seen["channels"]}
    assert set(topics) == {f"/dem/{server}/status", f"/dem/{server}/plate_forces", f"/dem/{server}/contact_stats",
                           f"/dem/{server}/region_measures"}
    for channel in topics.values():
        assert channel["encoding"] == "cdr" and channel["schemaEncoding"] == "ros2msg"
        assert channel["schema"] == _schemas.SCHEMAS[channel["schemaName"]]
    decoder = CdrDecoder("dem_interfaces/msg/PlateForces", topics[f"/dem/{server}/plate_forces"]["schema"])
    samples = [decoder.decode(base64.b64decode(m["data"])) for m in seen["messages"]]
    assert [s.cycle for s in samples] == [10, 20, 30, 40, 50, 60]
    assert {s.server for s in samples} == {server}
    top = [next(w for w in s.walls if w.name == "top") for s in samples]
    assert all(b.settlement > a.settlement for a, b in zip(top, top[1:]))  # the wall goes down
    assert int(seen["messages"][0]["receiveTime"]) > 1.6e18  # ns since the epoch


@pytest.mark.parametrize("bridged", ["bridge_foxglove"], indirect=True)
def test_a_request_the_bridge_does_not_take_gets_a_warning(bridged):
    import websockets

    _, _, url = bridged

    async def talk():
        async with websockets.connect(url.replace("http://", "ws://"), subprotocols=["foxglove.websocket.v1"]) as ws:
            assert json.loads(await ws.recv())["op"] == "serverInfo"
            await ws.send(json.dumps({"op": "publish"}))
            while True:
                message = json.loads(await ws.recv())
                if message["op"] == "status":
                    return message

    status = asyncio.run(asyncio.wait_for(talk(), 20))
    assert status["level"] == 1 and "does not take publish" in status["message"]
