#include "dem/programme.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

namespace dem {

namespace {

template <int Dim>
bool servos_settled(const BasicWorld<Dim>& world, double tolerance) {
  bool any = false;
  std::vector<bool> boxed(static_cast<std::size_t>(world.wall_count()), false);
  if (const auto& box = world.box_control()) {
    const BoxMeasureT<Dim> m = world.box_measure();
    for (int i = 0; i < Dim; ++i) {
      const BoxAxisDef& a = box->axes[static_cast<std::size_t>(i)];
      boxed[a.lower.index()] = boxed[a.upper.index()] = true;
      if (a.control == AxisControl::kStrainRate) continue;
      any = true;
      if (std::abs(m.stress[i] - m.target[i]) > tolerance * std::abs(m.target[i])) return false;
    }
  }
  for (const WallMeasureT<Dim>& m : world.wall_measures()) {
    const auto& servo = world.wall(m.wall).motion.servo;
    if (!servo || boxed[m.wall.index()] || world.wall(m.wall).removed) continue;
    any = true;
    if (std::abs(m.normal_force - servo->target_force) > tolerance * std::abs(servo->target_force)) return false;
  }
  return any;
}

}  // namespace

template <int Dim>
bool stop_conditions_hold(const BasicWorld<Dim>& world, const StopConditions& until) {
  const bool needs_assembly = until.kinetic_energy_below || until.out_of_balance_below ||
                              until.kinetic_to_elastic_below || until.unbalanced_force_below;
  const AssemblyMeasures a = needs_assembly ? world.assembly_measures() : AssemblyMeasures{};
  if (until.kinetic_energy_below && !(a.kinetic_energy < *until.kinetic_energy_below)) return false;
  if (until.out_of_balance_below && !(a.contacts > 0 && a.out_of_balance < *until.out_of_balance_below)) return false;
  if (until.kinetic_to_elastic_below && !(a.contacts > 0 && a.kinetic_to_elastic < *until.kinetic_to_elastic_below)) {
    return false;
  }
  if (until.unbalanced_force_below && !(a.contacts > 0 && a.unbalanced_force < *until.unbalanced_force_below)) {
    return false;
  }
  if (until.servo_tolerance && !servos_settled(world, *until.servo_tolerance)) return false;
  if (until.wall_stress_above && world.wall_stress(until.wall_stress_above->wall) < until.wall_stress_above->value) {
    return false;
  }
  if (until.wall_settlement_above &&
      world.wall_settlement(until.wall_settlement_above->wall) < until.wall_settlement_above->value) {
    return false;
  }
  if (until.deviator_strain_above &&
      (!world.box_control() || world.box_measure().deviator_strain < *until.deviator_strain_above)) {
    return false;
  }
  if (until.region_out_of_balance_below) {
    const auto* region = std::get_if<RegionT<Dim>>(&until.region_out_of_balance_below->region);
    assert(region != nullptr && "a region of another dimension than the world's");
    const double ratio = world.out_of_balance(*region);
    if (!(ratio > 0.0 && ratio < until.region_out_of_balance_below->value)) return false;
  }
  return true;
}

bool has_stop_condition(const StopConditions& until) {
  return until.kinetic_energy_below || until.out_of_balance_below || until.kinetic_to_elastic_below ||
         until.unbalanced_force_below || until.servo_tolerance || until.wall_stress_above ||
         until.wall_settlement_above || until.deviator_strain_above || until.region_out_of_balance_below;
}

template bool stop_conditions_hold<2>(const BasicWorld<2>&, const StopConditions&);
template bool stop_conditions_hold<3>(const BasicWorld<3>&, const StopConditions&);

namespace {

// Miyata et al. (2002) 3.1, eq. 60: remove the particles whose centres lie
// above height + amplitude sin(2 pi x / wavelength).
template <int Dim>
void trim(BasicWorld<Dim>& world, const TrimDef& t) {
  const auto p = world.particles();
  std::vector<ParticleId> above;
  for (const ParticleId i : world.particle_ids()) {
    const Vec<Dim>& x = p.position[i];
    const double surface = t.height + t.amplitude * std::sin(2.0 * std::numbers::pi * x[0] / t.wavelength);
    if (x[Dim - 1] > surface) above.push_back(i);
  }
  world.remove_particles(above);
}

// Sets a wall on the sample: along its normal, `clearance` beyond the
// particle surface that reaches furthest towards it.
template <int Dim>
void place_on_sample(BasicWorld<Dim>& world, const PlaceWallDef& place) {
  const auto& wall = world.wall(place.wall);
  Vec<Dim> normal;  // towards the particles
  if constexpr (Dim == 2) {
    normal = counter_clockwise_perpendicular(wall.direction);
  } else {
    normal = wall.direction.cross(wall.direction2);
  }
  const double reach = world.furthest_reach(Vec<Dim>(-normal));
  const double shift = -wall.point.dot(normal) - (reach + place.clearance);
  world.place_wall(place.wall, Vec<Dim>(wall.point + shift * normal));
}

// A stage's start actions (StageDefT's list).
template <int Dim>
void start_stage(BasicWorld<Dim>& world, const StageDefT<Dim>& stage) {
  if (stage.trim) trim(world, *stage.trim);
  if (stage.place_wall) place_on_sample(world, *stage.place_wall);
  if (stage.release_box_control) world.set_box_control(std::nullopt);
  for (const WallId wall : stage.remove_walls) world.remove_wall(wall);
  for (const auto& [wall, motion] : stage.wall_motions) world.set_wall_motion(wall, motion);
  if (stage.box_control) world.set_box_control(stage.box_control);
  if (stage.damping) world.set_damping(*stage.damping);
  if (stage.body_force) world.set_body_force(*stage.body_force);
  if (stage.time_step) {
    if (stage.time_step->fixed > 0.0) {
      world.set_fixed_time_step(stage.time_step->fixed);
    } else {
      world.set_time_step_fraction(stage.time_step->fraction);
    }
  }
  for (const auto& [material, friction] : stage.frictions) world.set_friction(material, friction);
}

}  // namespace

template <int Dim>
StageRunT<Dim>::StageRunT(BasicWorld<Dim>& world, StageDefT<Dim> stage)
    : world_(&world),
      stage_(std::move(stage)),
      conditional_(has_stop_condition(stage_.until)),
      check_interval_(std::max<std::uint64_t>(stage_.until.check_interval, 1)) {
  start_stage(world, stage_);
  over_ = stage_.cycles == 0;
}

template <int Dim>
std::uint64_t StageRunT<Dim>::cycles_to_next_stop() const {
  if (over_) return 0;
  const std::uint64_t left = stage_.cycles - result_.cycles_run;
  if (!conditional_) return left;
  return std::min(left, check_interval_ - result_.cycles_run % check_interval_);
}

template <int Dim>
void StageRunT<Dim>::cycle(std::uint64_t cycles) {
  world_->cycle(cycles);
  result_.cycles_run += cycles;
}

template <int Dim>
bool StageRunT<Dim>::check() {
  if (conditional_ && result_.cycles_run >= stage_.until.min_cycles && result_.cycles_run % check_interval_ == 0 &&
      stop_conditions_hold(*world_, stage_.until)) {
    result_.condition_met = true;
    over_ = true;
  }
  if (result_.cycles_run >= stage_.cycles) over_ = true;
  return over_;
}

template <int Dim>
StageResult run_stage(BasicWorld<Dim>& world, const StageDefT<Dim>& stage, std::uint64_t interval,
                      const std::type_identity_t<StageObserverT<Dim>>& observer) {
  StageRunT<Dim> run(world, stage);
  while (!run.over()) {
    // Advance to the next output row, condition check or the stage's end;
    // the row comes before the check at the same cycle.
    std::uint64_t chunk = run.cycles_to_next_stop();
    if (interval > 0) chunk = std::min(chunk, interval - run.result().cycles_run % interval);
    run.cycle(chunk);
    if (observer && interval > 0 && run.result().cycles_run % interval == 0 && !observer(world)) break;
    run.check();
  }
  return run.result();
}

template <int Dim>
StageDefT<Dim> stage_remainder(StageDefT<Dim> stage, std::uint64_t done) {
  stage.trim.reset();
  stage.place_wall.reset();
  stage.remove_walls.clear();
  stage.wall_motions.clear();
  stage.box_control.reset();
  stage.release_box_control = false;
  stage.damping.reset();
  stage.body_force.reset();
  stage.time_step.reset();
  stage.frictions.clear();
  stage.cycles -= std::min(done, stage.cycles);
  stage.until.min_cycles = stage.until.min_cycles > done ? stage.until.min_cycles - done : 0;
  return stage;
}

template StageResult run_stage<2>(BasicWorld<2>&, const StageDefT<2>&, std::uint64_t, const StageObserverT<2>&);
template StageResult run_stage<3>(BasicWorld<3>&, const StageDefT<3>&, std::uint64_t, const StageObserverT<3>&);
template class StageRunT<2>;
template class StageRunT<3>;
template StageDefT<2> stage_remainder<2>(StageDefT<2>, std::uint64_t);
template StageDefT<3> stage_remainder<3>(StageDefT<3>, std::uint64_t);

}  // namespace dem
