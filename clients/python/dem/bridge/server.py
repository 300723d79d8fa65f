"""The bridge between DDS and browsers: every dem_server's telemetry on a DDS
domain (dem._client.TelemetryTap: status, plate forces and contact
statistics as the CDR bytes on the wire) served over WebSocket with the
Foxglove WebSocket protocol (foxglove.websocket.v1, its public
specification) - one channel per topic, its ros2msg schema generated from
the IDL, its messages the CDR as they came - so Foxglove connects to it;
and, on the same port, over plain HTTP, the bridge's own dashboard page
(static/), which speaks the same protocol.

    bridge = Bridge(domain=7, port=8765)
    asyncio.run(bridge.serve())     # until bridge.stop()

Channels come when a server appears on the domain (advertise) and go when
it leaves (unadvertise); with `sweep`, only that sweep's servers. A client that reads slower than telemetry comes
loses the oldest messages queued for it, never the others'.
"""

import asyncio
import http
import itertools
import json
import mimetypes
import pathlib
import re
import struct
import threading
import time

import websockets

from .. import _schemas
from .._client import TelemetryTap

SUBPROTOCOL = "foxglove.websocket.v1"
MESSAGE_DATA = 0x01  # the binary opcode of a message (Foxglove WebSocket protocol)
STATIC = pathlib.Path(__file__).resolve().parent / "static"
# Debian's libjs-chart.js: the page's charts.
CHART_JS = pathlib.Path("/usr/share/javascript/chart.js/chart.min.js")
CLIENT_QUEUE = 10000  # messages waiting for one client before its oldest go


class Channel:
    def __init__(self, channel_id, server, topic, schema_name):
        self.id = channel_id
        self.server = server
        self.topic = topic
        self.schema_name = schema_name

    def advertisement(self):
        return {"id": self.id, "topic": self.topic, "encoding": "cdr", "schemaName": self.schema_name,
                "schema": _schemas.SCHEMAS[self.schema_name], "schemaEncoding": "ros2msg"}


class Client:
    """One WebSocket connection: its subscriptions and its outgoing queue."""

    def __init__(self, websocket):
        self.websocket = websocket
        self.subscriptions = {}  # subscription id -> channel id
        self.queue = asyncio.Queue()
        self.dropped = 0

    def put(self, item):
        if self.queue.qsize() >= CLIENT_QUEUE:
            self.queue.get_nowait()
            self.dropped += 1
        self.queue.put_nowait(item)


class Bridge:
    def __init__(self, domain, *, host="127.0.0.1", port=8765, dds_config="", name="dem bridge", sweep=None):
        self.domain = domain
        # With a sweep's name, only its servers (<sweep>_<task>; docs/SWEEPS.md).
        self.sweep = sweep
        self._follows = re.compile(re.escape(sweep) + r"_[0-9]+").fullmatch if sweep else (lambda server: True)
        self.host = host
        self.port = port
        self.dds_config = dds_config
        self.name = name
        self.channels = {}  # topic -> Channel
        self.clients = set()
        self.messages_forwarded = 0
        self._ids = itertools.count(1)
        self._stopping = threading.Event()
        self._stopped = None
        self._loop = None

    # --- the DDS side: a thread of its own, handing samples to the loop ---

    def _tap_loop(self, tap):
        while not self._stopping.is_set():
            samples = tap.take(0.2)
            servers = [server for server in tap.servers() if self._follows(server)]
            self._loop.call_soon_threadsafe(self._on_samples, servers, samples)

    def _on_samples(self, servers, samples):
        self._update_channels(servers)
        for _, topic, _, data, log_time, _ in samples:
            channel = self.channels.get(topic)
            if channel is None:  # a sample of a server that has just gone
                continue
            for client in self.clients:
                for subscription, channel_id in client.subscriptions.items():
                    if channel_id == channel.id:
                        header = struct.pack("<BIQ", MESSAGE_DATA, subscription, log_time)
                        client.put(header + data)
                        self.messages_forwarded += 1

    def _update_channels(self, servers):
        current = {channel.server for channel in self.channels.values()}
        gone = [c for c in self.channels.values() if c.server not in servers]
        if gone:
            for channel in gone:
                del self.channels[channel.topic]
                for client in self.clients:
                    for subscription in [s for s, c in client.subscriptions.items() if c == channel.id]:
                        del client.subscriptions[subscription]
            self._broadcast({"op": "unadvertise", "channelIds": [c.id for c in gone]})
        added = []
        for server in servers:
            if server in current:
                continue
            for topic, type_name in TelemetryTap.topics(server):
                channel = Channel(next(self._ids), server, topic, type_name)
                self.channels[topic] = channel
                added.append(channel)
        if added:
            self._broadcast({"op": "advertise", "channels": [c.advertisement() for c in added]})

    def _broadcast(self, message):
        text = json.dumps(message)
        for client in self.clients:
            client.put(text)

    # --- the WebSocket and HTTP side ---

    async def _http(self, path, headers):
        """The page and its scripts for a browser; None lets a WebSocket handshake go on."""
        if headers.get("Upgrade", "").lower() == "websocket":
            return None
        path = path.split("?", 1)[0]
        if path == "/":
            path = "/index.html"
        if path == "/chart.js":
            file = CHART_JS
        else:
            file = STATIC / path.lstrip("/")
            if file.parent != STATIC or not file.is_file():
                return http.HTTPStatus.NOT_FOUND, [("Content-Type", "text/plain")], b"not found\n"
        if not file.is_file():
            return (http.HTTPStatus.NOT_FOUND, [("Content-Type", "text/plain")],
                    f"{file} is missing (Debian's libjs-chart.js)\n".encode())
        content_type = mimetypes.guess_type(file.name)[0] or "application/octet-stream"
        return http.HTTPStatus.OK, [("Content-Type", content_type), ("Cache-Control", "no-store")], file.read_bytes()

    async def _connection(self, websocket, path=None):
        client = Client(websocket)
        self.clients.add(client)
        client.put(json.dumps({"op": "serverInfo", "name": self.name, "capabilities": [],
                               "supportedEncodings": [], "metadata": {"domain": str(self.domain)},
                               "sessionId": str(time.time_ns())}))
        if self.channels:
            client.put(json.dumps({"op": "advertise",
                                   "channels": [c.advertisement() for c in self.channels.values()]}))
        sender = asyncio.create_task(self._send(client))
        try:
            async for message in websocket:
                self._request(client, message)
        except websockets.ConnectionClosed:
            pass
        finally:
            self.clients.discard(client)
            sender.cancel()

    async def _send(self, client):
        try:
            while True:
                await client.websocket.send(await client.queue.get())
        except (websockets.ConnectionClosed, asyncio.CancelledError):
            pass

    def _request(self, client, message):
        """subscribe and unsubscribe (text JSON); anything else is answered with a warning status."""
        try:
            request = json.loads(message) if isinstance(message, str) else None
            op = request.get("op") if isinstance(request, dict) else None
            if op == "subscribe":
                channels = {c.id for c in self.channels.values()}
                for subscription in request["subscriptions"]:
                    if subscription["channelId"] in channels:
                        client.subscriptions[int(subscription["id"])] = int(subscription["channelId"])
                    else:
                        self._warn(client, f"no channel {subscription['channelId']}")
            elif op == "unsubscribe":
                for subscription in request["subscriptionIds"]:
                    client.subscriptions.pop(int(subscription), None)
            else:
                self._warn(client, f"this bridge does not take {op or 'that message'} (it takes subscribe and "
                                   "unsubscribe)")
        except (KeyError, TypeError, ValueError) as error:
            self._warn(client, f"a malformed request: {error}")

    def _warn(self, client, text):
        client.put(json.dumps({"op": "status", "level": 1, "message": text}))

    async def serve(self, ready=None):
        """Serves until stop(); `ready(url)` is called once it listens."""
        self._loop = asyncio.get_running_loop()
        self._stopped = asyncio.Event()
        tap = await asyncio.to_thread(TelemetryTap, self.domain, self.dds_config)
        reader = threading.Thread(target=self._tap_loop, args=(tap,), name="dem-bridge-tap", daemon=True)
        async with websockets.serve(self._connection, self.host, self.port, subprotocols=[SUBPROTOCOL],
                                    process_request=self._http, compression=None) as server:
            self.port = server.sockets[0].getsockname()[1]
            reader.start()
            if ready:
                ready(self.url)
            await self._stopped.wait()
        self._stopping.set()
        await asyncio.to_thread(reader.join)

    def stop(self):
        """From any thread: ends serve()."""
        if self._loop is not None:
            self._loop.call_soon_threadsafe(self._stopped.set)

    @property
    def url(self):
        return f"http://{self.host}:{self.port}/"
