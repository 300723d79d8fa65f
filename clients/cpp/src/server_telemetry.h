// One server's telemetry topics taken as the bytes on the wire, for those
// that pass the samples on unread: the recorder (demctl record) and the tap
// (dem.bridge). This is the one list of what a server publishes: a topic
// added here is recorded and bridged.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "dem/dds/participant.h"
#include "dem/dds/qos.h"
#include "dem/dds/serialized_reader.h"
#include "dem/dds/topic.h"
#include "dem/dds/waitset.h"
#include "dem/protocol/messages.h"
#include "dem/protocol/type_support.h"

namespace dem::client {

// A telemetry topic as ROS 2 names it, with its ros2msg schema.
struct TelemetryTopic {
  std::string topic;        // /dem/<server>/<name>
  std::string type;         // dem_interfaces/msg/<Type>
  std::string_view schema;  // generated from the IDL (ros2/generate_interfaces.py)
};

// The streams, in the order one cycle's samples are taken: the server
// publishes plate forces, contact statistics and region measures of a
// cycle before the status that follows them.
enum class Stream : std::size_t { kPlateForces, kContactStats, kRegionMeasures, kStatus };
inline constexpr std::size_t kStreamCount = 4;

// The telemetry topics of the server `server`, in Stream order.
std::array<TelemetryTopic, kStreamCount> telemetry_topics(const std::string& server);

// The status as the server publishes it (durable: the current state comes at
// once), but every change kept until taken: a recording or a bridge wants
// them all, not only the latest.
dds::Qos every_status_qos();

// A reader of each of a server's telemetry topics, with its read condition.
class ServerTelemetry {
 public:
  ServerTelemetry(const dds::Participant& participant, const std::string& server);

  const TelemetryTopic& topic(Stream stream) const { return topics_[index(stream)]; }
  dds::SerializedReader& reader(Stream stream) { return readers_[index(stream)]; }
  const dds::ReadCondition& data(Stream stream) const { return data_[index(stream)]; }
  // Whether every reader has matched the server's writer.
  bool matched() const;

  static constexpr std::array<Stream, kStreamCount> kStreams = {Stream::kPlateForces, Stream::kContactStats,
                                                                Stream::kRegionMeasures, Stream::kStatus};

 private:
  static constexpr std::size_t index(Stream stream) { return static_cast<std::size_t>(stream); }

  std::array<TelemetryTopic, kStreamCount> topics_;
  dds::Topic<protocol::PlateForces> plates_topic_;
  dds::Topic<protocol::ContactStats> stats_topic_;
  dds::Topic<protocol::RegionTelemetry> regions_topic_;
  dds::Topic<protocol::Status> status_topic_;
  std::array<dds::SerializedReader, kStreamCount> readers_;
  std::array<dds::ReadCondition, kStreamCount> data_;
};

}  // namespace dem::client
