#include "rolling.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "dem/io/csv_file.h"
#include "dem/packing.h"
#include "dem/programme.h"
#include "dem/world.h"

namespace dem::validation {

namespace {

constexpr double kGravity = 9.81;

ContactModelDef rolling_model(double rolling_friction) {
  ContactModelDef model;
  model.law = ContactLaw::kLinearRestitution;
  model.linear = {1e6, 1e6};
  model.restitution = 0.3;
  model.rolling = RollingResistanceDef{rolling_friction, 0.3};
  return model;
}

// Rolls the ball, returns what it did.
template <int Dim>
RollingToRest roll(double rolling_friction) {
  constexpr double kRadius = 0.005, kDensity = 7800.0, kSpeed = 0.1;
  WorldDefT<Dim> def;
  def.materials = {MaterialDef{"steel", kDensity, 0.5, 0.0}};
  def.contact_models = {rolling_model(rolling_friction)};
  ParticleDefT<Dim> ball;
  ball.radius = kRadius;
  const bool disc = Dim == 2;
  const double mass = disc ? kDensity * std::numbers::pi * kRadius * kRadius
                           : kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  // Resting on the plane: pressed in by its weight.
  const double overlap = mass * kGravity / 1e6;
  ball.position[Dim - 1] = kRadius - overlap;
  ball.velocity[0] = kSpeed;
  // Rolling without slip: the contact point at rest, v = omega R.
  if constexpr (Dim == 2) {
    ball.angular_velocity = -kSpeed / kRadius;  // clockwise to roll along +x
  } else {
    ball.angular_velocity = Vec3(0.0, kSpeed / kRadius, 0.0);
  }
  def.particles = {ball};
  WallDefT<Dim> plane;
  plane.name = "plane";
  if constexpr (Dim == 2) {
    plane.h1 = -1.0;
    plane.h2 = 1.0;
  } else {
    plane.h1 = plane.k1 = -1.0;
    plane.h2 = plane.k2 = 1.0;
  }
  def.walls = {plane};
  def.gravity[Dim - 1] = -kGravity;
  def.time_step_fraction = 0.05;
  def.threads = 1;
  BasicWorld<Dim> world(def);
  RollingToRest r;
  r.dimension = Dim;
  r.rolling_friction = rolling_friction;
  r.speed = kSpeed;
  // I / (m R^2): 1/2 for a disc, 2/5 for a sphere.
  const double inertia_ratio = disc ? 0.5 : 0.4;
  const double deceleration = rolling_friction * kGravity / (1.0 + inertia_ratio);
  r.theory_time = kSpeed / deceleration;
  r.theory_distance = kSpeed * kSpeed / (2.0 * deceleration);
  const double start = world.particles().position[ParticleId{0}].x();
  const auto cycles = static_cast<std::uint64_t>(3.0 * r.theory_time / world.time_step());
  for (std::uint64_t k = 0; k < cycles; ++k) {
    world.cycle();
    const auto p = world.particles();
    const double v = p.velocity[ParticleId{0}].x();
    double contact_speed;
    if constexpr (Dim == 2) {
      contact_speed = v + p.angular_velocity[ParticleId{0}] * kRadius;
    } else {
      contact_speed = v - p.angular_velocity[ParticleId{0}].y() * kRadius;
    }
    r.largest_slip = std::max(r.largest_slip, std::abs(contact_speed) / kSpeed);
    if (v <= 1e-3 * kSpeed) {
      r.stop_time = world.time();
      r.stop_distance = p.position[ParticleId{0}].x() - start;
      break;
    }
  }
  return r;
}

}  // namespace

RollingToRest roll_to_rest(int dimension, double rolling_friction) {
  return dimension == 2 ? roll<2>(rolling_friction) : roll<3>(rolling_friction);
}

Repose angle_of_repose(double rolling_friction, std::uint64_t packing_seed) {
  // A fixed-base heap: 200 discs of 1 and 1.5 mm settle in a column 20 mm
  // wide standing on a base 50 mm wide; the column's walls are taken out
  // and it collapses; what rolls off the base's edges falls away and is
  // taken out. The heap left on the base stands at its angle of repose.
  WorldDef def;
  def.materials = {MaterialDef{"glass", 2650.0, 0.5, 0.0}};
  ContactModelDef model = rolling_model(rolling_friction);
  model.linear = {1e5, 1e5};
  def.contact_models = {model};
  RandomPackingDef packing;
  packing.min = {-0.01, 0.0};
  packing.max = {0.01, 0.12};
  packing.sizes = {{0.0015, 80}, {0.001, 120}};
  packing.seed = packing_seed;
  def.particles = generate_random_packing(packing);
  def.walls = {WallDef{"base", {0.0, 0.0}, {1, 0}, -0.025, 0.025, MaterialId{0}, {}},
               WallDef{"column_right", {0.01, 0.0}, {0, 1}, 0.0, 0.15, MaterialId{0}, {}},
               WallDef{"column_left", {-0.01, 0.15}, {0, -1}, 0.0, 0.15, MaterialId{0}, {}}};
  def.gravity = {0.0, -kGravity};
  def.threads = 1;
  World world(def);
  StageDef fill;
  fill.cycles = 200000;
  fill.until.kinetic_energy_below = 1e-8;
  fill.until.min_cycles = 2000;
  fill.until.check_interval = 500;
  run_stage(world, fill);
  world.remove_wall(WallId{1});
  world.remove_wall(WallId{2});
  Repose r;
  r.rolling_friction = rolling_friction;
  r.packing_seed = packing_seed;
  // Collapse and settle, in chunks, taking out what has left the base.
  for (int chunk = 0; chunk < 400 && !r.at_rest; ++chunk) {
    world.cycle(500);
    std::vector<ParticleId> fallen;
    const auto p = world.particles();
    for (const ParticleId i : world.particle_ids()) {
      if (p.position[i].y() < -0.005) fallen.push_back(i);
    }
    if (static_cast<int>(fallen.size()) == world.particle_count()) break;
    if (!fallen.empty()) world.remove_particles(fallen);
    r.at_rest = chunk > 10 && world.assembly_measures().kinetic_energy < 1e-9;
  }
  // The surface: the highest disc top in each 2 mm column; the slopes on
  // either side of the peak between a fifth and four fifths of its height.
  const auto p = world.particles();
  std::map<int, double> top;
  for (const ParticleId i : world.particle_ids()) {
    const Vec2 x = p.position[i];
    const int column = static_cast<int>(std::floor(x.x() / 0.002));
    top[column] = std::max(top.contains(column) ? top[column] : 0.0, x.y() + p.radius[i]);
  }
  double height = 0.0;
  int peak = 0;
  for (const auto& [column, y] : top) {
    if (y > height) height = y, peak = column;
  }
  r.height = height;
  r.discs_left = world.particle_count();
  double angle_sum = 0.0;
  int sides = 0;
  for (const int side : {-1, 1}) {
    std::vector<double> xs, ys;
    for (const auto& [column, y] : top) {
      if ((column - peak) * side <= 0 || y < 0.2 * height || y > 0.8 * height) continue;
      xs.push_back((column + 0.5) * 0.002);
      ys.push_back(y);
    }
    if (xs.size() < 2) continue;
    double mx = 0, my = 0;
    for (std::size_t k = 0; k < xs.size(); ++k) mx += xs[k], my += ys[k];
    mx /= static_cast<double>(xs.size());
    my /= static_cast<double>(xs.size());
    double sxy = 0, sxx = 0;
    for (std::size_t k = 0; k < xs.size(); ++k) sxy += (xs[k] - mx) * (ys[k] - my), sxx += (xs[k] - mx) * (xs[k] - mx);
    angle_sum += std::atan(std::abs(sxy / sxx)) * 180.0 / std::numbers::pi;
    ++sides;
  }
  if (sides > 0) r.angle_deg = angle_sum / sides;
  return r;
}

Verdict report_rolling_to_rest(const std::filesystem::path& out) {
  Verdict v;
  io::CsvFile csv(out, "rolling_to_rest.csv",
                  "dimension,rolling_friction,speed,stop_time,theory_time,stop_distance,theory_distance,largest_slip");
  std::printf("Rolling to rest (Ai et al. 2011, model C): v0 = 0.1 m/s, deceleration mu_r g / (1 + I/(m R^2))\n");
  for (const int dimension : {2, 3}) {
    for (const double mu : {0.05, 0.1, 0.2}) {
      const RollingToRest r = roll_to_rest(dimension, mu);
      csv.write_row(r.dimension, mu, r.speed, r.stop_time, r.theory_time, r.stop_distance, r.theory_distance,
                    r.largest_slip);
      const char* ball = dimension == 2 ? "disc" : "sphere";
      std::printf("  %-6s mu_r = %.2f: stops after %.5f s (theory %.5f), %.4f mm (theory %.4f), slip at most %.1e v0\n",
                  ball, mu, r.stop_time, r.theory_time, 1e3 * r.stop_distance, 1e3 * r.theory_distance, r.largest_slip);
      char label[64];
      std::snprintf(label, sizeof label, "%s mu_r = %.2f", ball, mu);
      v.near(std::string(label) + ": stopping distance / v0^2 / (2a)", r.stop_distance / r.theory_distance, 1.0, 0.01);
      v.near(std::string(label) + ": stopping time / (v0 / a)", r.stop_time / r.theory_time, 1.0, 0.01);
      // The contact point moves only by the tangential spring's give (sliding would reach v0).
      v.below(std::string(label) + ": largest contact-point speed / v0 (rolls without sliding)", r.largest_slip, 0.05);
    }
  }
  return v;
}

Verdict report_angle_of_repose(const std::filesystem::path& out, const std::vector<double>& rolling_frictions,
                               const std::vector<std::uint64_t>& packing_seeds) {
  Verdict v;
  io::CsvFile csv(out, "angle_of_repose.csv", "rolling_friction,packing_seed,angle_deg,height,discs_left,at_rest");
  std::printf(
      "Angle of repose of a fixed-base heap (a column of 200 discs, tan phi = 0.5, collapsed), by mu_r, over %zu "
      "packings:\n",
      packing_seeds.size());
  std::vector<double> medians;
  for (const double mu : rolling_frictions) {
    std::vector<double> angles;
    int at_rest = 0;
    std::printf("  mu_r = %.3f:", mu);
    for (const std::uint64_t seed : packing_seeds) {
      const Repose r = angle_of_repose(mu, seed);
      csv.write_row(mu, seed, r.angle_deg, r.height, r.discs_left, r.at_rest);
      std::printf(" %.1f%s", r.angle_deg, r.at_rest ? "" : " (not at rest)");
      angles.push_back(r.angle_deg);
      at_rest += r.at_rest ? 1 : 0;
    }
    std::ranges::sort(angles);
    medians.push_back(angles[angles.size() / 2]);
    std::printf(" deg; median %.1f, spread %.1f-%.1f\n", medians.back(), angles.front(), angles.back());
    // Without rolling resistance round discs roll off a flat base: no heap.
    if (mu > 0.0) {
      v.at_least("mu_r = " + std::to_string(mu) + ": packings whose heap comes to rest on the base", at_rest,
                 static_cast<int>(packing_seeds.size()));
    }
  }
  // The published trend (Zhou et al. 1999; Ai et al. 2011): the angle of
  // repose grows with the rolling friction and levels off.
  for (std::size_t k = 1; k < medians.size(); ++k) {
    v.at_least("median angle at mu_r = " + std::to_string(rolling_frictions[k]) + " against the one before (-1 deg)",
               medians[k], medians[k - 1] - 1.0);
  }
  if (medians.size() >= 2) {
    v.above("median angle at the largest mu_r over at the smallest, + 10 deg", medians.back(), medians.front() + 10.0);
  }
  return v;
}

}  // namespace dem::validation
