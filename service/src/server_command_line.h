// dem_server's command line, and the environment variables that stand for
// its options (a container or a batch script configures it that way).
#pragma once

#include <string>
#include <variant>

#include "dem/service/options.h"

namespace dem::service {

// dem_server's exit codes (main.cpp's header says when each is given).
enum ServerExit : int {
  kServerDone = 0,
  kServerFailure = 1,
  kServerBadArguments = 2,
  kServerBadCase = 3,
  kServerStopped = 4,
  kServerNameInUse = 5,
};

struct ServerCommandLine {
  ServerOptions options;
  std::string log_level = "info";
};

// The options asked for, or the exit code when the program ends at once
// (--help, --version: 0; a bad argument: kServerBadArguments, said on stderr).
std::variant<ServerCommandLine, int> parse_server_command_line(int argc, char** argv);

}  // namespace dem::service
