#include "dem/service/active_run.h"

#include <algorithm>

#include "format_value.h"

namespace dem::service {

ActiveRun::ActiveRun(ReceivedCommand command, RunGoal goal, const WorldSession& world)
    : command_(std::move(command)), goal_(goal) {
  goal_.check_interval = std::max<std::uint64_t>(goal_.check_interval, 1);
  if (goal_.wall) {
    const protocol::WallForce start = world.read_wall(*goal_.wall);
    if (goal_.stress) stress_rising_ = start.normal_stress < *goal_.stress;
    if (goal_.settlement) settlement_rising_ = start.settlement < *goal_.settlement;
  }
}

std::uint64_t ActiveRun::cycles_to_next_stop() const {
  const std::uint64_t left = goal_.max_cycles - done_;
  const bool conditions = goal_.stress || goal_.settlement || goal_.kinetic_energy;
  if (!conditions) return left;
  return std::min(left, goal_.check_interval - done_ % goal_.check_interval);
}

bool ActiveRun::advance(std::uint64_t cycles, const WorldSession& world) {
  done_ += cycles;
  const bool at_check = done_ % goal_.check_interval == 0;
  if (at_check && check(world)) return true;
  return done_ >= goal_.max_cycles;
}

bool ActiveRun::check(const WorldSession& world) {
  const auto reached = [](double value, double target, bool rising) {
    return rising ? value >= target : value <= target;
  };
  if (goal_.wall && (goal_.stress || goal_.settlement)) {
    const protocol::WallForce plate = world.read_wall(*goal_.wall);
    if (goal_.stress && reached(plate.normal_stress, *goal_.stress, stress_rising_)) {
      condition_ = "the stress on " + plate.name + " reached " + format_value(plate.normal_stress) + " Pa";
    } else if (goal_.settlement && reached(plate.settlement, *goal_.settlement, settlement_rising_)) {
      condition_ = "the settlement of " + plate.name + " reached " + format_value(plate.settlement) + " m";
    }
  }
  if (condition_.empty() && goal_.kinetic_energy) {
    const double energy = world.kinetic_energy();
    if (energy < *goal_.kinetic_energy) condition_ = "the kinetic energy fell to " + format_value(energy) + " J";
  }
  condition_met_ = !condition_.empty();
  return condition_met_;
}

}  // namespace dem::service
