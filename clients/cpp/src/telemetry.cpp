#include "dem/client/telemetry.h"

#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"

namespace dem::client {

using protocol::TopicKind;

namespace {
constexpr std::intptr_t kPlates = 1;
constexpr std::intptr_t kStats = 2;
constexpr std::intptr_t kStatus = 3;
constexpr std::intptr_t kWake = 4;
constexpr std::intptr_t kRegions = 5;
}  // namespace

TelemetrySubscription::TelemetrySubscription(const Client& client, TelemetryCallbacks callbacks)
    : TelemetrySubscription(client.participant(), client.server(), std::move(callbacks)) {}

TelemetrySubscription::TelemetrySubscription(const dds::Participant& participant, const std::string& server,
                                             TelemetryCallbacks callbacks)
    : callbacks_(std::move(callbacks)),
      plates_topic_(participant, protocol::topic_name(server, TopicKind::kPlateForces)),
      stats_topic_(participant, protocol::topic_name(server, TopicKind::kContactStats)),
      status_topic_(participant, protocol::topic_name(server, TopicKind::kStatus)),
      regions_topic_(participant, protocol::topic_name(server, TopicKind::kRegionMeasures)),
      plates_reader_(participant, plates_topic_, protocol::telemetry_reader_qos()),
      stats_reader_(participant, stats_topic_, protocol::telemetry_reader_qos()),
      status_reader_(participant, status_topic_, protocol::status_qos()),
      regions_reader_(participant, regions_topic_, protocol::telemetry_reader_qos()),
      plates_data_(plates_reader_.handle()),
      stats_data_(stats_reader_.handle()),
      status_data_(status_reader_.handle()),
      regions_data_(regions_reader_.handle()),
      wake_(participant),
      waitset_(participant) {
  waitset_.attach(plates_data_, kPlates);
  waitset_.attach(stats_data_, kStats);
  waitset_.attach(status_data_, kStatus);
  waitset_.attach(regions_data_, kRegions);
  waitset_.attach(wake_, kWake);
  thread_ = std::thread([this] { receive_loop(); });
}

TelemetrySubscription::~TelemetrySubscription() {
  stopping_ = true;
  wake_.trigger();
  thread_.join();
}

void TelemetrySubscription::receive_loop() {
  while (!stopping_) {
    try {
      waitset_.wait(std::chrono::seconds(1));
      // Plate forces before contact statistics: a consumer pairing them by
      // cycle sees the plates of a cycle first.
      for (const auto& sample : plates_reader_.take()) {
        if (callbacks_.plate_forces) callbacks_.plate_forces(sample);
      }
      for (const auto& sample : stats_reader_.take()) {
        if (callbacks_.contact_stats) callbacks_.contact_stats(sample);
      }
      for (const auto& sample : regions_reader_.take()) {
        if (callbacks_.region_measures) callbacks_.region_measures(sample);
      }
      for (const auto& sample : status_reader_.take()) {
        if (callbacks_.status) callbacks_.status(sample);
      }
    } catch (const std::exception&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
}

}  // namespace dem::client
