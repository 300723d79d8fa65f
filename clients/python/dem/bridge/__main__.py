"""python3 -m dem.bridge --domain ID [--host H] [--port P] [--dds-config X] [--sweep NAME]:
serves every dem_server's telemetry on the domain (or a sweep's) to browsers (docs/DASHBOARD.md).
Prints its URL, then serves until Ctrl-C or SIGTERM. Exit codes: 0 stopped,
2 bad arguments, 1 it could not start (the message says why)."""

import argparse
import asyncio
import signal
import sys

from .. import __version__
from ..paths import use_loopback
from .server import Bridge


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m dem.bridge", description=__doc__.split("\n\n")[0])
    parser.add_argument("--domain", type=int, default=0, help="DDS domain id of the servers (default 0)")
    parser.add_argument("--host", default="127.0.0.1", help="address to listen on (default 127.0.0.1: this machine only)")
    parser.add_argument("--port", type=int, default=8765, help="TCP port (default 8765; 0: any free one)")
    parser.add_argument("--dds-config", default="", help="Cyclone DDS configuration (default $CYCLONEDDS_URI, else "
                                                         "the loopback-only configuration)")
    parser.add_argument("--sweep", help="only the servers of this sweep (named <sweep>_<task>; docs/SWEEPS.md)")
    parser.add_argument("--version", action="version", version=f"dem.bridge {__version__}")
    args = parser.parse_args(argv)
    if not 0 <= args.domain <= 232:
        parser.error(f"--domain must be 0-232, got {args.domain}")
    use_loopback()
    bridge = Bridge(args.domain, host=args.host, port=args.port, dds_config=args.dds_config, sweep=args.sweep)

    def ready(url):
        ws_url = url.replace("http://", "ws://").rstrip("/")
        print(f"dem bridge for DDS domain {args.domain}: dashboard {url} ; Foxglove WebSocket {ws_url}", flush=True)

    async def run():
        loop = asyncio.get_running_loop()
        for signal_number in (signal.SIGINT, signal.SIGTERM):
            loop.add_signal_handler(signal_number, bridge.stop)
        await bridge.serve(ready)

    try:
        asyncio.run(run())
    except OSError as error:
        sys.exit(f"dem.bridge: cannot serve on {args.host}:{args.port}: {error}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
