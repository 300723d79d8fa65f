#include "dem/service/programme_run.h"

#include <algorithm>

namespace dem::service {

ProgrammeRun::ProgrammeRun(const WorldSession& world, std::uint64_t output_interval, std::size_t first,
                           std::size_t count)
    : stage_count_(world.stage_count()),
      output_interval_(std::max<std::uint64_t>(output_interval, 1)),
      start_cycle_(world.cycle_count()),
      stage_start_(world.cycle_count()),
      health_(world) {
  for (std::size_t i = first; i < first + count; ++i) total_ += world.stage_cycles(i);
}

void ProgrammeRun::start_stage(std::size_t stage, const WorldSession& world, std::uint64_t done) {
  stage_ = stage;
  stage_start_ = world.cycle_count() - done;
}

void ProgrammeRun::stop(std::string reason) {
  if (outcome_ != ProgrammeOutcome::kRunning) return;
  outcome_ = ProgrammeOutcome::kStopped;
  reason_ = std::move(reason);
}

void ProgrammeRun::fail(std::string error) {
  // A failure outranks a stop asked for just before it (the state is not
  // good) and a completion whose snapshot could not be written.
  if (outcome_ == ProgrammeOutcome::kFailed) return;
  outcome_ = ProgrammeOutcome::kFailed;
  reason_ = std::move(error);
}

void ProgrammeRun::complete() {
  stage_ = stage_count_;
  if (outcome_ == ProgrammeOutcome::kRunning) outcome_ = ProgrammeOutcome::kCompleted;
}

}  // namespace dem::service
