// demctl's subcommands, each a function of the parsed command line that
// returns an exit code (exit_codes.h); errors travel as exceptions to main.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

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

// The servers on the domain; with `sweep`, those of that sweep only (named <sweep>_<task>).
int servers(const Global& global, double discovery, const std::string& sweep = {});
int status(const Global& global, bool json = false);
int load(const Global& global, const std::string& file, bool on_server, bool binary);
int wall_velocity(const Global& global, const std::string& wall, const std::vector<double>& values);
int servo(const Global& global, const std::string& wall, double stress, double gain, double max_speed);
int cycle(const Global& global, std::int64_t cycles, bool wait);
int run_until(const Global& global, const dem::protocol::RunUntilArgs& args, bool wait);
int run_programme(const Global& global, std::uint32_t first_stage, std::uint32_t stage_count, bool wait);
int stop(const Global& global, bool force);
int contacts(const Global& global, const dem::protocol::ContactQueryArgs& query, const std::string& csv, int limit);
int snapshot_save(const Global& global, const std::string& file, bool on_server);
int snapshot_load(const Global& global, const std::string& file, bool on_server);
int set(const Global& global, const std::string& parameter, const std::string& value);
int shutdown(const Global& global, bool wait, bool force);

struct MonitorOptions {
  std::optional<std::uint64_t> samples;  // stop after this many rows; default: until Ctrl-C
  std::string csv;                       // record the rows here too
  std::vector<std::string> walls;        // the plates to show; default: every wall
  std::string sweep;                     // follow every server of this sweep (<sweep>_<task>) instead of one
  bool all = false;                      // follow every server of the domain instead of one
  double idle_exit = 0.0;                // with sweep or all: end once no such server was there for this long, s
};
int monitor(const Global& global, const MonitorOptions& options);

struct RecordOptions {
  std::string file;                      // the MCAP file to write
  std::optional<std::uint64_t> samples;  // stop after this many plate forces samples
  std::optional<double> duration;        // stop after this many seconds
};
int record(const Global& global, const RecordOptions& options);

}  // namespace demctl
