#include "dem/service/active_run.h"

#include "format_value.h"

namespace dem::service {

ActiveRun::ActiveRun(ReceivedCommand command, const RunGoal& goal, WorldSession& world)
    : command_(std::move(command)),
      until_(goal.until),
      total_(goal.max_cycles),
      stepper_(world.begin_run(goal.max_cycles, goal.until)) {}

bool ActiveRun::step(std::uint64_t cycles, const WorldSession& world) {
  stepper_->cycle(cycles);
  const bool over = stepper_->check();
  if (stepper_->result().condition_met) describe(world);
  return over;
}

void ActiveRun::describe(const WorldSession& world) {
  std::vector<std::string> held;
  if (until_.wall_stress_above) {
    const protocol::WallForce plate = world.read_wall(until_.wall_stress_above->wall);
    held.push_back("the stress on " + plate.name + " reached " + format_value(plate.normal_stress) + " Pa");
  }
  if (until_.wall_settlement_above) {
    const protocol::WallForce plate = world.read_wall(until_.wall_settlement_above->wall);
    held.push_back("the settlement of " + plate.name + " reached " + format_value(plate.settlement) + " m");
  }
  if (until_.kinetic_energy_below) {
    held.push_back("the kinetic energy fell to " + format_value(world.kinetic_energy()) + " J");
  }
  condition_.clear();
  for (const std::string& part : held) condition_ += (condition_.empty() ? "" : " and ") + part;
}

}  // namespace dem::service
