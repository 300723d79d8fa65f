// A server's telemetry recorded into an MCAP file the way a ROS 2 bag holds
// it (demctl record): one channel per topic - /dem/<server>/status,
// /plate_forces and /contact_stats - with the ros2msg schema of its
// dem_interfaces message (generated from the IDL, ros2/generate_interfaces.py)
// and each sample's CDR bytes exactly as they came over DDS (encapsulation
// header included), stamped with the time it was received (log time) and
// the server's send time (publish time). The Python client reads it back
// (dem.recording); so do Foxglove and `ros2 bag` (profile "ros2").
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>

#include "dem/client/mcap_writer.h"
#include "dem/dds/participant.h"
#include "dem/dds/serialized_reader.h"
#include "dem/dds/waitset.h"
#include "dem/protocol/messages.h"
#include "dem/protocol/type_support.h"

namespace dem::client {

struct RecordedCounts {
  std::uint64_t status = 0;
  std::uint64_t plate_forces = 0;
  std::uint64_t contact_stats = 0;
  std::uint64_t total() const { return status + plate_forces + contact_stats; }
};

class TelemetryRecorder {
 public:
  // Creates the file (throws std::runtime_error naming it when it cannot)
  // and subscribes to the server's telemetry; the durable status arrives
  // at once.
  TelemetryRecorder(const dds::Participant& participant, const std::string& server, const std::filesystem::path& file);

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
  std::uint64_t write_all(dds::SerializedReader& reader, std::uint16_t channel);

  McapWriter file_;
  dds::Topic<protocol::Status> status_topic_;
  dds::Topic<protocol::PlateForces> plates_topic_;
  dds::Topic<protocol::ContactStats> stats_topic_;
  dds::SerializedReader status_reader_;
  dds::SerializedReader plates_reader_;
  dds::SerializedReader stats_reader_;
  dds::ReadCondition status_data_;
  dds::ReadCondition plates_data_;
  dds::ReadCondition stats_data_;
  dds::WaitSet waitset_;
  std::uint16_t status_channel_;
  std::uint16_t plates_channel_;
  std::uint16_t stats_channel_;
  RecordedCounts counts_;
  std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace dem::client
