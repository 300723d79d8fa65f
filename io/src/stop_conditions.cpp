#include "dem/io/stop_conditions.h"

#include <cmath>

namespace dem::io {

bool has_stop_condition(const StopConditions& until) {
  return until.kinetic_energy_below || until.out_of_balance_below || until.servo_tolerance || until.wall_stress_above ||
         until.wall_settlement_above;
}

template <int Dim>
bool stop_conditions_hold(const BasicWorld<Dim>& world, const StopConditions& until) {
  const bool needs_assembly = until.kinetic_energy_below || until.out_of_balance_below;
  const AssemblyMeasures a = needs_assembly ? world.assembly_measures() : AssemblyMeasures{};
  if (until.kinetic_energy_below && !(a.kinetic_energy < *until.kinetic_energy_below)) return false;
  if (until.out_of_balance_below && !(a.contacts > 0 && a.out_of_balance < *until.out_of_balance_below)) return false;
  if (until.servo_tolerance) {
    bool any = false;
    for (const WallMeasureT<Dim>& m : world.wall_measures()) {
      const auto& servo = world.wall(m.wall).motion.servo;
      if (!servo) continue;
      any = true;
      if (std::abs(m.normal_force - servo->target_force) > *until.servo_tolerance * std::abs(servo->target_force)) {
        return false;
      }
    }
    if (!any) return false;
  }
  if (until.wall_stress_above) {
    const WallId wall = until.wall_stress_above->wall;
    if (world.wall_measures()[wall].normal_force / world.wall_area(wall) < until.wall_stress_above->value) return false;
  }
  if (until.wall_settlement_above &&
      world.wall_settlement(until.wall_settlement_above->wall) < until.wall_settlement_above->value) {
    return false;
  }
  return true;
}

template bool stop_conditions_hold(const BasicWorld<2>&, const StopConditions&);
template bool stop_conditions_hold(const BasicWorld<3>&, const StopConditions&);

}  // namespace dem::io
