#include "dem/client/telemetry_tap.h"

#include <set>

#include "dem/client/client.h"
#include "server_telemetry.h"

namespace dem::client {
namespace {

constexpr auto kRefreshInterval = std::chrono::milliseconds(500);

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

}  // namespace

// One server's readers and their read conditions (attached to the tap's
// wait set; deleting a condition detaches it).
struct TelemetryTap::Server {
  Server(const dds::Participant& participant, const std::string& name) : telemetry(participant, name) {}
  ServerTelemetry telemetry;
};

TelemetryTap::TelemetryTap(std::uint32_t domain, const std::string& dds_config)
    : participant_(domain, dds_config), publications_(participant_), waitset_(participant_) {}

TelemetryTap::~TelemetryTap() = default;

std::vector<TapTopic> TelemetryTap::topics(const std::string& server) {
  std::vector<TapTopic> topics;
  for (const TelemetryTopic& topic : telemetry_topics(server)) topics.push_back({topic.topic, topic.type});
  return topics;
}

void TelemetryTap::refresh() {
  const std::set<std::string> alive = server_names(publications_.alive());
  for (auto it = servers_.begin(); it != servers_.end();) {
    it = alive.count(it->first) ? std::next(it) : servers_.erase(it);
  }
  for (const std::string& name : alive) {
    if (servers_.count(name)) continue;
    auto server = std::make_unique<Server>(participant_, name);
    for (Stream stream : ServerTelemetry::kStreams) waitset_.attach(server->telemetry.data(stream), 1);
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
      // In Stream order: a cycle's telemetry before the status that follows it.
      for (Stream stream : ServerTelemetry::kStreams) {
        const TelemetryTopic& topic = server->telemetry.topic(stream);
        for (dds::SerializedSample& sample : server->telemetry.reader(stream).take()) {
          samples.push_back({name, topic.topic, topic.type, std::move(sample.bytes), now_ns(),
                             static_cast<std::uint64_t>(sample.source_timestamp)});
        }
      }
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
