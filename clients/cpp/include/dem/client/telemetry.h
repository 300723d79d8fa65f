// Telemetry of one server delivered to callbacks, on a thread of the
// subscription's own (so a slow callback delays only this subscriber; the
// server never waits for it). Destroying the subscription stops the thread.
#pragma once

#include <atomic>
#include <functional>
#include <thread>

#include "dem/client/client.h"

namespace dem::client {

struct TelemetryCallbacks {
  std::function<void(const protocol::PlateForces&)> plate_forces;
  std::function<void(const protocol::ContactStats&)> contact_stats;
  std::function<void(const protocol::Status&)> status;
  // The measures of the case's regions (output.region), when it has some.
  std::function<void(const protocol::RegionTelemetry&)> region_measures;
};

class TelemetrySubscription {
 public:
  TelemetrySubscription(const Client& client, TelemetryCallbacks callbacks);
  TelemetrySubscription(const dds::Participant& participant, const std::string& server, TelemetryCallbacks callbacks);
  ~TelemetrySubscription();
  TelemetrySubscription(const TelemetrySubscription&) = delete;
  TelemetrySubscription& operator=(const TelemetrySubscription&) = delete;

  // Telemetry writers this subscription is matched with (0 until discovery).
  std::uint32_t matched_publishers() const { return plates_reader_.matched_writers(); }

 private:
  void receive_loop();

  TelemetryCallbacks callbacks_;
  dds::Topic<protocol::PlateForces> plates_topic_;
  dds::Topic<protocol::ContactStats> stats_topic_;
  dds::Topic<protocol::Status> status_topic_;
  dds::Topic<protocol::RegionTelemetry> regions_topic_;
  dds::Reader<protocol::PlateForces> plates_reader_;
  dds::Reader<protocol::ContactStats> stats_reader_;
  dds::Reader<protocol::Status> status_reader_;
  dds::Reader<protocol::RegionTelemetry> regions_reader_;
  dds::ReadCondition plates_data_;
  dds::ReadCondition stats_data_;
  dds::ReadCondition status_data_;
  dds::ReadCondition regions_data_;
  dds::GuardCondition wake_;
  dds::WaitSet waitset_;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace dem::client
