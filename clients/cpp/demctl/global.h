// What every demctl subcommand shares: the global options, how they
// become a connection, and what a bad command line is.
#pragma once

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "dem/client/client.h"

namespace demctl {
// A command line that parses but makes no sense (exit code 2).
class BadArguments : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Options every subcommand takes.
struct Global {
  std::string server = "dem";
  std::uint32_t domain = 0;
  std::string dds_config;
  double timeout = 5.0;  // s, to find the server and for each reply
  bool quiet = false;    // no progress bar
};

dem::client::ConnectOptions connect_options(const Global& global);
// Whether a server belongs to a sweep: a sweep's servers are named <sweep>_<task>, the task a number (docs/SWEEPS.md).
bool in_sweep(const std::string& server, const std::string& sweep);
// Seconds from the command line as a timeout.
std::chrono::milliseconds milliseconds(double seconds);

}  // namespace demctl
