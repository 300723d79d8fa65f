// demctl record: the server's telemetry into an MCAP file (a ROS 2 bag).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "global.h"

namespace demctl {

struct RecordOptions {
  std::string file;                      // the MCAP file to write
  std::optional<std::uint64_t> samples;  // stop after this many plate forces samples
  std::optional<double> duration;        // stop after this many seconds
};
int record(const Global& global, const RecordOptions& options);
}  // namespace demctl
