// How far a running stage of a programme is toward its end (StageProgress,
// case_programme.h): the share of its target that a wall's stress or
// settlement, or a box's deviator strain, has reached - the measures the
// engine's stop rule compares (dem/programme.h StopConditions) - else the
// share of its cycles; and what of a run's stop conditions holds, said
// with the values reached (conditions_reached).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dem/service/case_programme.h"
#include "dem/service/world_view.h"
#include "format_value.h"

namespace dem::service {

namespace {

double share(double value, double target) {
  if (!(target > 0.0) || !std::isfinite(value)) return 0.0;
  return std::clamp(value / target, 0.0, 1.0);
}

// "900 kPa", "1.2 MPa", "35 Pa": stresses as people read them.
std::string stress_text(double pascals) {
  char text[48];
  const double magnitude = std::abs(pascals);
  if (magnitude >= 1e6) {
    std::snprintf(text, sizeof text, "%.4g MPa", pascals / 1e6);
  } else if (magnitude >= 1e3) {
    std::snprintf(text, sizeof text, "%.4g kPa", pascals / 1e3);
  } else {
    std::snprintf(text, sizeof text, "%.4g Pa", pascals);
  }
  return text;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

template <int Dim>
StageProgress stage_progress(const std::vector<StageDefT<Dim>>& stages, std::size_t index, std::uint64_t stage_cycles,
                             const WorldSession& session) {
  const StageDefT<Dim>& stage = stages.at(index);
  const BasicWorld<Dim>& world = session.world<Dim>();
  const StopConditions& until = stage.until;
  StageProgress progress;
  progress.fraction = 1.0;
  const auto measure = [&](double fraction, std::string text) {
    // Every condition must hold: the stage is as far as its least advanced measure.
    if (!progress.measured || fraction < progress.fraction) {
      progress.fraction = fraction;
      progress.text = std::move(text);
    }
    progress.measured = true;
  };
  if (until.wall_stress_above) {
    const WallId wall = until.wall_stress_above->wall;
    const double stress = world.wall_stress(wall);
    measure(share(stress, until.wall_stress_above->value), world.wall(wall).name + " stress " + stress_text(stress) +
                                                               " of " + stress_text(until.wall_stress_above->value));
  }
  if (until.wall_settlement_above) {
    const WallId wall = until.wall_settlement_above->wall;
    const double settlement = world.wall_settlement(wall);
    measure(share(settlement, until.wall_settlement_above->value),
            world.wall(wall).name + " settlement " + number_text(settlement) + " m of " +
                number_text(until.wall_settlement_above->value) + " m");
  }
  if (until.deviator_strain_above && world.box_control()) {
    const double strain = world.box_measure().deviator_strain;
    measure(share(strain, *until.deviator_strain_above),
            "deviator strain " + number_text(strain) + " of " + number_text(*until.deviator_strain_above));
  }
  if (!progress.measured) {
    progress.fraction = share(static_cast<double>(stage_cycles), static_cast<double>(stage.cycles));
    progress.text = "cycle " + std::to_string(stage_cycles) + " of " + (has_stop_condition(until) ? "at most " : "") +
                    std::to_string(stage.cycles);
  }
  return progress;
}

}  // namespace

std::string conditions_reached(const StopConditions& until, const WorldSession& world) {
  std::vector<std::string> held;
  if (until.wall_stress_above) {
    const protocol::WallForce plate = read_wall(world, until.wall_stress_above->wall);
    held.push_back("the stress on " + plate.name + " reached " + format_value(plate.normal_stress) + " Pa");
  }
  if (until.wall_settlement_above) {
    const protocol::WallForce plate = read_wall(world, until.wall_settlement_above->wall);
    held.push_back("the settlement of " + plate.name + " reached " + format_value(plate.settlement) + " m");
  }
  if (until.kinetic_energy_below) {
    held.push_back("the kinetic energy fell to " + format_value(kinetic_energy(world)) + " J");
  }
  std::string text;
  for (const std::string& part : held) text += (text.empty() ? "" : " and ") + part;
  return text;
}

StageProgress CaseProgramme::progress(std::size_t stage, std::uint64_t stage_cycles, const WorldSession& world) const {
  return std::visit([&](const auto& stages) { return stage_progress(stages, stage, stage_cycles, world); }, stages_);
}

}  // namespace dem::service
