// The single checks behind HealthMonitorT (dem/health.h), each over the
// public state of a world; numerical_health.cpp composes them.
#pragma once

#include <optional>
#include <string>

#include "dem/health.h"

namespace dem::health {

// One pass over the particles: the first whose position or velocity is
// not finite, as text, and the one travelling farthest in a step relative
// to its radius.
struct ParticleScan {
  std::optional<std::string> non_finite;
  double travel = 0.0;  // |v| dt / r, the largest
  ParticleId fastest = kInvalidId;
};
template <int Dim>
ParticleScan scan_particles(const BasicWorld<Dim>& world);

// The contact overlapping most, relative to its smaller radius, if beyond
// `limit`; `deepest` is AssemblyMeasures::deepest_overlap, so a healthy
// world costs no pass over its contacts here.
template <int Dim>
std::optional<std::string> deepest_overlap(const BasicWorld<Dim>& world, double deepest, double limit);

// Three significant digits, for messages.
std::string number(double value);

// Energy created: held and dissipated beyond what came in (the negated residual).
inline double created_energy(const EnergyBudget& e) { return -e.residual(); }

// Energy the dissipating terms put in since `start`: dashpots, friction and
// damping only take energy out, so a term booked below where it was made
// what it lost. An unstable step does that, and the residual cannot see it
// (the nine-disc case at dt = 0.05 s: the dashpots booked -1.02e13 J, which
// friction and global damping booked back).
inline double injected_energy(const EnergyBudget& now, const EnergyBudget& start) {
  const auto put_in = [](double dissipated, double before) { return before > dissipated ? before - dissipated : 0.0; };
  return put_in(now.contact_damping, start.contact_damping) + put_in(now.friction, start.friction) +
         put_in(now.global_damping, start.global_damping) + put_in(now.local_damping, start.local_damping);
}

}  // namespace dem::health
