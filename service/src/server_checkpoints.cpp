#include "dem/service/server_checkpoints.h"

#include <spdlog/spdlog.h>

namespace dem::service {

void ServerCheckpoints::begin(const std::filesystem::path& case_directory, std::string case_digest,
                              std::uint64_t cycle) {
  store_.reset();
  // No directory: the case's is not the server's own (OutputRecorder::directory_problem).
  if (settings_.enabled() && !case_directory.empty()) store_.emplace(case_directory / "checkpoints", settings_.keep);
  case_digest_ = std::move(case_digest);
  last_cycle_ = cycle;
  last_time_ = std::chrono::steady_clock::now();
}

bool ServerCheckpoints::due(std::uint64_t cycle) const {
  if (!store_) return false;
  const bool by_cycles = settings_.cycles > 0 && cycle - last_cycle_ >= settings_.cycles;
  const bool by_time =
      settings_.seconds > 0.0 &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_time_).count() >= settings_.seconds;
  return by_cycles || by_time;
}

void ServerCheckpoints::write(const WorldSession& world, const io::SnapshotInfo& info, OutputRecorder& recorder,
                              std::size_t stage, std::uint64_t stage_cycles) {
  io::ResumePoint point;
  point.cycle = world.cycle_count();
  point.stage = stage;
  point.stage_cycles = stage_cycles;
  point.case_digest = case_digest_;
  recorder.fill(point);
  store_->write(world.snapshot_bytes(info), point);
  last_cycle_ = point.cycle;
  last_time_ = std::chrono::steady_clock::now();
  spdlog::debug("checkpoint at cycle {} in {}", point.cycle, store_->directory().string());
}

}  // namespace dem::service
