#include "mindlin_loading.h"

#include <algorithm>
#include <cmath>

#include "dem/contact_driver.h"

namespace dem::validation {

namespace {

constexpr double kRadius = 0.010, kFriction = 0.3, kYoungs = 210e9, kPoisson = 0.3, kDensity = 7800.0;
constexpr double kNormalForce = 88.0;

ContactDriverDef two_spheres() {
  ContactDriverDef def;
  MaterialDef steel;
  steel.density = kDensity;
  steel.friction = kFriction;
  steel.youngs_modulus = kYoungs;
  steel.poisson_ratio = kPoisson;
  def.material_a = def.material_b = steel;
  def.model.law = ContactLaw::kHertzMindlin;
  def.radius_a = def.radius_b = kRadius;
  def.mass_a = def.mass_b = kDensity * 4.0 / 3.0 * 3.141592653589793 * kRadius * kRadius * kRadius;
  return def;
}

// Hertz (Randall 3.13) inverted: the overlap that carries N.
double overlap_for(double n) {
  const double e_star = kYoungs / (2.0 * (1.0 - kPoisson * kPoisson));
  const double r_star = 0.5 * kRadius;
  return std::pow(3.0 * n / (4.0 * e_star * std::sqrt(r_star)), 2.0 / 3.0);
}

double shear_modulus_star() { return kYoungs / (4.0 * (2.0 - kPoisson) * (1.0 + kPoisson)); }

}  // namespace

MindlinLoadingResult mindlin_constant_normal_force(int steps_per_branch) {
  ContactDriver contact(two_spheres());
  const double dt = 1e-6;
  // Press the spheres together in small steps (Randall Fig. 5.2).
  const double target = overlap_for(kNormalForce);
  for (int k = 0; k < 200; ++k) contact.step(target / 200.0, 0.0, dt);

  MindlinLoadingResult r;
  r.normal_force = contact.normal_force();
  const double mu_n = kFriction * r.normal_force;
  r.friction_force = mu_n;
  const double a = contact.contact_radius();
  const double c = 3.0 * mu_n / (16.0 * shear_modulus_star() * a);  // Miyata eq. 28 at S = mu N
  r.slip_displacement = c;
  // Closed forms at constant N (Randall 3.52-3.55 integrated; Miyata eq. 28):
  // loading T = mu N [1 - (1 - d/c)^(3/2)]; unloading from (d*, T*) and
  // reloading from (d**, T**) follow the same curve at twice the scale.
  auto loading = [&](double d) { return mu_n * (1.0 - std::pow(1.0 - d / c, 1.5)); };
  auto unloading = [&](double d, double d1, double t1) {
    return t1 - 2.0 * mu_n * (1.0 - std::pow(1.0 - (d1 - d) / (2.0 * c), 1.5));
  };
  auto reloading = [&](double d, double d2, double t2) {
    return t2 + 2.0 * mu_n * (1.0 - std::pow(1.0 - (d - d2) / (2.0 * c), 1.5));
  };

  double d = 0.0;
  auto run = [&](const std::string& branch, double to, auto theory) {
    const double step = (to - d) / steps_per_branch;
    for (int k = 0; k < steps_per_branch; ++k) {
      contact.step(0.0, step, dt);
      d += step;
      if ((k + 1) % (steps_per_branch / 20) == 0) {
        const MindlinPoint p{branch, d, contact.tangential_force(), theory(d)};
        r.points.push_back(p);
        r.largest_error = std::max(r.largest_error, std::abs(p.simulated - p.theory) / mu_n);
      }
    }
  };
  // Load to 0.8 c, unload to -0.5 c, reload to 0.8 c (inside the first loop).
  run("loading", 0.8 * c, loading);
  const double d1 = d, t1 = contact.tangential_force();
  run("unloading", -0.5 * c, [&](double x) { return unloading(x, d1, t1); });
  const double d2 = d, t2 = contact.tangential_force();
  run("reloading", 0.8 * c, [&](double x) { return reloading(x, d2, t2); });
  return r;
}

VaryingNormalResult mindlin_varying_normal_force() {
  ContactDriver contact(two_spheres());
  const double dt = 1e-6;
  const double base = overlap_for(kNormalForce);
  for (int k = 0; k < 200; ++k) contact.step(base / 200.0, 0.0, dt);
  const double g = shear_modulus_star();
  VaryingNormalResult r;
  // Normal approach and tangential displacement per step, over phases that
  // raise and lower N while the tangential motion loads, unloads and reloads.
  struct Phase {
    double approach, tangential;
    int steps;
  };
  const double unit = 0.3 * base / 1000.0;
  const Phase phases[] = {{+unit, 0.05 * unit, 1000},  // N rising fast, small tangential motion: lagging
                          {+unit, 2.0 * unit, 1000},   // N rising, tangential loading towards slip
                          {-unit, 1.0 * unit, 1000},   // N falling while loading: sliding
                          {0.0, -2.0 * unit, 1000},    // unloading at constant N
                          {-0.5 * unit, 1.5 * unit, 1000}};  // N falling, reloading
  for (const Phase& phase : phases) {
    for (int k = 0; k < phase.steps; ++k) {
      const double n0 = contact.normal_force(), t0 = contact.tangential_force();
      const double a0 = contact.contact_radius();
      contact.step(phase.approach, phase.tangential, dt);
      const double n = contact.normal_force(), t = contact.tangential_force();
      const double a = contact.contact_radius();
      r.largest_ratio = std::max(r.largest_ratio, std::abs(t) / (kFriction * n));
      r.sliding_steps += contact.sliding();
      // Eq. 3.98 / 4.16: while ds < mu dN / (8 G* a), theta = 1 and dT = 8 G* a ds.
      const double dn = n - n0;
      if (dn > 0.0 && std::abs(phase.tangential) < kFriction * dn / (8.0 * g * a) && !contact.sliding() && a0 > 0.0) {
        ++r.lagging_checks;
        const double expected = 8.0 * g * a * phase.tangential;
        r.largest_lag_error = std::max(r.largest_lag_error, std::abs((t - t0) - expected) / std::abs(expected));
      }
    }
  }
  return r;
}

}  // namespace dem::validation
