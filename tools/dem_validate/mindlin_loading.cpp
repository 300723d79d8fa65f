#include "mindlin_loading.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dem/contact_driver.h"
#include "dem/world.h"

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

// Hertz (Randall 3.13) inverted: the overlap that carries N at an
// effective radius R* (two spheres: R/2; a sphere on a wall: R).
double overlap_for(double n, double r_star = 0.5 * kRadius) {
  const double e_star = kYoungs / (2.0 * (1.0 - kPoisson * kPoisson));
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
  const Phase phases[] = {{+unit, 0.05 * unit, 1000},        // N rising fast, small tangential motion: lagging
                          {+unit, 2.0 * unit, 1000},         // N rising, tangential loading towards slip
                          {-unit, 1.0 * unit, 1000},         // N falling while loading: sliding
                          {0.0, -2.0 * unit, 1000},          // unloading at constant N
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

FreshContactResult mindlin_fresh_contact_rising_normal_force(bool wall) {
  // Bodies so heavy that the contact force cannot change their motion: the
  // relative displacement is prescribed, as by Randall's kinematic walls (5.2).
  MaterialDef steel;
  steel.density = 1e30;
  steel.friction = kFriction;
  steel.youngs_modulus = kYoungs;
  steel.poisson_ratio = kPoisson;
  WorldDef3 def;
  def.materials = {steel};
  ContactModelDef model;
  model.material_a = model.material_b = MaterialId{0};
  model.law = ContactLaw::kHertzMindlin;
  def.contact_models = {model};
  const double r_star = wall ? kRadius : 0.5 * kRadius;
  const double g = shear_modulus_star();
  const double mu = kFriction;
  // N rises by a quarter over the run while delta goes to 0.8 of the final
  // delta*: ds exceeds mu dN / (8 G* a) (3.65) by about six at every step,
  // so the loading case (3.68-3.69) holds throughout.
  constexpr int kSteps = 4000;
  const double dt = 1e-7;
  const double start_overlap = overlap_for(kNormalForce, r_star);
  const double end_overlap = start_overlap * std::pow(1.25, 2.0 / 3.0);
  const double end_slip = 3.0 * mu * 1.25 * kNormalForce / (16.0 * g * std::sqrt(r_star * end_overlap));
  const double approach_speed = (end_overlap - start_overlap) / (kSteps * dt);
  const double tangential_speed = 0.8 * end_slip / (kSteps * dt);
  ParticleDef3 moving;
  moving.radius = kRadius;
  moving.velocity = {tangential_speed, 0.0, -approach_speed};
  if (wall) {
    WallDef3 plane;  // z = 0, normal +z, same steel
    plane.name = "wall";
    plane.h1 = plane.k1 = -1.0;
    plane.h2 = plane.k2 = 1.0;
    def.walls = {plane};
    moving.position = {0.0, 0.0, kRadius - start_overlap};
    def.particles = {moving};
  } else {
    ParticleDef3 fixed;
    fixed.radius = kRadius;
    moving.position = {0.0, 0.0, 2.0 * kRadius - start_overlap};
    def.particles = {fixed, moving};
  }
  def.fixed_time_step = dt;
  def.threads = 1;
  // The world's first force pass forms the contact with its whole overlap.
  World3 world(def);
  FreshContactResult r;
  r.wall = wall;
  const std::string branch = wall ? "fresh_wall" : "fresh_pair";
  for (int k = 0; k <= kSteps; ++k) {
    if (k > 0) world.cycle();
    const auto contacts = world.contacts();
    if (contacts.size() != 1) throw std::runtime_error("fresh contact: expected one contact");
    const ContactRecord3& c = contacts.front();
    const auto p = world.particles();
    const ParticleId id{wall ? 0 : 1};
    // delta: the tangential displacement since the contact formed (the
    // first pass already moved it by one step's displacement).
    const double delta = (p.position[id].x() + tangential_speed * dt);
    const double n = c.normal_force;
    const double a = std::sqrt(r_star * c.overlap);
    const double slip = 3.0 * mu * n / (16.0 * g * a);
    const double theory = mu * n * (1.0 - std::pow(std::max(0.0, 1.0 - delta / slip), 1.5));
    const double t = c.tangential_force.norm();
    if (k == 0) r.initial_normal_force = n;
    r.final_normal_force = n;
    r.final_ratio = delta / slip;
    r.sliding = r.sliding || c.sliding;
    r.largest_error = std::max(r.largest_error, std::abs(t - theory) / (mu * n));
    if (k % (kSteps / 20) == 0) r.points.push_back({branch, delta, t, theory});
  }
  return r;
}

}  // namespace dem::validation
