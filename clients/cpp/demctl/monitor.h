// demctl monitor: the plates' stress and settlement as a live table, of one
// server, a sweep's or every server of the domain.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "global.h"

namespace demctl {

struct MonitorOptions {
  std::optional<std::uint64_t> samples;  // stop after this many rows; default: until Ctrl-C
  std::string csv;                       // record the rows here too
  std::vector<std::string> walls;        // the plates to show; default: every wall
  std::string sweep;                     // follow every server of this sweep (<sweep>_<task>) instead of one
  bool all = false;                      // follow every server of the domain instead of one
  double idle_exit = 0.0;                // with sweep or all: end once no such server was there for this long, s
};
int monitor(const Global& global, const MonitorOptions& options);
}  // namespace demctl
