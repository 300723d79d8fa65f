"""dem.bridge: the servers of a DDS domain in a browser - the Foxglove
WebSocket protocol for Foxglove and other clients, and a dashboard page of
its own (the loading plates' stress-settlement curves growing live,
contact statistics, status), on one port.

    python3 -m dem.bridge --domain 7            # http://127.0.0.1:8765/ ; Foxglove: ws://127.0.0.1:8765
"""

from .server import Bridge, SUBPROTOCOL

__all__ = ["Bridge", "SUBPROTOCOL"]
