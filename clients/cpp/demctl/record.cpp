// demctl record FILE.mcap: the server's telemetry (status, plate forces,
// contact statistics) recorded as a ROS 2 bag holds it, in MCAP
// (dem::client::TelemetryRecorder), until Ctrl-C, --samples plate forces
// samples, --duration seconds, or the server stops.
#include "record.h"

#include <unistd.h>

#include <cstdio>

#include "dem/cli/interrupt.h"
#include "dem/client/telemetry_recorder.h"
#include "exit_codes.h"

namespace demctl {

using namespace std::chrono_literals;

int record(const Global& global, const RecordOptions& options) {
  dem::client::Client client(connect_options(global));
  dem::client::TelemetryRecorder recorder(client.participant(), global.server, options.file);
  const bool terminal = !global.quiet && isatty(STDERR_FILENO) == 1;
  // Said once the subscriptions are matched: what the server publishes from then on is recorded.
  if (!recorder.wait_for_publishers(milliseconds(global.timeout))) {
    throw dem::client::ReplyTimeout("server \"" + global.server + "\" publishes no telemetry topics");
  }
  const auto start = std::chrono::steady_clock::now();
  std::fprintf(stderr, "recording server %s to %s (Ctrl-C to stop)\n", global.server.c_str(), options.file.c_str());
  std::string ended = "interrupted";
  for (;;) {
    recorder.poll(100ms);
    const auto& counts = recorder.counts();
    if (terminal) {
      std::fprintf(
          stderr, "\r%llu messages: %llu plate forces, %llu contact statistics, %llu region measures, %llu status",
          static_cast<unsigned long long>(counts.total()), static_cast<unsigned long long>(counts.plate_forces),
          static_cast<unsigned long long>(counts.contact_stats),
          static_cast<unsigned long long>(counts.region_measures), static_cast<unsigned long long>(counts.status));
    }
    if (dem::cli::interrupted()) break;
    if (options.samples && counts.plate_forces >= *options.samples) {
      ended = "the samples asked for are in";
      break;
    }
    if (options.duration &&
        std::chrono::steady_clock::now() - start >= std::chrono::duration<double>(*options.duration)) {
      ended = "the duration has passed";
      break;
    }
    // The last samples a stopping server publishes come just before its
    // status writer goes: take what is still on the way.
    if (!client.server_alive() || client.status().state == dem::protocol::ServerState::kShutdown) {
      for (int i = 0; i < 5; ++i) recorder.poll(100ms);
      ended = "the server stopped";
      break;
    }
  }
  recorder.close();
  const auto& counts = recorder.counts();
  if (terminal) std::fprintf(stderr, "\n");
  std::printf(
      "recorded %llu messages (%llu plate forces, %llu contact statistics, %llu region measures, %llu status) to %s: "
      "%s\n",
      static_cast<unsigned long long>(counts.total()), static_cast<unsigned long long>(counts.plate_forces),
      static_cast<unsigned long long>(counts.contact_stats), static_cast<unsigned long long>(counts.region_measures),
      static_cast<unsigned long long>(counts.status), options.file.c_str(), ended.c_str());
  return kOk;
}

}  // namespace demctl
