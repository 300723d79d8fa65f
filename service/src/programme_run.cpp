#include "dem/service/programme_run.h"

#include <algorithm>

namespace dem::service {

namespace {
// A checkpoint is taken no sooner than this many times its own duration
// after the last one: copying then costs at most 1/20 of the run's time.
constexpr int kCheckpointSpacing = 20;
}  // namespace

ProgrammeRun::ProgrammeRun(const WorldSession& world, std::uint64_t output_interval, std::size_t first,
                           std::size_t count)
    : stage_count_(world.stage_count()),
      output_interval_(std::max<std::uint64_t>(output_interval, 1)),
      start_cycle_(world.cycle_count()),
      stage_start_(world.cycle_count()),
      last_good_(world.checkpoint()) {
  for (std::size_t i = first; i < first + count; ++i) total_ += world.stage_cycles(i);
}

void ProgrammeRun::start_stage(std::size_t stage, const WorldSession& world) {
  stage_ = stage;
  stage_start_ = world.cycle_count();
}

void ProgrammeRun::keep_if_good(const WorldSession& world, bool always) {
  const auto now = std::chrono::steady_clock::now();
  if (!always && now < next_checkpoint_) return;
  last_good_ = world.checkpoint();
  next_checkpoint_ = now + kCheckpointSpacing * (std::chrono::steady_clock::now() - now);
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
