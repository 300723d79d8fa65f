#include "dem/service/server_checkpoints.h"

#include <spdlog/spdlog.h>

#include "dem/service/world_snapshots.h"

namespace dem::service {

void ServerCheckpoints::begin(const std::filesystem::path& case_directory, std::string case_digest,
                              std::uint64_t cycle) {
  // No directory: the case's is not the server's own (OutputRecorder::directory_problem).
  directory_ = case_directory.empty() ? case_directory : case_directory / "checkpoints";
  case_digest_ = std::move(case_digest);
  in_programme_ = false;
  commands_.begin(directory_, case_digest_, cycle);
}

void ServerCheckpoints::begin_programme(std::uint64_t cycle) {
  in_programme_ = true;
  programme_.begin(directory_, case_digest_, cycle);
}

void ServerCheckpoints::end_programme(std::uint64_t cycle) {
  in_programme_ = false;
  commands_.begin(directory_, case_digest_, cycle);
}

void ServerCheckpoints::write(const WorldSession& world, const io::SnapshotInfo& info, OutputRecorder& recorder,
                              std::size_t stage, std::uint64_t stage_cycles) {
  io::ResumePoint point{.cycle = world.cycle_count(), .stage = stage, .stage_cycles = stage_cycles};
  recorder.fill(point);
  io::PeriodicCheckpoints& periodic = active();
  periodic.write(snapshot_bytes(world, info), std::move(point));
  spdlog::debug("checkpoint at cycle {} in {}", world.cycle_count(), periodic.store()->directory().string());
}

}  // namespace dem::service
