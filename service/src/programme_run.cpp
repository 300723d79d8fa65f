#include "dem/service/programme_run.h"

#include <algorithm>

namespace dem::service {

ProgrammeRun::ProgrammeRun(const CaseProgramme& programme, const WorldSession& world, std::uint64_t output_interval,
                           std::size_t first, std::size_t count, std::uint64_t first_done)
    : stage_count_(programme.stage_count()),
      output_interval_(std::max<std::uint64_t>(output_interval, 1)),
      start_cycle_(world.cycle_count()),
      first_(first),
      next_(first),
      end_(first + count),
      first_done_(first_done),
      stage_(first),
      stage_start_(world.cycle_count()),
      health_(world) {
  for (std::size_t i = first; i < end_; ++i) total_ += programme.stage_cycles(i);
}

std::uint64_t ProgrammeRun::next_stage(const WorldSession& world) {
  stage_ = next_++;
  stage_done_ = stage_ == first_ ? first_done_ : 0;
  stage_start_ = world.cycle_count() - stage_done_;
  return stage_done_;
}

double ProgrammeRun::progress(double stage_fraction) const {
  const std::size_t count = end_ - first_;
  if (count == 0 || stage_ >= end_) return 1.0;
  const double before = static_cast<double>(stage_ - first_);
  return std::clamp((before + (stage_running() ? stage_fraction : 0.0)) / static_cast<double>(count), 0.0, 1.0);
}

StageResult ProgrammeRun::end_stage() {
  StageResult result = stepper_->result();
  result.cycles_run += stage_done_;
  stepper_.reset();
  return result;
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
