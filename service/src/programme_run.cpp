#include "dem/service/programme_run.h"

#include <algorithm>

namespace dem::service {

ProgrammeRun::ProgrammeRun(RunPlan plan, const WorldSession& world, std::optional<ReceivedCommand> command)
    : plan_(std::move(plan)),
      command_(std::move(command)),
      start_cycle_(world.cycle_count()),
      next_(plan_.first),
      stage_(plan_.first),
      stage_start_(world.cycle_count()),
      health_(world) {
  plan_.output_interval = std::max<std::uint64_t>(plan_.output_interval, 1);
  last_stage_ = plan_.first;
  for (std::size_t i = plan_.first; i < plan_.first + plan_.count; ++i) total_ += plan_.programme.stage_cycles(i);
}

void ProgrammeRun::begin_next_stage(WorldSession& world) {
  stage_ = next_++;
  stage_done_ = stage_ == plan_.first ? plan_.first_done : 0;
  stage_start_ = world.cycle_count() - stage_done_;
  stepper_ = plan_.programme.begin_stage(stage_, world, stage_done_);
}

std::uint64_t ProgrammeRun::cycles_to_next_stop(std::uint64_t cycle) const {
  std::uint64_t to_stop = stepper_->cycles_to_next_stop();
  if (plan_.sample_every > 0)
    to_stop = std::min(to_stop, plan_.sample_every - stage_cycles(cycle) % plan_.sample_every);
  if (!plan_.of_case) return to_stop;
  return std::min(to_stop, plan_.output_interval - stage_cycles(cycle) % plan_.output_interval);
}

RunPosition ProgrammeRun::position(std::uint64_t cycle) const {
  if (stage_running()) return {.stage = stage_, .stage_cycles = stage_cycles(cycle), .stage_ended = false};
  return {.stage = last_stage_, .stage_cycles = last_result_.cycles_run, .stage_ended = next_ > plan_.first};
}

double ProgrammeRun::progress(double stage_fraction) const {
  if (plan_.count == 0 || stage_ >= plan_.first + plan_.count) return 1.0;
  const double before = static_cast<double>(stage_ - plan_.first);
  return std::clamp((before + (stage_running() ? stage_fraction : 0.0)) / static_cast<double>(plan_.count), 0.0, 1.0);
}

StageResult ProgrammeRun::end_stage() {
  last_result_ = stepper_->result();
  last_result_.cycles_run += stage_done_;
  last_stage_ = stage_;
  stepper_.reset();
  return last_result_;
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

void ProgrammeRun::pause() {
  if (outcome_ == ProgrammeOutcome::kRunning) outcome_ = ProgrammeOutcome::kPaused;
}

void ProgrammeRun::complete() {
  stage_ = stage_count();
  if (outcome_ == ProgrammeOutcome::kRunning) outcome_ = ProgrammeOutcome::kCompleted;
}

}  // namespace dem::service
