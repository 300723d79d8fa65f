#include "server_telemetry.h"

#include "dem/interfaces/ros2_schemas.h"
#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"

namespace dem::client {
namespace {

using protocol::TopicKind;

// The ROS 2 name of a DDS topic: "rt/dem/a/status" -> "/dem/a/status", as a bag names its channels.
std::string ros_topic(const std::string& server, TopicKind kind) {
  return protocol::topic_name(server, kind).substr(2);
}

}  // namespace

std::array<TelemetryTopic, kStreamCount> telemetry_topics(const std::string& server) {
  return {
      {{ros_topic(server, TopicKind::kPlateForces), "dem_interfaces/msg/PlateForces", interfaces::kPlateForcesSchema},
       {ros_topic(server, TopicKind::kContactStats), "dem_interfaces/msg/ContactStats",
        interfaces::kContactStatsSchema},
       {ros_topic(server, TopicKind::kRegionMeasures), "dem_interfaces/msg/RegionTelemetry",
        interfaces::kRegionTelemetrySchema},
       {ros_topic(server, TopicKind::kStatus), "dem_interfaces/msg/Status", interfaces::kStatusSchema}}};
}

dds::Qos every_status_qos() {
  dds::Qos qos = protocol::status_qos();
  qos.keep_last(1024);
  return qos;
}

ServerTelemetry::ServerTelemetry(const dds::Participant& participant, const std::string& server)
    : topics_(telemetry_topics(server)),
      plates_topic_(participant, protocol::topic_name(server, TopicKind::kPlateForces)),
      stats_topic_(participant, protocol::topic_name(server, TopicKind::kContactStats)),
      regions_topic_(participant, protocol::topic_name(server, TopicKind::kRegionMeasures)),
      status_topic_(participant, protocol::topic_name(server, TopicKind::kStatus)),
      readers_{dds::SerializedReader(participant, plates_topic_, protocol::telemetry_reader_qos()),
               dds::SerializedReader(participant, stats_topic_, protocol::telemetry_reader_qos()),
               dds::SerializedReader(participant, regions_topic_, protocol::telemetry_reader_qos()),
               dds::SerializedReader(participant, status_topic_, every_status_qos())},
      data_{dds::ReadCondition(readers_[0].handle()), dds::ReadCondition(readers_[1].handle()),
            dds::ReadCondition(readers_[2].handle()), dds::ReadCondition(readers_[3].handle())} {}

bool ServerTelemetry::matched() const {
  for (const dds::SerializedReader& reader : readers_) {
    if (reader.matched_writers() == 0) return false;
  }
  return true;
}

}  // namespace dem::client
