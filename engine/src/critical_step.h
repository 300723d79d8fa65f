// The pieces of a contact law's critical time step (time_step.cpp): the
// limit of central differences for one mode of a particle on a contact
// with a body that does not move, and Rayleigh's step. Each law puts its
// own together (critical_time_step, undamped_critical_time_step).
#pragma once

#include "contact_params.h"
#include "dem/definitions.h"

namespace dem {

// The particle whose step is estimated, and its material.
struct StepParticle {
  double mass;
  double inertia;
  double radius;
  const MaterialDef& material;
};

// What a dashpot of damping ratio zeta acting on the last step's velocity
// leaves of the undamped limit omega dt < 2: sqrt(1 + zeta^2) - zeta.
double damped_step_factor(double zeta);
// The critical step of a mass (or moment of inertia) on a spring with a
// dashpot on the last step's velocity, under local damping `local`.
double mode_critical_step(double mass, double stiffness, double dashpot, double local);
// Randall (1989) 4.33-4.34: the time for a Rayleigh wave to cross a
// particle, dt = pi R sqrt(rho / G) / (0.1631 nu + 0.876605).
double rayleigh_time_step(const MaterialDef& material, double radius);

// The linear laws' modes, k_n / m, k_s / m and (k_s R^2 + k_roll) / I,
// with the law's normal and shear dashpots (Cundall & Strack, Motion).
double linear_critical_step(const StepParticle& particle, const ContactParams& c, double normal_dashpot,
                            double shear_dashpot, const DampingDef& damping);
// Undamped, 2 sqrt(m / k_n) and 2 sqrt(I / (k_s R^2)) (Cundall & Strack, Motion).
double linear_undamped_critical_step(const StepParticle& particle, const ContactParams& c);

}  // namespace dem
