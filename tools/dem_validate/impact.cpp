#include "impact.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dem/world.h"

namespace dem::validation {

namespace {

MaterialDef material_of(const Sphere& s) {
  MaterialDef m;
  m.name = "steel";
  m.density = s.density;
  m.friction = s.friction;
  m.youngs_modulus = s.youngs_modulus;
  m.poisson_ratio = s.poisson_ratio;
  return m;
}

// Runs until the contact that starts after the first cycle ends; records the
// contact, interpolating the instants where the gap crosses zero (in free
// flight positions move linearly, so this is exact at both ends).
template <typename Gap, typename Forces>
ImpactResult run_impact(World3& world, Gap gap, Forces forces, std::uint64_t max_cycles) {
  ImpactResult r;
  double previous_gap = gap(world);
  double start = -1.0;
  bool slid_always = true;
  for (std::uint64_t k = 0; k < max_cycles; ++k) {
    world.cycle();
    const double g = gap(world);
    const double t = world.time();
    const double dt = world.time_step();
    if (start < 0.0 && g < 0.0) start = t - dt * g / (g - previous_gap);  // first overlap this cycle
    const auto f = forces(world);
    if (start >= 0.0 && f.touching) {
      r.history.push_back({world.time() - start, f.normal, f.tangential, f.sliding});
      r.peak_normal_force = std::max(r.peak_normal_force, f.normal);
      slid_always = slid_always && f.sliding;
    }
    if (start >= 0.0 && g >= 0.0) {
      r.contact_duration = (t - dt * g / (g - previous_gap)) - start;
      r.sliding_throughout = slid_always && !r.history.empty();
      return r;
    }
    previous_gap = g;
  }
  return r;  // no impact within max_cycles (a grazing or missing trajectory)
}

struct ContactForces {
  bool touching = false;
  double normal = 0.0, tangential = 0.0;
  bool sliding = false;
};

}  // namespace

HertzTheory hertz_theory(double m, double r, double e, double v) {
  // (5.9): alpha* = (15 m* V^2 / (16 R*^(1/2) E*))^(2/5); (5.5): N = 4/3 R*^(1/2) E* alpha^(3/2).
  const double alpha = std::pow(15.0 * m * v * v / (16.0 * std::sqrt(r) * e), 0.4);
  return {2.87 * std::pow(m * m / (r * e * e * v), 0.2), 4.0 / 3.0 * std::sqrt(r) * e * std::pow(alpha, 1.5)};
}

double maw_chi(double nu) { return (1.0 - nu) * (1.0 + 1.0 / 0.4) / (2.0 - nu); }

double maw_psi(double nu, double mu, double ratio) { return 2.0 * (1.0 - nu) / (mu * (2.0 - nu)) * ratio; }

ImpactResult sphere_wall_impact(const Sphere& sphere, const ContactModelDef& model, double speed, double angle_deg,
                                double time_step_fraction) {
  WorldDef3 def;
  def.materials = {material_of(sphere)};
  ContactModelDef m = model;
  m.material_a = m.material_b = MaterialId{0};
  def.contact_models = {m};
  const double angle = angle_deg * std::numbers::pi / 180.0;
  const double r = sphere.radius;
  ParticleDef3 p;
  p.radius = r;
  p.position = {0.0, 0.0, r * 1.001};  // just above the wall: the impact comes within a few cycles
  p.velocity = {speed * std::sin(angle), 0.0, -speed * std::cos(angle)};
  def.particles = {p};
  WallDef3 wall;
  wall.name = "wall";
  wall.point = Vec3::Zero();
  wall.h1 = wall.k1 = -1.0;
  wall.h2 = wall.k2 = 1.0;  // x-y plane, normal +z
  def.walls = {wall};
  def.time_step_fraction = time_step_fraction;
  def.threads = 1;
  World3 world(def);
  const Vec3 v0 = p.velocity;
  auto gap = [r](const World3& w) { return w.particles().position[ParticleId{0}].z() - r; };
  auto forces = [](const World3& w) {
    ContactForces f;
    for (const ContactRecord3& c : w.contacts()) {
      f = {true, c.normal_force, -c.tangential_force.x(), c.sliding};  // the force on the wall, along +x
    }
    return f;
  };
  // Time to reach the wall plus several contact durations, at the step in use.
  const double reach = 0.001 * r / std::max(speed * std::cos(angle), 1e-9);
  const auto cycles = static_cast<std::uint64_t>(std::min(2e6, (reach + 1e-3) / world.time_step()));
  ImpactResult result = run_impact(world, gap, forces, cycles);
  const auto view = world.particles();
  const Vec3 v = view.velocity[ParticleId{0}];
  const Vec3 w = view.angular_velocity[ParticleId{0}];
  result.normal_velocity_after = v.z();
  // Velocity of the sphere's point at the wall: v + omega x (-r e_z).
  result.tangential_velocity_after = (v + w.cross(Vec3(0.0, 0.0, -r))).x();
  result.restitution = angle_deg == 0.0 ? v.z() / -v0.z() : v.norm() / v0.norm();
  return result;
}

ImpactResult sphere_sphere_impact(const Sphere& sphere, const ContactModelDef& model, double speed,
                                  double time_step_fraction) {
  WorldDef3 def;
  def.materials = {material_of(sphere)};
  ContactModelDef m = model;
  m.material_a = m.material_b = MaterialId{0};
  def.contact_models = {m};
  const double r = sphere.radius;
  ParticleDef3 a, b;
  a.radius = b.radius = r;
  a.position = {-r * 1.001, 0.0, 0.0};
  b.position = {r * 1.001, 0.0, 0.0};
  a.velocity = {0.5 * speed, 0.0, 0.0};
  b.velocity = {-0.5 * speed, 0.0, 0.0};
  def.particles = {a, b};
  def.time_step_fraction = time_step_fraction;
  def.threads = 1;
  World3 world(def);
  auto gap = [r](const World3& w) {
    const auto p = w.particles();
    return (p.position[ParticleId{1}] - p.position[ParticleId{0}]).norm() - 2.0 * r;
  };
  auto forces = [](const World3& w) {
    ContactForces f;
    for (const ContactRecord3& c : w.contacts()) f = {true, c.normal_force, c.shear_force, c.sliding};
    return f;
  };
  const auto cycles = static_cast<std::uint64_t>(std::min(2e6, (0.002 * r / speed + 1e-3) / world.time_step()));
  ImpactResult result = run_impact(world, gap, forces, cycles);
  const auto view = world.particles();
  result.normal_velocity_after = (view.velocity[ParticleId{1}] - view.velocity[ParticleId{0}]).x();
  result.restitution = result.normal_velocity_after / speed;
  return result;
}

}  // namespace dem::validation
