// The part of a disc or sphere inside a box or a ball, against the areas
// and volumes of segments, quadrants, caps and lenses.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solid_volume.h"

namespace dem::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SolidVolume, DiscInABoxAgainstQuadrantsHalvesAndSegments) {
  const Box<2> box{{0.0, 0.0}, {10.0, 10.0}};
  EXPECT_NEAR(disc_in_box({5.0, 5.0}, 1.0, box), kPi, 1e-12);         // inside
  EXPECT_NEAR(disc_in_box({0.0, 0.0}, 1.0, box), kPi / 4.0, 1e-12);   // on a corner
  EXPECT_NEAR(disc_in_box({5.0, 10.0}, 1.0, box), kPi / 2.0, 1e-12);  // on a side
  EXPECT_NEAR(disc_in_box({20.0, 5.0}, 1.0, box), 0.0, 1e-15);        // outside
  // Centre 0.4 outside the side x = 0: the segment beyond a chord at
  // distance d = 0.4, r^2 acos(d/r) - d sqrt(r^2 - d^2).
  const double d = 0.4;
  EXPECT_NEAR(disc_in_box({-d, 5.0}, 1.0, box), std::acos(d) - d * std::sqrt(1.0 - d * d), 1e-12);
  // A disc larger than a thin box: the strip's width times the chords.
  const Box<2> strip{{-0.5, -5.0}, {0.5, 5.0}};
  const double strip_area =
      2.0 * (0.5 * std::sqrt(0.75) + std::asin(0.5));  // integral of 2 sqrt(1 - x^2) over [-0.5, 0.5]
  EXPECT_NEAR(disc_in_box({0.0, 0.0}, 1.0, strip), strip_area, 1e-12);
}

TEST(SolidVolume, DiscInADiscAgainstTheLens) {
  // Two unit circles a radius apart: the lens 2 (pi/3 - sqrt(3)/4).
  EXPECT_NEAR(disc_in_disc({0.0, 0.0}, 1.0, {1.0, 0.0}, 1.0), 2.0 * (kPi / 3.0 - std::sqrt(3.0) / 4.0), 1e-12);
  EXPECT_NEAR(disc_in_disc({0.0, 0.0}, 1.0, {0.5, 0.0}, 3.0), kPi, 1e-12);
  EXPECT_EQ(disc_in_disc({0.0, 0.0}, 1.0, {3.0, 0.0}, 1.0), 0.0);
}

TEST(SolidVolume, SphereInABoxAgainstOctantsHalvesAndCaps) {
  const double whole = 4.0 / 3.0 * kPi;
  const Box<3> box{{0.0, 0.0, 0.0}, {10.0, 10.0, 10.0}};
  EXPECT_NEAR(sphere_in_box({5.0, 5.0, 5.0}, 1.0, box), whole, 1e-9);
  EXPECT_NEAR(sphere_in_box({0.0, 0.0, 0.0}, 1.0, box), whole / 8.0, 1e-9);
  EXPECT_NEAR(sphere_in_box({0.0, 5.0, 0.0}, 1.0, box), whole / 4.0, 1e-9);
  EXPECT_NEAR(sphere_in_box({5.0, 5.0, 10.0}, 1.0, box), whole / 2.0, 1e-9);
  // A cap of height h = 0.6: pi h^2 (3 r - h) / 3.
  const double h = 0.6;
  EXPECT_NEAR(sphere_in_box({5.0, 1.0 - h, 5.0}, 1.0, Box<3>{{0.0, 0.0, 0.0}, {10.0, 10.0, 10.0}}),
              whole - kPi * h * h * (3.0 - h) / 3.0, 1e-8);
}

TEST(SolidVolume, SphereInASphereAgainstTheLens) {
  // Two unit spheres a radius apart: twice a cap of height 1/2, 5 pi / 12.
  EXPECT_NEAR(sphere_in_sphere({0.0, 0.0, 0.0}, 1.0, {1.0, 0.0, 0.0}, 1.0), 5.0 * kPi / 12.0, 1e-12);
  EXPECT_NEAR(sphere_in_sphere({0.0, 0.0, 0.0}, 1.0, {0.0, 0.5, 0.0}, 3.0), 4.0 / 3.0 * kPi, 1e-12);
}

}  // namespace
}  // namespace dem::analysis
