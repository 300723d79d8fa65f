#include "dem/service/telemetry_publisher.h"

#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"
#include "dem/protocol/type_support.h"

namespace dem::service {

using protocol::TopicKind;

TelemetryPublisher::TelemetryPublisher(const dds::Participant& participant, const std::string& server_name)
    : plates_topic_(participant, protocol::topic_name(server_name, TopicKind::kPlateForces)),
      stats_topic_(participant, protocol::topic_name(server_name, TopicKind::kContactStats)),
      status_topic_(participant, protocol::topic_name(server_name, TopicKind::kStatus)),
      regions_topic_(participant, protocol::topic_name(server_name, TopicKind::kRegionMeasures)),
      plates_writer_(participant, plates_topic_, protocol::telemetry_writer_qos()),
      stats_writer_(participant, stats_topic_, protocol::telemetry_writer_qos()),
      status_writer_(participant, status_topic_, protocol::status_qos()),
      regions_writer_(participant, regions_topic_, protocol::telemetry_writer_qos()) {}

void TelemetryPublisher::publish(const protocol::PlateForces& plates, const protocol::ContactStats& stats) {
  if (!plates_writer_.write(plates)) ++dropped_;
  if (!stats_writer_.write(stats)) ++dropped_;
}

void TelemetryPublisher::publish(const protocol::RegionTelemetry& regions) {
  if (!regions_writer_.write(regions)) ++dropped_;
}

void TelemetryPublisher::publish(const protocol::Status& status) {
  if (!status_writer_.write(status)) ++dropped_;
}

bool TelemetryPublisher::flush_status(std::chrono::milliseconds timeout) {
  return status_writer_.wait_for_acks(timeout);
}

}  // namespace dem::service
