// Walls of triangle faces (Miyata et al. 2002, 2.4 and eqs. 57-59): the
// nearest point of a face, triangular coordinates, and spheres and
// ellipsoids meeting a plate built of faces as they meet a rectangle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "dem/error.h"
#include "dem/world.h"
#include "walls.h"

namespace dem {
namespace {

using Triangle = std::array<Vec3, 3>;

// The nearest of many points spread over the triangle: the reference the
// exact Voronoi-region answer must beat or match.
Vec3 nearest_by_sampling(const Triangle& t, const Vec3& x, int n) {
  Vec3 best = t[0];
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double a = double(i) / n, b = double(j) / n;
      const Vec3 q = t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]);
      if ((q - x).squaredNorm() < (best - x).squaredNorm()) best = q;
    }
  }
  return best;
}

TEST(TriangleWalls, ClosestPointMatchesSamplingInEveryRegion) {
  const Triangle t{Vec3(0.0, 0.0, 0.0), Vec3(1.0, 0.2, 0.1), Vec3(0.3, 0.9, -0.2)};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 2.5);
  double worst = 0.0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 x(u(rng), u(rng), u(rng));
    const Vec3 exact = closest_point_on_triangle(t, x);
    const Vec3 sampled = nearest_by_sampling(t, x, 400);
    // The exact point lies in the triangle and is no farther than any sample...
    EXPECT_GE((triangular_coordinates(t, exact).array()).minCoeff(), -1e-12);
    EXPECT_LE((exact - x).norm(), (sampled - x).norm() + 1e-12);
    // ... and the samples come within their spacing of it.
    worst = std::max(worst, (exact - sampled).norm());
  }
  std::printf("largest gap between the exact nearest point and a 400-per-edge sampling: %.2e m\n", worst);
  EXPECT_LT(worst, 5e-3);
}

TEST(TriangleWalls, TriangularCoordinatesAreAreaFractions) {
  const Triangle t{Vec3(0.0, 0.0, 1.0), Vec3(2.0, 0.0, 1.0), Vec3(0.0, 2.0, 1.0)};
  const Vec3 inside = triangular_coordinates(t, {0.5, 0.5, 1.0});  // eqs. 57-58
  EXPECT_NEAR(inside.sum(), 1.0, 1e-15);
  EXPECT_NEAR(inside.x(), 0.5, 1e-15);  // opposite corner I: area 1 of 2
  EXPECT_NEAR(inside.y(), 0.25, 1e-15);
  EXPECT_NEAR(inside.z(), 0.25, 1e-15);
  const Vec3 outside = triangular_coordinates(t, {1.5, 1.5, 1.0});  // past the edge JK (eq. 59 fails)
  EXPECT_LT(outside.x(), 0.0);
  EXPECT_NEAR(outside.sum(), 1.0, 1e-15);
}

MaterialDef rock() { return MaterialDef{"rock", 2650.0, 0.6, 0.0, 70e9, 0.2}; }

ContactModelDef hertz() {
  ContactModelDef m;
  m.law = ContactLaw::kHertzLinearTangential;
  m.hertz.restitution = 0.5;
  return m;
}

// The square -h..h in x and y at height z, as a rectangle or as two faces
// split along the diagonal through (-h,-h) and (h,h).
WallDef3 plate(double h, bool of_triangles) {
  WallDef3 w;
  w.name = "plate";
  w.h1 = w.k1 = -h;
  w.h2 = w.k2 = h;
  if (of_triangles) {
    const Vec3 a(-h, -h, 0.0), b(h, -h, 0.0), c(h, h, 0.0), d(-h, h, 0.0);
    w.triangles = {Triangle{a, b, c}, Triangle{a, c, d}};
  }
  return w;
}

WorldDef3 drop_onto(const WallDef3& wall, const ParticleDef3& p) {
  WorldDef3 def;
  def.materials = {rock()};
  def.contact_models = {hertz()};
  def.particles = {p};
  def.walls = {wall};
  def.gravity = {0.0, 0.0, -9.81};
  def.time_step_fraction = 0.1;
  def.threads = 1;
  return def;
}

void expect_same_history(WorldDef3 rectangle_def, WorldDef3 faces_def, int cycles, const char* what) {
  World3 rectangle(std::move(rectangle_def)), faces(std::move(faces_def));
  double peak = 0.0, gap = 0.0;
  for (int k = 0; k < cycles; ++k) {
    rectangle.cycle();
    faces.cycle();
    peak = std::max(peak, rectangle.wall_measures()[0].normal_force);
    gap = std::max(gap, std::abs(faces.wall_measures()[0].normal_force - rectangle.wall_measures()[0].normal_force));
  }
  const auto r = rectangle.particles(), f = faces.particles();
  std::printf("%s: peak plate force %.6e N, largest difference faces vs rectangle %.2e N, final position gap %.2e m\n",
              what, peak, gap, (r.position[ParticleId{0}] - f.position[ParticleId{0}]).norm());
  EXPECT_GT(peak, 0.0);
  EXPECT_LT(gap, 1e-9 * peak);
  EXPECT_LT((r.position[ParticleId{0}] - f.position[ParticleId{0}]).norm(), 1e-12);
  EXPECT_LT((r.angular_velocity[ParticleId{0}] - f.angular_velocity[ParticleId{0}]).norm(), 1e-9);
}

TEST(TriangleWalls, SphereBouncingOnTheDiagonalSeesOnePlate) {
  // Landing on the shared edge of the two faces, sliding across it.
  ParticleDef3 p;
  p.position = {0.1, 0.1, 0.25};
  p.radius = 0.2;
  p.velocity = {0.4, -0.3, -1.0};
  expect_same_history(drop_onto(plate(1.0, false), p), drop_onto(plate(1.0, true), p), 30000, "sphere on the diagonal");
}

TEST(TriangleWalls, EllipsoidBouncingOnFacesSeesOnePlate) {
  ParticleDef3 p;
  p.position = {0.3, -0.2, 0.4};
  p.shape.axes = {0.371, 0.260, 0.182};  // Miyata's section 3.3 particle
  p.shape.orientation = Quaternion(Eigen::AngleAxisd(0.7, Vec3(1.0, -0.5, 0.2).normalized()));
  p.velocity = {0.2, 0.1, -0.5};
  expect_same_history(drop_onto(plate(2.0, false), p), drop_onto(plate(2.0, true), p), 30000, "ellipsoid on faces");
}

TEST(TriangleWalls, EllipsoidCentredOnTheSeamSeesOnePlate) {
  // Its support point lies exactly on the edge the two faces share: the
  // edge belongs to both faces, so it neither falls through nor is pushed twice.
  ParticleDef3 p;
  p.position = {0.5, 0.5, 0.25};
  p.shape.axes = {0.371, 0.260, 0.182};
  p.velocity = {0.0, 0.0, -0.5};
  expect_same_history(drop_onto(plate(2.0, false), p), drop_onto(plate(2.0, true), p), 30000, "ellipsoid on the seam");
}

TEST(TriangleWalls, SphereAtACornerIsPushedAwayFromTheCorner) {
  // A sphere beside the plate's corner, below its top: only the corner touches.
  ParticleDef3 p;
  p.position = {1.05, 1.05, -0.02};
  p.radius = 0.1;
  WorldDef3 def = drop_onto(plate(1.0, true), p);
  def.gravity = Vec3::Zero();
  World3 world(def);
  world.cycle();
  const WallMeasure3 m = world.wall_measures()[0];
  const Vec3 away = (p.position - Vec3(1.0, 1.0, 0.0)).normalized();
  std::printf("corner contact: force on plate (%.4e %.4e %.4e) N\n", m.force.x(), m.force.y(), m.force.z());
  ASSERT_EQ(m.contacts, 1);
  // The plate feels the reaction, along the line from the sphere to the corner.
  EXPECT_NEAR(m.force.normalized().dot(-away), 1.0, 1e-12);
}

TEST(TriangleWalls, FacesMoveAndTurnWithTheWall) {
  WallDef3 w = plate(0.5, true);
  w.point = {0.0, 0.0, 1.0};
  for (auto& t : w.triangles) {
    for (Vec3& corner : t) corner.z() = 1.0;
  }
  w.motion.velocity = {0.0, 0.0, -0.1};
  w.motion.angular_velocity = {0.0, 0.0, 0.2};
  WorldDef3 def;
  def.materials = {rock()};
  def.contact_models = {hertz()};
  def.particles = {ParticleDef3{{5.0, 5.0, 5.0}, 0.1, MaterialId{0}}};  // far off, a world needs one
  def.walls = {w};
  def.fixed_time_step = 1e-3;
  World3 world(def);
  world.cycle(1000);
  const WallDef3& now = world.wall(WallId{0});
  // One second: down 0.1 m and turned 0.2 rad about z, corners still on a square.
  EXPECT_NEAR(now.point.z(), 0.9, 1e-12);
  const Vec3 corner = now.triangles[0][1];  // started at (0.5, -0.5)
  EXPECT_NEAR(corner.z(), 0.9, 1e-12);
  EXPECT_NEAR(std::atan2(corner.y(), corner.x()), -std::numbers::pi / 4 + 0.2, 1e-9);
  EXPECT_NEAR(corner.head<2>().norm(), 0.5 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(world.wall_area(WallId{0}), 1.0, 1e-12);
  // Placing the plate carries its faces along.
  world.place_wall(WallId{0}, {0.0, 0.0, 2.0});
  for (const auto& t : world.wall(WallId{0}).triangles) {
    for (const Vec3& c : t) EXPECT_NEAR(c.z(), 2.0, 1e-12);
  }
}

TEST(TriangleWalls, DegenerateFacesAreRejected) {
  WallDef3 w = plate(1.0, true);
  w.triangles.push_back(Triangle{Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 2, 0)});
  WorldDef3 def;
  def.materials = {rock()};
  def.contact_models = {hertz()};
  def.particles = {ParticleDef3{{0.0, 0.0, 0.5}, 0.1, MaterialId{0}}};
  def.walls = {w};
  try {
    World3 world(def);
    FAIL() << "a degenerate face was accepted";
  } catch (const DefinitionError& e) {
    EXPECT_NE(std::string(e.what()).find("triangle 2 is degenerate"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dem
