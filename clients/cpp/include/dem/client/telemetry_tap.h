// The telemetry of every server on a DDS domain as the bytes on the wire,
// for bridges to other protocols (dem.bridge, the Foxglove WebSocket
// bridge): it watches discovery for servers (a writer of
// rt/dem/<name>/status), subscribes to each one's status, plate forces,
// contact statistics and region measures as serialized CDR samples, and hands them out in the
// order they came, each with its server, ROS 2 topic and message type.
// A server leaves the set when its status writer goes away.
//   TelemetryTap tap(7);
//   for (const TapSample& s : tap.take(200ms)) forward(s.topic, s.bytes);
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dem/dds/discovery.h"
#include "dem/dds/participant.h"
#include "dem/dds/waitset.h"

namespace dem::client {

struct TapSample {
  std::string server;
  std::string topic;               // the ROS 2 name: /dem/<server>/plate_forces
  std::string type;                // the ROS 2 type: dem_interfaces/msg/PlateForces
  std::string bytes;               // CDR with its encapsulation header, as sent
  std::uint64_t log_time = 0;      // ns since the Unix epoch: when it was taken here
  std::uint64_t publish_time = 0;  // ns since the Unix epoch: when the server sent it
};

struct TapTopic {
  std::string topic;  // /dem/<server>/<name>
  std::string type;   // dem_interfaces/msg/<Type>
};

class TelemetryTap {
 public:
  explicit TelemetryTap(std::uint32_t domain, const std::string& dds_config = {});
  ~TelemetryTap();
  TelemetryTap(const TelemetryTap&) = delete;
  TelemetryTap& operator=(const TelemetryTap&) = delete;

  // Looks for servers that came or went (at most every half second), waits
  // up to `timeout` for samples and returns those that came.
  std::vector<TapSample> take(std::chrono::milliseconds timeout);
  // The servers subscribed to now, by name.
  std::vector<std::string> servers() const;
  // The topics a server publishes telemetry on, with their types.
  static std::vector<TapTopic> topics(const std::string& server);

 private:
  struct Server;
  void refresh();

  dds::Participant participant_;
  dds::PublicationMonitor publications_;
  dds::WaitSet waitset_;  // over every server's read conditions
  std::map<std::string, std::unique_ptr<Server>> servers_;
  std::chrono::steady_clock::time_point refreshed_{};
};

}  // namespace dem::client
