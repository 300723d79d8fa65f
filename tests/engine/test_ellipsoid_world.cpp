// Ellipsoids in a 3D world (Miyata et al. 2002, section 2.4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dem/world.h"

namespace dem {
namespace {

MaterialDef rock() { return MaterialDef{"rock", 2650.0, 0.6, 0.0, 70e9, 0.2}; }

ContactModelDef hertz(double restitution) {
  ContactModelDef m;
  m.law = ContactLaw::kHertzLinearTangential;  // Miyata eqs. 47 and 49
  if (restitution < 1.0) m.hertz.restitution = restitution;
  return m;
}

WallDef3 floor_plate() {
  WallDef3 w;
  w.name = "floor";
  w.h1 = w.k1 = -2.0;
  w.h2 = w.k2 = 2.0;
  return w;
}

// A particle falling onto the floor, as a sphere or as an ellipsoid with equal axes.
WorldDef3 drop(bool as_ellipsoid, const Vec3& velocity) {
  WorldDef3 def;
  def.materials = {rock()};
  def.contact_models = {hertz(1.0)};
  ParticleDef3 p;
  p.position = {0.0, 0.0, 0.1001};
  p.radius = 0.1;
  p.velocity = velocity;
  if (as_ellipsoid) p.shape.axes = Vec3::Constant(0.1);
  def.particles = {p};
  def.walls = {floor_plate()};
  def.time_step_fraction = 0.05;
  def.threads = 1;
  return def;
}

TEST(EllipsoidWorld, EqualAxesReproduceTheSphere) {
  World3 sphere(drop(false, {0.3, 0.0, -0.5})), ellipsoid(drop(true, {0.3, 0.0, -0.5}));
  EXPECT_NEAR(ellipsoid.particles().mass[ParticleId{0}], sphere.particles().mass[ParticleId{0}],
              1e-15 * sphere.particles().mass[ParticleId{0}]);
  double peak_sphere = 0.0, peak_ellipsoid = 0.0;
  for (int k = 0; k < 4000; ++k) {
    sphere.cycle();
    ellipsoid.cycle();
    peak_sphere = std::max(peak_sphere, sphere.wall_measures()[0].normal_force);
    peak_ellipsoid = std::max(peak_ellipsoid, ellipsoid.wall_measures()[0].normal_force);
  }
  const auto s = sphere.particles(), e = ellipsoid.particles();
  std::printf(
      "peak force sphere %.9e, ellipsoid %.9e; rebound velocity (%.9f %.9f) vs (%.9f %.9f), spin %.6f vs %.6f\n",
      peak_sphere, peak_ellipsoid, s.velocity[ParticleId{0}].x(), s.velocity[ParticleId{0}].z(),
      e.velocity[ParticleId{0}].x(), e.velocity[ParticleId{0}].z(), s.angular_velocity[ParticleId{0}].y(),
      e.angular_velocity[ParticleId{0}].y());
  EXPECT_GT(peak_sphere, 0.0);
  EXPECT_NEAR(peak_ellipsoid / peak_sphere, 1.0, 1e-9);
  EXPECT_NEAR((e.velocity[ParticleId{0}] - s.velocity[ParticleId{0}]).norm(), 0.0, 1e-9);
  EXPECT_NEAR((e.angular_velocity[ParticleId{0}] - s.angular_velocity[ParticleId{0}]).norm(), 0.0, 1e-7);
}

TEST(EllipsoidWorld, TumblingFreeEllipsoidKeepsEnergyAndAngularMomentum) {
  WorldDef3 def;
  def.materials = {rock()};
  def.contact_models = {hertz(1.0)};
  ParticleDef3 p;
  p.shape.axes = {0.371, 0.260, 0.182};  // Miyata's section 3.3 particle
  p.angular_velocity = {1.0, 0.2, 3.0};  // near the minor axis of inertia... and off it
  def.particles = {p};
  def.fixed_time_step = 1e-4;
  World3 world(def);
  auto momentum = [&] {
    const auto v = world.particles();
    const Quaternion q = v.rotation[ParticleId{0}];
    const Vec3 body = q.conjugate() * v.angular_velocity[ParticleId{0}];
    const Vec3 principal =
        2650.0 * (4.0 / 3.0 * std::numbers::pi * 0.371 * 0.260 * 0.182) / 5.0 *
        Vec3(0.260 * 0.260 + 0.182 * 0.182, 0.371 * 0.371 + 0.182 * 0.182, 0.371 * 0.371 + 0.260 * 0.260);
    return Vec3(q * principal.cwiseProduct(body));
  };
  const double e0 = world.assembly_measures().kinetic_energy;
  const Vec3 l0 = momentum();
  world.cycle(20000);  // 2 s, several turns
  const double e1 = world.assembly_measures().kinetic_energy;
  const Vec3 l1 = momentum();
  std::printf("free tumbling over 2 s: energy %.6e -> %.6e (%.2e), angular momentum change %.2e\n", e0, e1,
              e1 / e0 - 1.0, (l1 - l0).norm() / l0.norm());
  EXPECT_NEAR(e1 / e0, 1.0, 1e-3);
  EXPECT_LT((l1 - l0).norm() / l0.norm(), 1e-3);
}

TEST(EllipsoidWorld, DroppedEllipsoidRestsOnItsFlattestSide) {
  WorldDef3 def;
  def.materials = {rock()};
  def.contact_models = {hertz(0.3)};
  ParticleDef3 p;
  p.shape.axes = {0.371, 0.260, 0.182};
  p.shape.orientation = Quaternion(Eigen::AngleAxisd(0.5, Vec3(1.0, 1.0, 0.3).normalized()));
  p.position = {0.0, 0.0, 0.5};
  def.particles = {p};
  def.walls = {floor_plate()};
  def.gravity = {0.0, 0.0, -9.81};
  def.damping.local_alpha = 0.3;
  def.time_step_fraction = 0.2;
  World3 world(def);
  world.cycle(200000);
  const auto v = world.particles();
  const Vec3 up_in_body = v.rotation[ParticleId{0}].conjugate() * Vec3::UnitZ();
  const double weight = 9.81 * v.mass[ParticleId{0}];
  std::printf("at rest: centre at %.5f m (a3 = 0.182), |a3 axis . z| = %.6f, floor %.6e of weight %.6e N, KE %.2e J\n",
              v.position[ParticleId{0}].z(), std::abs(up_in_body.z()), world.wall_measures()[0].normal_force, weight,
              world.assembly_measures().kinetic_energy);
  EXPECT_NEAR(std::abs(up_in_body.z()), 1.0, 1e-3);  // the shortest axis stands vertical
  EXPECT_NEAR(v.position[ParticleId{0}].z(), 0.182, 1e-3);
  EXPECT_NEAR(world.wall_measures()[0].normal_force, weight, 1e-3 * weight);
}

// A loading plate is placed on the sample's top (Miyata 3.3): what counts
// is how far the bodies reach, not their bounding spheres. A flat-lying
// ellipsoid reaches its smallest semi-axis up; turned a quarter about x, its
// middle one.
TEST(EllipsoidWorld, FurthestReachIsTheSurfaceNotTheBoundingSphere) {
  WorldDef3 def = drop(true, Vec3::Zero());
  def.particles[0].shape.axes = {0.3, 0.2, 0.1};
  def.particles[0].position = {0.0, 0.0, 0.5};
  ParticleDef3 turned = def.particles[0];
  turned.position = {1.0, 0.0, 0.4};
  turned.shape.orientation = Quaternion(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()));
  def.particles.push_back(turned);
  const World3 world(def);
  EXPECT_NEAR(world.furthest_reach(Vec3::UnitZ()), 0.6, 1e-12);    // 0.5 + 0.1, not 0.5 + 0.3
  EXPECT_NEAR(world.furthest_reach(-Vec3::UnitZ()), -0.2, 1e-12);  // the turned one: 0.4 - 0.2 below
  EXPECT_NEAR(world.furthest_reach(Vec3::UnitX()), 1.3, 1e-12);
}

}  // namespace
}  // namespace dem
