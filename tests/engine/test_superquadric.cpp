// 2D superquadric contact geometry (Miyata et al. 2002, section 2.3) on
// configurations with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "superquadric.h"

namespace dem {
namespace {

TEST(Superquadric, BoundaryPointsLieOnTheSurface) {
  const Superquadric s{0.195, 0.0976, 4.0};  // Miyata's Table 1 particle
  for (double alpha = 0.0; alpha < 6.3; alpha += 0.1) {
    EXPECT_NEAR(superquadric_function(s, superquadric_point(s, alpha)), 0.0, 1e-12);  // eqs. 34-35
  }
}

TEST(Superquadric, BoundingRadiusReachesTheCorners) {
  // An ellipse reaches no farther than its larger semi-axis. With n = 4,
  // r^2 = a^2 cos(alpha) + b^2 sin(alpha) along the boundary (eq. 35),
  // largest at tan(alpha) = b^2 / a^2: Miyata's Table 1 rectangle reaches
  // 0.19799 m, past a = 0.195 m; a square reaches a (1 + 1)^(1/4) = a 2^(1/4)
  // at its corner.
  EXPECT_EQ(superquadric_bounding_radius({0.3, 0.2, 2.0}), 0.3);
  const double a2 = 0.195 * 0.195, b2 = 0.0976 * 0.0976;
  const double rectangle = std::sqrt(std::hypot(a2, b2));  // max of a2 cos + b2 sin
  EXPECT_NEAR(superquadric_bounding_radius({0.195, 0.0976, 4.0}), rectangle, 1e-6);
  EXPECT_GE(superquadric_bounding_radius({0.195, 0.0976, 4.0}), rectangle);
  const double corner = std::pow(2.0, 0.25);
  EXPECT_NEAR(superquadric_bounding_radius({1.0, 1.0, 4.0}), corner, 2e-6);
  EXPECT_GE(superquadric_bounding_radius({1.0, 1.0, 4.0}), corner);
  EXPECT_GT(superquadric_bounding_radius({1.0, 1.0, 10.0}), 1.3);  // nearly a square
}

TEST(Superquadric, CircleHasItsRadiusAsCurvatureAndAreaPiR2) {
  const Superquadric circle{0.15, 0.15, 2.0};
  const Curvature k = superquadric_curvature(circle, superquadric_point(circle, 0.7));
  EXPECT_NEAR(k.radius, 0.15, 1e-12);
  const SuperquadricMass m = superquadric_mass(circle);
  EXPECT_NEAR(m.area, std::numbers::pi * 0.0225, 1e-12);
  EXPECT_NEAR(m.polar_moment, 0.5 * std::numbers::pi * std::pow(0.15, 4), 1e-14);  // pi R^4 / 2
}

TEST(Superquadric, EllipseCurvatureAtTheEndsOfItsAxes) {
  // For n = 2 the radius of curvature is b^2/a at (a, 0) and a^2/b at (0, b).
  const Superquadric ellipse{0.3, 0.1, 2.0};
  EXPECT_NEAR(superquadric_curvature(ellipse, {0.3, 0.0}).radius, 0.01 / 0.3, 1e-12);
  EXPECT_NEAR(superquadric_curvature(ellipse, {0.0, 0.1}).radius, 0.09 / 0.1, 1e-12);
  EXPECT_NEAR(superquadric_mass(ellipse).area, std::numbers::pi * 0.03, 1e-12);
}

TEST(Superquadric, DiscsOverlapByTheSumOfRadiiLessTheDistance) {
  const PlacedSuperquadric i{{0.15, 0.15, 2.0}, {0.0, 0.0}, 0.3};
  const PlacedSuperquadric j{{0.10, 0.10, 2.0}, {0.2, 0.1}, -1.1};
  const SuperquadricContact c = superquadric_contact(i, j, 0.0, 0.0, false);
  const double d = std::hypot(0.2, 0.1);
  EXPECT_NEAR(c.overlap, 0.25 - d, 1e-9);
  EXPECT_NEAR(c.normal.x(), 0.2 / d, 1e-6);
  EXPECT_NEAR(c.normal.y(), 0.1 / d, 1e-6);
}

TEST(Superquadric, FlatSidesFaceToFaceAlongTheAxes) {
  // Two n = 4 particles side by side along x, axes aligned: the flat tips
  // overlap by 2a - D; side by side along y, by 2b - D.
  const Superquadric s{0.195, 0.0976, 4.0};
  for (double gap : {-0.002, -0.0005}) {
    const PlacedSuperquadric i{s, {0.0, 0.0}, 0.0}, j{s, {2 * s.a + gap, 0.0}, 0.0};
    const SuperquadricContact c = superquadric_contact(i, j, 0.0, 0.0, false);
    EXPECT_NEAR(c.overlap, -gap, 1e-7) << "along x, gap " << gap;
    EXPECT_NEAR(c.normal.x(), 1.0, 1e-6);
    const PlacedSuperquadric k{s, {0.0, 2 * s.b + gap}, 0.0};
    const SuperquadricContact cy = superquadric_contact(i, k, 0.0, 0.0, false);
    EXPECT_NEAR(cy.overlap, -gap, 1e-7) << "along y, gap " << gap;
    EXPECT_NEAR(cy.normal.y(), 1.0, 1e-6);
  }
  // Apart: a negative overlap.
  const PlacedSuperquadric far{s, {2 * s.a + 0.01, 0.0}, 0.0};
  EXPECT_LT(superquadric_contact({s, {0, 0}, 0}, far, 0, 0, false).overlap, 0.0);
}

TEST(Superquadric, TurnedParticlesMeetOnTheirLongSides) {
  // Turned by 90 degrees, the long axis stands along y: two such particles
  // side by side along x touch with their b sides.
  const Superquadric s{0.195, 0.0976, 4.0};
  const double half = 0.5 * std::numbers::pi;
  const PlacedSuperquadric i{s, {0.0, 0.0}, half}, j{s, {2 * s.b - 0.001, 0.0}, half};
  EXPECT_NEAR(superquadric_contact(i, j, 0, 0, false).overlap, 0.001, 1e-7);
}

TEST(Superquadric, LineContactUsesTheSupportPoint) {
  const Superquadric s{0.195, 0.0976, 4.0};
  // A floor y = 0 below a particle at height b - 0.001: overlap 0.001 at the bottom.
  const SupportContact flat = superquadric_line_contact({s, {0.0, s.b - 0.001}, 0.0}, {0.0, 0.0}, {0.0, -1.0});
  EXPECT_NEAR(flat.overlap, 0.001, 1e-12);
  // Turned 45 degrees, the lowest point is where the normal points down.
  const PlacedSuperquadric turned{s, {0.0, 0.0}, 0.25 * std::numbers::pi};
  double lowest = 0.0;
  for (double alpha = 0.0; alpha < 2 * std::numbers::pi; alpha += 1e-4) {
    const Vec2 p = superquadric_point(s, alpha);
    const double c = std::cos(turned.angle), sn = std::sin(turned.angle);
    lowest = std::min(lowest, sn * p.x() + c * p.y());
  }
  const SupportContact tilted = superquadric_line_contact(turned, {0.0, lowest + 0.001}, {0.0, -1.0});
  EXPECT_NEAR(tilted.overlap, 0.001, 1e-6);
}

TEST(Superquadric, WarmStartFindsTheSameContact) {
  const Superquadric s{0.195, 0.0976, 4.0};
  const PlacedSuperquadric i{s, {0.0, 0.0}, 0.2}, j{s, {0.3, 0.12}, -0.4};
  const SuperquadricContact cold = superquadric_contact(i, j, 0.0, 0.0, false);
  const PlacedSuperquadric j2{s, {0.3005, 0.1201}, -0.401};  // a cycle later
  const SuperquadricContact warm = superquadric_contact(i, j2, cold.alpha_i, cold.alpha_j, true);
  const SuperquadricContact fresh = superquadric_contact(i, j2, 0.0, 0.0, false);
  EXPECT_NEAR(warm.overlap, fresh.overlap, 1e-9);
}

// The force acts at the overlap's centroid (superquadric.h): two flat sides
// pressed delta together and tilted by theta move it by theta L^2 / (12
// delta) towards the deeper end, L the length they overlap along - the
// moment of a linear spring spread over the side, linear in the tilt. (At
// P_i and P_j it moved as the cube root of the tilt: 2 cm at 1e-3 rad.)
TEST(Superquadric, FlatSidesTiltedMoveTheForceLinearlyWithTheTilt) {
  const Superquadric s{0.195, 0.0976, 4.0};
  const double delta = 0.02;
  const auto shift = [&](double tilt) {
    const PlacedSuperquadric i{s, {0.0, 0.0}, 0.0}, j{s, {0.0, 2.0 * s.b - delta}, tilt};
    return superquadric_contact(i, j, 0.0, 0.0, false).point.x();
  };
  // Where the sides overlap: 2 b (1 - (x/a)^4)^(1/4) > 2 b - delta.
  const double length = 2.0 * s.a * std::pow(1.0 - std::pow(1.0 - 0.5 * delta / s.b, 4.0), 0.25);
  for (const double tilt : {1e-4, 1e-3, 2e-3}) {
    const double expected = -tilt * length * length / (12.0 * delta);  // j's left end dips: the force moves left
    std::printf("tilt %.0e rad: the force moves %.3e m (theta L^2 / (12 delta) = %.3e m)\n", tilt, shift(tilt),
                expected);
    EXPECT_NEAR(shift(tilt), expected, 0.15 * std::abs(expected));
    EXPECT_NEAR(shift(-tilt), -shift(tilt), 1e-9);
  }
  EXPECT_NEAR(shift(0.0), 0.0, 1e-12);
  // Offset sideways, the overlap's middle.
  const PlacedSuperquadric i{s, {0.0, 0.0}, 0.0}, j{s, {0.01, 2.0 * s.b - delta}, 0.0};
  EXPECT_NEAR(superquadric_contact(i, j, 0.0, 0.0, false).point.x(), 0.005, 1e-6);
}

TEST(Superquadric, AFlatSideOnALineCarriesItsForceAtTheOverlapsCentroid) {
  const Superquadric s{0.195, 0.0976, 4.0};
  const double delta = 0.002;
  const auto centroid = [&](double tilt) {
    return superquadric_line_contact({s, {0.0, s.b - delta}, tilt}, {0.0, 0.0}, {0.0, -1.0}).centroid;
  };
  EXPECT_NEAR(centroid(0.0).x(), 0.0, 1e-12);
  EXPECT_LT(centroid(0.0).y(), 0.0);  // below the line, inside the body's part past it
  EXPECT_GT(centroid(0.0).y(), -delta);
  // Tilted counter-clockwise the right end rises: the force moves left,
  // linearly in the tilt.
  const double small = centroid(1e-4).x(), large = centroid(1e-3).x();
  EXPECT_LT(small, 0.0);
  EXPECT_NEAR(large / small, 10.0, 1.0);
}

TEST(Superquadric, ACurvedContactsCentroidIsHalfwayThroughTheOverlap) {
  // Discs: the lens is symmetric about the line of centres.
  const PlacedSuperquadric i{{0.15, 0.15, 2.0}, {0.0, 0.0}, 0.3};
  const PlacedSuperquadric j{{0.10, 0.10, 2.0}, {0.2, 0.1}, -1.1};
  const SuperquadricContact c = superquadric_contact(i, j, 0.0, 0.0, false);
  const double d = std::hypot(0.2, 0.1);
  const Vec2 along = Vec2(0.2, 0.1) / d;
  EXPECT_NEAR((c.point - (0.15 - 0.5 * c.overlap) * along).dot(Vec2(-along.y(), along.x())), 0.0, 1e-9);
  EXPECT_NEAR(c.point.dot(along), 0.15 - 0.5 * c.overlap, 0.1 * c.overlap);
}

}  // namespace
}  // namespace dem
