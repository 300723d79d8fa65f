"""dem: the Python client of dem_server (docs/PYTHON.md).

The C++ client library (dem::client) through pybind11 (dem._client), with a
Pythonic layer around it: connect to a named server, send commands and await
their replies, subscribe to telemetry, receive contacts as numpy arrays; cases
built with the protobuf-generated classes (dem.cases) or read from text; a
case's stages run through the service (dem.programme); the seeds' figures
(dem.plots).

    import dem
    with dem.ServerProcess("press", domain=21, out="out/press") as server, server.connect() as press:
        press.load_case("cases/ball/nine_disc_damped.case.txtpb")
        press.set_wall_velocity("top", (0, -0.5))     # lower the top wall at 0.5 m/s
        press.run_until(wall="top", stress=1e6, max_cycles=2000)   # until it carries 1 MPa
        contacts = press.contacts(wall="top")
"""

from . import _build_info

try:
    from . import cases, errors
    from ._client import (CONTACT_DTYPE, ContactStats, PlateForces, RegionMeasures, RegionTelemetry, Reply, Status,
                          WallForce)
except ModuleNotFoundError as missing:
    from ._interpreter import dependency_hint

    raise ImportError(dependency_hint(missing)) from missing
from .client import Client, list_servers
from .errors import (CaseFileError, DdsError, DemError, InterfaceMismatch, NoSuchServer, ProgrammeError,
                     ReplyTimeout, ServerError)
from .paths import use_loopback
from .programme import run_programme
from .server_process import ServerProcess
from .telemetry import Subscription

# The project's version (CMakeLists.txt's project(VERSION)), as every program's --version.
__version__ = _build_info.VERSION

__all__ = [
    "CONTACT_DTYPE",
    "CaseFileError",
    "Client",
    "ContactStats",
    "DdsError",
    "DemError",
    "InterfaceMismatch",
    "NoSuchServer",
    "PlateForces",
    "ProgrammeError",
    "RegionMeasures",
    "RegionTelemetry",
    "Reply",
    "ReplyTimeout",
    "ServerError",
    "ServerProcess",
    "Status",
    "Subscription",
    "WallForce",
    "cases",
    "errors",
    "list_servers",
    "run_programme",
    "use_loopback",
]
