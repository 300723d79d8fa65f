// A loading programme: stages that set wall motions and cycle the world for a
// number of cycles or until a condition holds. Used by dem_run and the service.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
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

struct StageDef {
  std::string name;
  std::vector<std::pair<WallId, WallMotion>> wall_motions;  // applied when the stage starts
  std::optional<DampingDef> damping;                        // applied when the stage starts
  std::uint64_t cycles = 0;  // the stage's length, or its cap when conditions are set
  StopConditions until;
};

struct StageResult {
  std::uint64_t cycles_run = 0;
  bool condition_met = false;  // a stop condition ended the stage before its cycle cap
};

// Called every `interval` cycles counted from the stage's start, so a caller
// can record outputs; return false to stop the stage.
using StageObserver = std::function<bool(const World&)>;

StageResult run_stage(World& world, const StageDef& stage, std::uint64_t interval = 0,
                      const StageObserver& observer = {});

}  // namespace dem
