// Particle state as structure-of-arrays, indexed by ParticleId. Hot data
// (positions, velocities, force sums) in parallel arrays; no per-particle
// objects. Cundall & Strack's discs have unit thickness.
#pragma once

#include <cstddef>
#include <vector>

#include "dem/ids.h"
#include "dem/math.h"

namespace dem {

struct Particles {
  // dynamic state
  std::vector<Vec2> position;        // x_i at cycle N
  std::vector<Vec2> velocity;        // x_dot_i at N - 1/2 (time-centred, eq. 22)
  std::vector<double> angular_velocity;  // theta_dot at N - 1/2 (eq. 23)
  std::vector<double> rotation;      // theta, accumulated (eq. 23a)
  // per-cycle sums (eqs. 20-21): contact forces and damping forces, moments
  std::vector<Vec2> force;
  std::vector<double> moment;
  // constant properties
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inertia;
  std::vector<MaterialId> material;

  std::size_t size() const { return position.size(); }
};

}  // namespace dem
