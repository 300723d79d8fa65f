// demctl's command line: each subcommand's options and, once they are
// parsed, the command (commands.h, monitor.h, record.h) it runs.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

#include "global.h"

namespace demctl {

// What the parsed command line asks for; returns an exit code (exit_codes.h).
using Action = std::function<int()>;

// Adds every subcommand to app; parsing the one the command line names
// sets action. global is read when the action runs.
void add_subcommands(CLI::App& app, const Global& global, Action& action);

}  // namespace demctl
