// demctl's subcommands, each a function of the parsed command line that
// returns an exit code (exit_codes.h); errors travel as exceptions to main.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dem/client/client.h"
#include "global.h"

namespace demctl {

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

}  // namespace demctl
