// A server's telemetry recorded into an MCAP file the way a ROS 2 bag holds
// it (demctl record): one channel per topic - /dem/<server>/status,
// /plate_forces, /contact_stats and /region_measures - with the ros2msg schema of its
// dem_interfaces message (generated from the IDL, ros2/generate_interfaces.py)
// and each sample's CDR bytes exactly as they came over DDS (encapsulation
// header included), stamped with the time it was received (log time) and
// the server's send time (publish time). The Python client reads it back
// (dem.recording); so do Foxglove and `ros2 bag` (profile "ros2").
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "dem/client/mcap_writer.h"
#include "dem/dds/participant.h"
#include "dem/dds/waitset.h"

namespace dem::client {

class ServerTelemetry;

struct RecordedCounts {
  std::uint64_t status = 0;
  std::uint64_t plate_forces = 0;
  std::uint64_t contact_stats = 0;
  std::uint64_t region_measures = 0;
  std::uint64_t total() const { return status + plate_forces + contact_stats + region_measures; }
};

class TelemetryRecorder {
 public:
  // Creates the file (throws std::runtime_error naming it when it cannot)
  // and subscribes to the server's telemetry; the durable status arrives
  // at once.
  TelemetryRecorder(const dds::Participant& participant, const std::string& server, const std::filesystem::path& file);
  ~TelemetryRecorder();

  // Waits until the server's status and telemetry writers are matched (so
  // nothing it publishes from now on is missed); false after the timeout.
  bool wait_for_publishers(std::chrono::milliseconds timeout);
  // Waits up to `timeout` for samples and writes those that came.
  void poll(std::chrono::milliseconds timeout);
  // Writes what is still in the readers, then the file's summary.
  void close();

  const RecordedCounts& counts() const { return counts_; }
  const std::filesystem::path& path() const { return file_.path(); }

 private:
  McapWriter file_;
  std::unique_ptr<ServerTelemetry> telemetry_;
  dds::WaitSet waitset_;
  std::array<std::uint16_t, 4> channels_{};  // by Stream
  RecordedCounts counts_;
  std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace dem::client
