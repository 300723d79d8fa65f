// A loading programme: stages that set wall motions and cycle the world for a
// number of cycles or until a condition holds. Used by dem_run and the service.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "dem/definitions.h"
#include "dem/world.h"

namespace dem {

// Conditions that end a stage early: the stage ends when every condition
// that is set holds at once. They are checked every check_interval cycles,
// never before min_cycles.
struct StopConditions {
  std::optional<double> kinetic_energy_below;  // J
  std::optional<double> out_of_balance_below;  // Delta F / F
  // Every servo-controlled wall carries its target within this relative error.
  std::optional<double> servo_tolerance;
  std::uint64_t min_cycles = 0;
  std::uint64_t check_interval = 10;
};

template <int Dim>
struct StageDefT {
  std::string name;
  std::vector<std::pair<WallId, WallMotionT<Dim>>> wall_motions;  // applied when the stage starts
  std::optional<DampingDef> damping;                              // applied when the stage starts
  std::uint64_t cycles = 0;  // the stage's length, or its cap when conditions are set
  StopConditions until;
};

struct StageResult {
  std::uint64_t cycles_run = 0;
  bool condition_met = false;  // a stop condition ended the stage before its cycle cap
};

// Called every `interval` cycles counted from the stage's start, so a caller
// can record outputs; return false to stop the stage.
template <int Dim>
using StageObserverT = std::function<bool(const BasicWorld<Dim>&)>;

// The observer is not used to deduce Dim, so a lambda can be passed as it is.
template <int Dim>
StageResult run_stage(BasicWorld<Dim>& world, const StageDefT<Dim>& stage, std::uint64_t interval = 0,
                      const std::type_identity_t<StageObserverT<Dim>>& observer = {});

using StageDef = StageDefT<2>;
using StageDef3 = StageDefT<3>;
using StageObserver = StageObserverT<2>;

}  // namespace dem
