#include "numerical_health.h"

#include <cmath>
#include <sstream>

namespace dem {
namespace health {

std::string number(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

template <int Dim>
ParticleScan scan_particles(const BasicWorld<Dim>& world) {
  const ParticleViewT<Dim> p = world.particles();
  ParticleScan scan;
  const double dt = world.time_step();
  for (const ParticleId i : world.particle_ids()) {
    if (!p.position[i].allFinite()) {
      scan.non_finite = "particle " + to_string(i) + "'s position is not finite";
      return scan;
    }
    if (!p.velocity[i].allFinite()) {
      scan.non_finite = "particle " + to_string(i) + "'s velocity is not finite";
      return scan;
    }
    const double travel = p.velocity[i].norm() * dt / p.radius[i];
    if (travel > scan.travel) {
      scan.travel = travel;
      scan.fastest = i;
    }
  }
  return scan;
}

template <int Dim>
std::optional<std::string> deepest_overlap(const BasicWorld<Dim>& world, double depth, double limit) {
  // The assembly measures found the depth; only a contact beyond the limit is looked for, to name it.
  if (!(depth > limit)) return std::nullopt;
  const ParticleViewT<Dim> p = world.particles();
  double worst = 0.0;
  const ContactRecordT<Dim>* deepest = nullptr;
  const std::vector<ContactRecordT<Dim>> contacts = world.contacts();
  for (const ContactRecordT<Dim>& c : contacts) {
    double radius = p.radius[c.first];
    if (c.second_particle != kInvalidId) radius = std::min(radius, p.radius[c.second_particle]);
    const double fraction = c.overlap / radius;
    if (fraction > worst) {
      worst = fraction;
      deepest = &c;
    }
  }
  if (deepest == nullptr || !(worst > limit)) return std::nullopt;
  const std::string other = deepest->second_particle != kInvalidId ? "particle " + to_string(deepest->second_particle)
                                                                   : "wall " + world.wall(deepest->second_wall).name;
  return "the contact of particle " + to_string(deepest->first) + " and " + other + " overlaps " + number(worst) +
         " of the smaller radius (the limit is " + number(limit) + ")";
}

template ParticleScan scan_particles(const BasicWorld<2>&);
template ParticleScan scan_particles(const BasicWorld<3>&);
template std::optional<std::string> deepest_overlap(const BasicWorld<2>&, double, double);
template std::optional<std::string> deepest_overlap(const BasicWorld<3>&, double, double);

}  // namespace health

template <int Dim>
HealthMonitorT<Dim>::HealthMonitorT(const BasicWorld<Dim>& world, HealthLimits limits) : limits_(limits) {
  if (world.cycle_count() > 0 && world.energy_budget()) {
    const EnergyBudget e = world.assembly_measures().energy;
    created_at_start_ = health::created_energy(e);
    held_at_start_ = e.kinetic + e.strain;
    budget_at_start_ = e;
    referenced_ = true;
  }
  const ParticleViewT<Dim> p = world.particles();
  double mass = 0.0, radius = 0.0;
  for (const ParticleId i : world.particle_ids()) {
    mass += p.mass[i];
    radius += p.radius[i];
  }
  if (world.particle_count() > 0) radius /= world.particle_count();
  const double speed = radius / world.time_step();
  round_off_ = 1e-12 * mass * speed * speed;
}

template <int Dim>
StepHealth HealthMonitorT<Dim>::assess(const BasicWorld<Dim>& world) {
  StepHealth health;
  health.cycle = world.cycle_count();
  const std::string at = "at cycle " + std::to_string(health.cycle) + ": ";
  const AssemblyMeasures measures = world.assembly_measures();
  std::optional<std::string> bad;
  const health::ParticleScan particles = health::scan_particles(world);
  if (!std::isfinite(measures.kinetic_energy)) bad = "the kinetic energy is not finite";
  if (!bad) bad = particles.non_finite;
  if (bad) {
    health.problem = HealthProblem::kNonFinite;
    health.message = at + *bad +
                     ": the simulation blew up; reduce the time step (time_step.fraction) or check "
                     "the stiffnesses and masses";
    return health;
  }
  const EnergyBudget& e = measures.energy;
  // A world without the energy budget books no work (gravity's, the
  // walls', a continuum field's, the dampers'): its residual would count every joule gravity
  // puts in as created. Its blow-ups are caught by the other checks.
  if (world.energy_budget() && !referenced_ && health.cycle > 0) {
    created_at_start_ = health::created_energy(e);
    held_at_start_ = e.kinetic + e.strain;
    budget_at_start_ = e;
    referenced_ = true;
  }
  const double injected = referenced_ ? health::injected_energy(e, budget_at_start_) : 0.0;
  const double created = referenced_ ? health::created_energy(e) - created_at_start_ + injected : 0.0;
  const double in_play = std::abs(e.initial_kinetic) + std::abs(e.gravity_work) + std::abs(e.wall_work) +
                         std::abs(e.continuum_work) + held_at_start_;
  most_in_play_ = std::max(most_in_play_, in_play);
  const bool beyond = referenced_ && created > round_off_ && created > limits_.max_energy_growth * most_in_play_;
  if (!beyond) suspect_created_ = 0.0;
  health.energy_suspect = beyond;
  if (beyond && suspect_created_ == 0.0) {
    suspect_created_ = created;
    suspect_cycle_ = health.cycle;
  }
  if (beyond && (health.cycle >= suspect_cycle_ + 2 || created >= 2.0 * suspect_created_)) {
    health.problem = HealthProblem::kEnergyGrowth;
    health.message = at + health::number(created) +
                     " J of energy appeared without work done (the most energy in play was " +
                     health::number(most_in_play_) + " J; the limit is " + health::number(limits_.max_energy_growth) +
                     " times that): the integration is unstable; reduce the time step (time_step.fraction)";
    if (injected > 0.0) health.message += "; dashpots, friction or damping put in " + health::number(injected) + " J";
    return health;
  }
  // Validation refuses such a step in a case; a snapshot or a parameter can still bring one.
  if (world.time_step() > world.critical_time_step() * (1.0 + 1e-9)) {
    health.problem = HealthProblem::kStepAboveCritical;
    health.message = at + "the time step " + health::number(world.time_step()) + " s exceeds the critical step " +
                     health::number(world.critical_time_step()) +
                     " s, beyond which central differences are unstable: reduce the time step (time_step_fraction)";
    return health;
  }
  if (particles.travel > limits_.max_step_travel) {
    health.problem = HealthProblem::kRunaway;
    health.message = at + "particle " + to_string(particles.fastest) + " moves " + health::number(particles.travel) +
                     " of its radius in a step (the limit is " + health::number(limits_.max_step_travel) +
                     "): the simulation blew up, or flung it out; reduce the time step (time_step.fraction) or check "
                     "the stiffnesses and masses";
    return health;
  }
  if (const auto overlap = health::deepest_overlap(world, measures.deepest_overlap, limits_.max_overlap_fraction)) {
    health.problem = HealthProblem::kOverlap;
    health.message = at + *overlap +
                     ": the particles pass through each other; reduce the time step or the "
                     "loading rate, or stiffen the contacts";
    return health;
  }
  return health;
}

template <int Dim>
bool HealthMonitorT<Dim>::motion_suspect(const BasicWorld<Dim>& world) const {
  const health::ParticleScan scan = health::scan_particles(world);
  return scan.non_finite.has_value() || scan.travel > limits_.max_step_travel;
}

template class HealthMonitorT<2>;
template class HealthMonitorT<3>;

}  // namespace dem
