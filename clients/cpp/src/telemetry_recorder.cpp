#include "dem/client/telemetry_recorder.h"

#include "server_telemetry.h"

namespace dem::client {
namespace {

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

// A chunk at least every second, so a recording cut short loses at most that.
constexpr auto kFlushInterval = std::chrono::seconds(1);

std::uint64_t& count_of(RecordedCounts& counts, Stream stream) {
  switch (stream) {
    case Stream::kPlateForces:
      return counts.plate_forces;
    case Stream::kContactStats:
      return counts.contact_stats;
    case Stream::kRegionMeasures:
      return counts.region_measures;
    case Stream::kStatus:
      break;
  }
  return counts.status;
}

}  // namespace

TelemetryRecorder::TelemetryRecorder(const dds::Participant& participant, const std::string& server,
                                     const std::filesystem::path& file)
    : file_(file, "ros2", "dem demctl record"),
      telemetry_(std::make_unique<ServerTelemetry>(participant, server)),
      waitset_(participant),
      last_flush_(std::chrono::steady_clock::now()) {
  for (Stream stream : ServerTelemetry::kStreams) {
    const TelemetryTopic& topic = telemetry_->topic(stream);
    waitset_.attach(telemetry_->data(stream), static_cast<std::intptr_t>(stream));
    channels_[static_cast<std::size_t>(stream)] =
        file_.add_channel(file_.add_schema(topic.type, "ros2msg", topic.schema), topic.topic, "cdr");
  }
}

TelemetryRecorder::~TelemetryRecorder() = default;

bool TelemetryRecorder::wait_for_publishers(std::chrono::milliseconds timeout) {
  // A reader that has matched a writer does not yet know that the writer
  // has matched it, and a volatile writer sends only to readers it knows.
  // The durable status sample proves the server has discovered this
  // participant's readers; they were announced together, so a moment more
  // covers the telemetry writers' side of the match.
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!telemetry_->matched() || counts_.status == 0) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    poll(std::chrono::milliseconds(10));
  }
  const auto settled = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  while (std::chrono::steady_clock::now() < settled) poll(std::chrono::milliseconds(20));
  return true;
}

void TelemetryRecorder::poll(std::chrono::milliseconds timeout) {
  waitset_.wait(timeout);
  // In Stream order: a cycle's telemetry before the status that follows it.
  for (Stream stream : ServerTelemetry::kStreams) {
    for (const dds::SerializedSample& sample : telemetry_->reader(stream).take()) {
      file_.write(channels_[static_cast<std::size_t>(stream)], now_ns(),
                  static_cast<std::uint64_t>(sample.source_timestamp), sample.bytes);
      ++count_of(counts_, stream);
    }
  }
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
