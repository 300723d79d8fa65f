#include "dem/client/telemetry_recorder.h"

#include "dem/interfaces/ros2_schemas.h"
#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"

namespace dem::client {
namespace {

using protocol::TopicKind;

// The ROS 2 name of a topic ("rt/dem/a/status" -> "/dem/a/status"), as a bag names its channels.
std::string ros_topic(const std::string& dds_topic) { return dds_topic.substr(2); }

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

// A chunk at least every second, so a recording cut short loses at most that.
constexpr auto kFlushInterval = std::chrono::seconds(1);

// The status as the server publishes it (durable: the current state comes
// at once), but every change kept until taken: a recording wants them all,
// not only the latest.
dds::Qos recorded_status_qos() {
  dds::Qos qos = protocol::status_qos();
  qos.keep_last(1024);
  return qos;
}

}  // namespace

TelemetryRecorder::TelemetryRecorder(const dds::Participant& participant, const std::string& server,
                                     const std::filesystem::path& file)
    : file_(file, "ros2", "dem demctl record"),
      status_topic_(participant, protocol::topic_name(server, TopicKind::kStatus)),
      plates_topic_(participant, protocol::topic_name(server, TopicKind::kPlateForces)),
      stats_topic_(participant, protocol::topic_name(server, TopicKind::kContactStats)),
      status_reader_(participant, status_topic_, recorded_status_qos()),
      plates_reader_(participant, plates_topic_, protocol::telemetry_reader_qos()),
      stats_reader_(participant, stats_topic_, protocol::telemetry_reader_qos()),
      status_data_(status_reader_.handle()),
      plates_data_(plates_reader_.handle()),
      stats_data_(stats_reader_.handle()),
      waitset_(participant),
      last_flush_(std::chrono::steady_clock::now()) {
  waitset_.attach(status_data_, 1);
  waitset_.attach(plates_data_, 2);
  waitset_.attach(stats_data_, 3);
  status_channel_ =
      file_.add_channel(file_.add_schema("dem_interfaces/msg/Status", "ros2msg", interfaces::kStatusSchema),
                        ros_topic(status_topic_.name()), "cdr");
  plates_channel_ =
      file_.add_channel(file_.add_schema("dem_interfaces/msg/PlateForces", "ros2msg", interfaces::kPlateForcesSchema),
                        ros_topic(plates_topic_.name()), "cdr");
  stats_channel_ =
      file_.add_channel(file_.add_schema("dem_interfaces/msg/ContactStats", "ros2msg", interfaces::kContactStatsSchema),
                        ros_topic(stats_topic_.name()), "cdr");
}

std::uint64_t TelemetryRecorder::write_all(dds::SerializedReader& reader, std::uint16_t channel) {
  std::uint64_t written = 0;
  for (const dds::SerializedSample& sample : reader.take()) {
    file_.write(channel, now_ns(), static_cast<std::uint64_t>(sample.source_timestamp), sample.bytes);
    ++written;
  }
  return written;
}

bool TelemetryRecorder::wait_for_publishers(std::chrono::milliseconds timeout) {
  // A reader that has matched a writer does not yet know that the writer
  // has matched it, and a volatile writer sends only to readers it knows.
  // The durable status sample proves the server has discovered this
  // participant's readers; they were announced together, so a moment more
  // covers the telemetry writers' side of the match.
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (status_reader_.matched_writers() == 0 || plates_reader_.matched_writers() == 0 ||
         stats_reader_.matched_writers() == 0 || counts_.status == 0) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    poll(std::chrono::milliseconds(10));
  }
  const auto settled = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  while (std::chrono::steady_clock::now() < settled) poll(std::chrono::milliseconds(20));
  return true;
}

void TelemetryRecorder::poll(std::chrono::milliseconds timeout) {
  waitset_.wait(timeout);
  // Plate forces before contact statistics, as the subscription delivers them.
  counts_.plate_forces += write_all(plates_reader_, plates_channel_);
  counts_.contact_stats += write_all(stats_reader_, stats_channel_);
  counts_.status += write_all(status_reader_, status_channel_);
  if (std::chrono::steady_clock::now() - last_flush_ >= kFlushInterval) {
    file_.flush();
    last_flush_ = std::chrono::steady_clock::now();
  }
}

void TelemetryRecorder::close() {
  poll(std::chrono::milliseconds(0));
  file_.close();
}

}  // namespace dem::client
