#include "dem/client/telemetry_tap.h"

#include <set>

#include "dem/client/client.h"
#include "dem/dds/serialized_reader.h"
#include "dem/dds/waitset.h"
#include "dem/protocol/messages.h"
#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"
#include "dem/protocol/type_support.h"

namespace dem::client {
namespace {

using protocol::TopicKind;

constexpr auto kRefreshInterval = std::chrono::milliseconds(500);

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

// The ROS 2 name of a DDS topic: "rt/dem/a/status" -> "/dem/a/status".
std::string ros_topic(const std::string& dds_topic) { return dds_topic.substr(2); }

}  // namespace

// One server's three readers and their read conditions (attached to the
// tap's wait set; deleting a condition detaches it).
struct TelemetryTap::Server {
  Server(const dds::Participant& participant, const std::string& name)
      : status_topic(participant, protocol::topic_name(name, TopicKind::kStatus)),
        plates_topic(participant, protocol::topic_name(name, TopicKind::kPlateForces)),
        stats_topic(participant, protocol::topic_name(name, TopicKind::kContactStats)),
        status(participant, status_topic, status_qos()),
        plates(participant, plates_topic, protocol::telemetry_reader_qos()),
        stats(participant, stats_topic, protocol::telemetry_reader_qos()),
        status_data(status.handle()),
        plates_data(plates.handle()),
        stats_data(stats.handle()) {}
  // Durable, and every change kept until taken (a bridge forwards them all).
  static dds::Qos status_qos() {
    dds::Qos qos = protocol::status_qos();
    qos.keep_last(1024);
    return qos;
  }

  dds::Topic<protocol::Status> status_topic;
  dds::Topic<protocol::PlateForces> plates_topic;
  dds::Topic<protocol::ContactStats> stats_topic;
  dds::SerializedReader status;
  dds::SerializedReader plates;
  dds::SerializedReader stats;
  dds::ReadCondition status_data;
  dds::ReadCondition plates_data;
  dds::ReadCondition stats_data;
};

TelemetryTap::TelemetryTap(std::uint32_t domain, const std::string& dds_config)
    : participant_(domain, dds_config), publications_(participant_), waitset_(participant_) {}

TelemetryTap::~TelemetryTap() = default;

std::vector<TapTopic> TelemetryTap::topics(const std::string& server) {
  return {{ros_topic(protocol::topic_name(server, TopicKind::kStatus)), "dem_interfaces/msg/Status"},
          {ros_topic(protocol::topic_name(server, TopicKind::kPlateForces)), "dem_interfaces/msg/PlateForces"},
          {ros_topic(protocol::topic_name(server, TopicKind::kContactStats)), "dem_interfaces/msg/ContactStats"}};
}

void TelemetryTap::refresh() {
  const std::set<std::string> alive = server_names(publications_.alive());
  for (auto it = servers_.begin(); it != servers_.end();) {
    it = alive.count(it->first) ? std::next(it) : servers_.erase(it);
  }
  for (const std::string& name : alive) {
    if (servers_.count(name)) continue;
    auto server = std::make_unique<Server>(participant_, name);
    for (const dds::ReadCondition* condition : {&server->status_data, &server->plates_data, &server->stats_data}) {
      waitset_.attach(*condition, 1);
    }
    servers_.emplace(name, std::move(server));
  }
  refreshed_ = std::chrono::steady_clock::now();
}

std::vector<TapSample> TelemetryTap::take(std::chrono::milliseconds timeout) {
  if (std::chrono::steady_clock::now() - refreshed_ >= kRefreshInterval) refresh();
  std::vector<TapSample> samples;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    for (auto& [name, server] : servers_) {
      const std::vector<TapTopic> names = topics(name);
      auto collect = [&](dds::SerializedReader& reader, const TapTopic& topic) {
        for (dds::SerializedSample& sample : reader.take()) {
          samples.push_back({name, topic.topic, topic.type, std::move(sample.bytes), now_ns(),
                             static_cast<std::uint64_t>(sample.source_timestamp)});
        }
      };
      collect(server->plates, names[1]);
      collect(server->stats, names[2]);
      collect(server->status, names[0]);
    }
    const auto now = std::chrono::steady_clock::now();
    if (!samples.empty() || now >= deadline) return samples;
    // Waits in slices, so servers that come meanwhile are found too.
    waitset_.wait(std::min<std::chrono::nanoseconds>(deadline - now, kRefreshInterval));
    if (std::chrono::steady_clock::now() - refreshed_ >= kRefreshInterval) refresh();
  }
}

std::vector<std::string> TelemetryTap::servers() const {
  std::vector<std::string> names;
  for (const auto& [name, server] : servers_) names.push_back(name);
  return names;
}

}  // namespace dem::client
