"""What can go wrong when talking to a dem_server, as exceptions a program can
tell apart. The C++ client's exceptions are turned into these by the
extension module (clients/python/src/errors.cpp)."""


class DemError(Exception):
    """Base of every error of the dem package."""


class NoSuchServer(DemError):
    """No server of that name answered on the domain within the timeout."""


class InterfaceMismatch(DemError):
    """The server was found, but its interface and this client's cannot meet:
    its commands or replies are of an older or newer dem_interfaces (the
    message names the versions and the fields; docs/DDS.md)."""


class ReplyTimeout(DemError, TimeoutError):
    """The server was found, but its (complete) reply did not come in time."""


class DdsError(DemError):
    """Cyclone DDS refused an operation (its message names the action)."""


class ServerError(DemError):
    """The server answered a command with an error status.

    ``status`` is the reply's status (``"not_found"``, ``"invalid_case"``,
    ``"refused"``, ...), ``message`` the server's own message, ``command``
    the command's kind and ``reply`` the whole reply.
    """

    def __init__(self, status, message, command, reply=None):
        super().__init__(f"{command} -> {status}: {message}")
        self.status = status
        self.message = message
        self.command = command
        self.reply = reply


class CaseFileError(DemError):
    """A case file does not parse; the message names the file, line and column."""


class ProgrammeError(DemError):
    """A programme's stages asked for do not make a run (dem.run_programme)."""
