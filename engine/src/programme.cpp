#include "dem/programme.h"

#include <algorithm>
#include <cmath>

namespace dem {

namespace {

template <int Dim>
bool servos_settled(const BasicWorld<Dim>& world, double tolerance) {
  bool any = false;
  for (const WallMeasureT<Dim>& m : world.wall_measures()) {
    const auto& servo = world.wall(m.wall).motion.servo;
    if (!servo) continue;
    any = true;
    if (std::abs(m.normal_force - servo->target_force) > tolerance * std::abs(servo->target_force)) return false;
  }
  return any;
}

template <int Dim>
bool conditions_hold(const BasicWorld<Dim>& world, const StopConditions& until) {
  const bool needs_assembly = until.kinetic_energy_below || until.out_of_balance_below;
  const AssemblyMeasures a = needs_assembly ? world.assembly_measures() : AssemblyMeasures{};
  if (until.kinetic_energy_below && !(a.kinetic_energy < *until.kinetic_energy_below)) return false;
  if (until.out_of_balance_below && !(a.contacts > 0 && a.out_of_balance < *until.out_of_balance_below)) return false;
  if (until.servo_tolerance && !servos_settled(world, *until.servo_tolerance)) return false;
  return true;
}

bool has_condition(const StopConditions& until) {
  return until.kinetic_energy_below || until.out_of_balance_below || until.servo_tolerance;
}

}  // namespace

template <int Dim>
StageResult run_stage(BasicWorld<Dim>& world, const StageDefT<Dim>& stage, std::uint64_t interval,
                      const std::type_identity_t<StageObserverT<Dim>>& observer) {
  for (const auto& [wall, motion] : stage.wall_motions) world.set_wall_motion(wall, motion);
  if (stage.damping) world.set_damping(*stage.damping);

  StageResult result;
  const bool conditional = has_condition(stage.until);
  const std::uint64_t check = std::max<std::uint64_t>(stage.until.check_interval, 1);
  while (result.cycles_run < stage.cycles) {
    // Advance to the next output row, condition check or the stage's end.
    std::uint64_t chunk = stage.cycles - result.cycles_run;
    if (interval > 0) chunk = std::min(chunk, interval - result.cycles_run % interval);
    if (conditional) chunk = std::min(chunk, check - result.cycles_run % check);
    world.cycle(chunk);
    result.cycles_run += chunk;
    if (observer && interval > 0 && result.cycles_run % interval == 0 && !observer(world)) break;
    if (conditional && result.cycles_run >= stage.until.min_cycles && result.cycles_run % check == 0 &&
        conditions_hold(world, stage.until)) {
      result.condition_met = true;
      break;
    }
  }
  return result;
}

template StageResult run_stage<2>(BasicWorld<2>&, const StageDefT<2>&, std::uint64_t, const StageObserverT<2>&);
template StageResult run_stage<3>(BasicWorld<3>&, const StageDefT<3>&, std::uint64_t, const StageObserverT<3>&);

}  // namespace dem
