// Publishes plate forces, contact statistics, the measures of the case's
// regions and the status. Called from
// the engine thread only, and never blocks it: the telemetry writers keep
// the last few samples and do not wait (docs/DDS.md), so a subscriber that
// stops reading costs samples, counted here, never cycles.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "dem/dds/topic.h"
#include "dem/protocol/messages.h"
#include "dem/protocol/type_support.h"

namespace dem::service {

class TelemetryPublisher {
 public:
  TelemetryPublisher(const dds::Participant& participant, const std::string& server_name);

  void publish(const protocol::PlateForces& plates, const protocol::ContactStats& stats);
  void publish(const protocol::Status& status);
  void publish(const protocol::RegionTelemetry& regions);

  std::uint64_t dropped() const { return dropped_; }
  // Waits until subscribers acknowledged the status (the final one at shutdown).
  bool flush_status(std::chrono::milliseconds timeout);

 private:
  dds::Topic<protocol::PlateForces> plates_topic_;
  dds::Topic<protocol::ContactStats> stats_topic_;
  dds::Topic<protocol::Status> status_topic_;
  dds::Topic<protocol::RegionTelemetry> regions_topic_;
  dds::Writer<protocol::PlateForces> plates_writer_;
  dds::Writer<protocol::ContactStats> stats_writer_;
  dds::Writer<protocol::Status> status_writer_;
  dds::Writer<protocol::RegionTelemetry> regions_writer_;
  std::uint64_t dropped_ = 0;
};

}  // namespace dem::service
