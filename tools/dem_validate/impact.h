// Single-sphere impacts through the whole engine (3D): normal impact against
// Hertz theory (Randall 1989, 5.3.1), oblique impact against the regimes of
// Maw et al. (Randall 5.3.2, 5.4), and the restitution of the linear
// spring-dashpot (Miyata et al. 2002, eq. 17).
#pragma once

#include <vector>

#include "dem/definitions.h"

namespace dem::validation {

// A sphere of one material; the wall (or the second sphere) is of the same material.
struct Sphere {
  double radius = 1e-3;           // m
  double density = 7800.0;        // kg/m^3
  double youngs_modulus = 210e9;  // Pa
  double poisson_ratio = 0.28;
  double friction = 0.12;
};

struct ImpactSample {
  double time;              // s since first contact
  double normal_force;      // N
  double tangential_force;  // N, along the incident tangential direction
  bool sliding;
};

struct ImpactResult {
  double contact_duration = 0.0;           // s, from first touch to separation, interpolated
  double peak_normal_force = 0.0;          // N
  double restitution = 0.0;                // normal: v_n after / before; oblique: |v| after / before
  double normal_velocity_after = 0.0;      // m/s, away from the wall
  double tangential_velocity_after = 0.0;  // m/s, of the contact point, along the incident direction
  bool sliding_throughout = false;
  std::vector<ImpactSample> history;
};

// A sphere hits a wall at speed v, angle_deg from the wall's normal, with
// the given contact model (its material ids are set here). No gravity.
ImpactResult sphere_wall_impact(const Sphere& sphere, const ContactModelDef& model, double speed, double angle_deg,
                                double time_step_fraction);

// Two equal spheres meet head on at a relative speed v.
ImpactResult sphere_sphere_impact(const Sphere& sphere, const ContactModelDef& model, double speed,
                                  double time_step_fraction);

// Hertz theory of normal impact (Randall 5.4-5.12).
struct HertzTheory {
  double contact_duration;   // T_c = 2.87 (m*^2 / (R* E*^2 V))^(1/5) (5.12)
  double peak_normal_force;  // N at alpha* (5.5 with 5.9)
};
HertzTheory hertz_theory(double effective_mass, double effective_radius, double contact_modulus, double speed);

// Maw's parameters (Randall 5.14-5.16).
double maw_chi(double poisson_ratio);                                                  // (5.14), solid sphere K^2 = 2/5
double maw_psi(double poisson_ratio, double friction, double tangential_over_normal);  // (5.15)

}  // namespace dem::validation
