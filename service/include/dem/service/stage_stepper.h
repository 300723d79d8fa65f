// A stage of the engine's (StageRunT) of either dimension, stepped by the
// runner between the commands: cycle() and check() in turn until the stage
// is over. Begun by WorldSession::begin_stage; it steps that session's
// world in place.
#pragma once

#include <cstdint>
#include <utility>
#include <variant>

#include "dem/programme.h"

namespace dem::service {

class StageStepper {
 public:
  // Does the stage's start actions on `world` (StageRunT's constructor).
  template <int Dim>
  StageStepper(BasicWorld<Dim>& world, StageDefT<Dim> stage)
      : run_(std::in_place_type<StageRunT<Dim>>, world, std::move(stage)) {}
  // One stepper per stage: a copy would step the same world again.
  StageStepper(const StageStepper&) = delete;
  StageStepper& operator=(const StageStepper&) = delete;
  StageStepper(StageStepper&&) = default;
  StageStepper& operator=(StageStepper&&) = default;

  std::uint64_t cycles_to_next_stop() const {
    return std::visit([](const auto& run) { return run.cycles_to_next_stop(); }, run_);
  }
  void cycle(std::uint64_t cycles) {
    std::visit([&](auto& run) { run.cycle(cycles); }, run_);
  }
  bool check() {
    return std::visit([](auto& run) { return run.check(); }, run_);
  }
  const StageResult& result() const {
    return std::visit([](const auto& run) -> const StageResult& { return run.result(); }, run_);
  }

 private:
  std::variant<StageRunT<2>, StageRunT<3>> run_;
};

}  // namespace dem::service
