// Particle generators: lattices and seeded random non-overlapping packings.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "dem/error.h"
#include "dem/packing.h"

namespace dem {
namespace {

TEST(Packing, HexagonalLatticeRowsAndShift) {
  LatticeDef def;
  def.radius = 1.0;
  def.columns = 3;
  def.rows = 2;
  def.spacing = 2.0;
  def.arrangement = LatticeArrangement::kHexagonal;
  const auto p = generate_lattice(def);
  ASSERT_EQ(p.size(), 6u);
  EXPECT_DOUBLE_EQ(p[3].position.x(), 1.0);
  EXPECT_DOUBLE_EQ(p[3].position.y(), std::sqrt(3.0));
  EXPECT_NEAR((p[3].position - p[0].position).norm(), 2.0, 1e-15);
}

RandomPackingDef polydisperse_box() {
  RandomPackingDef def;
  def.min = {0.0, 0.0};
  def.max = {840.0, 840.0};
  def.sizes = {{40, 6}, {35, 7}, {30, 16}, {25, 33}, {20, 33}, {18, 36}, {15, 28}, {10, 38}};
  def.seed = 1979;
  return def;
}

TEST(Packing, RandomPackingHasNoOverlapAndStaysInTheBox) {
  const auto p = generate_random_packing(polydisperse_box());
  ASSERT_EQ(p.size(), 197u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_GE(p[i].position.x() - p[i].radius, 0.0);
    EXPECT_LE(p[i].position.y() + p[i].radius, 840.0);
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      EXPECT_GE((p[i].position - p[j].position).norm(), p[i].radius + p[j].radius) << i << " " << j;
    }
  }
}

TEST(Packing, SeedDecidesThePacking) {
  const auto a = generate_random_packing(polydisperse_box());
  const auto b = generate_random_packing(polydisperse_box());
  RandomPackingDef other = polydisperse_box();
  other.seed = 7;
  const auto c = generate_random_packing(other);
  EXPECT_EQ(a[100].position, b[100].position);
  EXPECT_NE(a[100].position, c[100].position);
}

// A caller that gave up on a packing stops it: the same packing when never
// stopped, an error naming what was placed when stopped.
TEST(Packing, APackingAskedToStopEnds) {
  RandomPackingDef def = polydisperse_box();
  int asked = 0;
  def.stopped = [&] { return ++asked > 0; };
  def.sizes = {{1, 100000}};  // 100,000 unit discs in the box: more than 4,096 attempts
  EXPECT_THROW(
      {
        try {
          generate_random_packing(def);
        } catch (const DefinitionError& error) {
          EXPECT_NE(std::string(error.what()).find("random packing: stopped after placing"), std::string::npos);
          throw;
        }
      },
      DefinitionError);
  EXPECT_EQ(asked, 1);
  RandomPackingDef never = polydisperse_box();
  never.stopped = [] { return false; };
  EXPECT_EQ(generate_random_packing(never)[100].position, generate_random_packing(polydisperse_box())[100].position);
}

TEST(Packing, SuperquadricsArePlacedByTheirBoundingCircleAtRandomAngles) {
  RandomPackingDef def;
  def.max = {4.0, 3.0};
  SizeClass rock;
  rock.count = 30;
  rock.shape = ShapeDefT<2>{0.195, 0.0976, 4.0, 0.0};  // Miyata's Table 1 particle
  def.sizes = {rock};
  const auto p = generate_random_packing(def);
  ASSERT_EQ(p.size(), 30u);
  double first_angle = p[0].shape.angle;
  bool varied = false;
  // Its farthest boundary point, off the corner towards the long axis:
  // r^2 = a^2 cos + b^2 sin at tan = b^2 / a^2 (eq. 35 with n = 4).
  const double bounding = 0.19799;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(p[i].radius, bounding, 1e-5);
    EXPECT_EQ(p[i].shape.n, 4.0);
    varied = varied || p[i].shape.angle != first_angle;
    for (std::size_t j = i + 1; j < p.size(); ++j) EXPECT_GE((p[i].position - p[j].position).norm(), 2 * bounding);
  }
  EXPECT_TRUE(varied);
}

TEST(Packing, EllipsoidsTakeUniformRandomOrientations) {
  RandomPackingDef3 def;
  def.max = {10.0, 10.0, 10.0};
  SizeClass3 rock;
  rock.count = 400;
  rock.shape.axes = {0.371, 0.260, 0.182};  // Miyata's section 3.3 particle
  def.sizes = {rock};
  const auto p = generate_random_packing(def);
  ASSERT_EQ(p.size(), 400u);
  // Over uniform rotations the long axis points anywhere: |cos| to z
  // averages 1/2 and cos^2 averages 1/3 (standard errors 0.014 and 0.015).
  double mean_cos = 0.0, mean_cos2 = 0.0;
  for (const auto& q : p) {
    EXPECT_EQ(q.radius, 0.371);
    EXPECT_NEAR(q.shape.orientation.norm(), 1.0, 1e-12);
    const double c = (q.shape.orientation * Vec3::UnitX()).z();
    mean_cos += std::abs(c) / 400.0;
    mean_cos2 += c * c / 400.0;
  }
  std::printf("long axis against z over 400 ellipsoids: mean |cos| %.4f (1/2), mean cos^2 %.4f (1/3)\n", mean_cos,
              mean_cos2);
  EXPECT_NEAR(mean_cos, 0.5, 0.05);
  EXPECT_NEAR(mean_cos2, 1.0 / 3.0, 0.05);
}

TEST(Packing, ImpossiblePackingIsAnErrorNamingTheSize) {
  RandomPackingDef def;
  def.max = {10.0, 10.0};
  def.sizes = {{1.0, 500}};
  def.max_attempts = 1000;
  try {
    generate_random_packing(def);
    FAIL();
  } catch (const DefinitionError& e) {
    EXPECT_NE(std::string(e.what()).find("radius 1"), std::string::npos) << e.what();
  }
}

// Randall's (1989, 4.4) dense generation: a size that finds no more room
// ends, and the generator "would now move on to the next smaller particle
// size and attempt to generate all those". A box that cannot hold the
// counts fills densely instead of failing: fewer of the large sizes, the
// small ones in the gaps.
TEST(Packing, DenseGenerationMovesOnToTheNextSmallerSize) {
  RandomPackingDef def;
  def.max = {20.0, 20.0};
  def.sizes = {{1.0, 200}, {0.6, 400}, {0.35, 800}};
  def.max_attempts = 20000;
  def.seed = 1989;
  EXPECT_THROW(generate_random_packing(def), DefinitionError);
  def.next_size_when_full = true;
  const auto p = generate_random_packing(def);
  int count[3] = {0, 0, 0};
  double solid = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    count[p[i].radius == 1.0 ? 0 : p[i].radius == 0.6 ? 1 : 2] += 1;
    solid += std::numbers::pi * p[i].radius * p[i].radius;
    EXPECT_GE(p[i].position.minCoeff() - p[i].radius, 0.0);
    EXPECT_LE(p[i].position.maxCoeff() + p[i].radius, 20.0);
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      ASSERT_GE((p[i].position - p[j].position).norm(), p[i].radius + p[j].radius) << i << " " << j;
    }
  }
  std::printf(
      "dense generation in a 20 x 20 box: %d of 200 r = 1, %d of 400 r = 0.6, %d of 800 r = 0.35; "
      "solid fraction %.3f\n",
      count[0], count[1], count[2], solid / 400.0);
  EXPECT_LT(count[0], 200);  // the box could not hold them all
  EXPECT_GT(count[1], 0);    // and the smaller sizes filled the gaps
  EXPECT_GT(count[2], 0);
  // Random sequential addition of one size jams near 0.55 of the plane;
  // the smaller sizes in the gaps take it well past.
  EXPECT_GT(solid / 400.0, 0.6);
}

}  // namespace
}  // namespace dem
