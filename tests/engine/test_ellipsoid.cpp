// Ellipsoid contact geometry (Miyata et al. 2002, section 2.4) on
// configurations with known answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "ellipsoid.h"

namespace dem {
namespace {

const Vec3 kAxes{0.371, 0.260, 0.182};  // Miyata's section 3.3 particle

TEST(Ellipsoid, SpheresOverlapAsSpheresWithHertzRadius) {
  const PlacedEllipsoid i{Vec3::Constant(0.15), Vec3::Zero(), Quaternion::Identity()};
  const PlacedEllipsoid j{Vec3::Constant(0.10), Vec3(0.2, 0.1, -0.05),
                          Quaternion(Eigen::AngleAxisd(1.0, Vec3::UnitY()))};
  const EllipsoidContact c = ellipsoid_contact(i, j);
  const double d = j.centre.norm();
  EXPECT_NEAR(c.overlap, 0.25 - d, 1e-12);
  EXPECT_NEAR((c.normal - j.centre / d).norm(), 0.0, 1e-12);
  EXPECT_NEAR(c.effective_radius, 0.15 * 0.10 / 0.25, 1e-12);  // R* of Hertz
}

TEST(Ellipsoid, AlignedPairsTouchAlongEachAxis) {
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 offset = Vec3::Zero();
    offset[axis] = 2.0 * kAxes[axis] - 0.003;
    const PlacedEllipsoid i{kAxes, Vec3::Zero(), Quaternion::Identity()}, j{kAxes, offset, Quaternion::Identity()};
    const EllipsoidContact c = ellipsoid_contact(i, j);
    EXPECT_NEAR(c.overlap, 0.003, 1e-9) << "axis " << axis;
    EXPECT_NEAR(std::abs(c.normal[axis]), 1.0, 1e-9);
    // Two equal tips: the relative curvatures are twice each surface's
    // principal curvatures there, a_axis / a_other^2.
    double k[2];
    for (int other = 0, o = 0; other < 3; ++other) {
      if (other != axis) k[o++] = 2.0 * kAxes[axis] / (kAxes[other] * kAxes[other]);
    }
    EXPECT_NEAR(c.effective_radius, 1.0 / std::sqrt(k[0] * k[1]), 1e-6 * c.effective_radius) << "axis " << axis;
  }
}

TEST(Ellipsoid, PlaneDistanceAndSupportPoint) {
  // Turned 40 degrees about y, centred 0.3 above the plane z = 0: the
  // lowest point is at depth sqrt(n^T M^-1 n) below the centre.
  const Quaternion q(Eigen::AngleAxisd(40.0 * std::numbers::pi / 180.0, Vec3::UnitY()));
  const PlacedEllipsoid e{kAxes, Vec3(0.0, 0.0, 0.3), q};
  const Eigen::Matrix3d r = q.toRotationMatrix();
  const Vec3 axis_z = r.transpose() * Vec3::UnitZ();  // the plane normal in body axes
  const double reach = std::sqrt((kAxes.cwiseAbs2().array() * axis_z.cwiseAbs2().array()).sum());
  const EllipsoidFaceContact c = ellipsoid_plane_contact(e, Vec3::Zero(), Vec3::UnitZ());
  EXPECT_NEAR(c.overlap, reach - 0.3, 1e-12);
  EXPECT_NEAR(c.projected.z(), 0.0, 1e-12);
  const Vec3 local = r.transpose() * (c.support - e.centre);
  EXPECT_NEAR((local.array() / kAxes.array()).matrix().squaredNorm(), 1.0, 1e-12);  // on the surface
  // Resting on its flattest side: R_e is sqrt(R' R'') at the end of a3.
  const PlacedEllipsoid flat{kAxes, Vec3(0.0, 0.0, 0.18), Quaternion::Identity()};
  const EllipsoidFaceContact f = ellipsoid_plane_contact(flat, Vec3::Zero(), Vec3::UnitZ());
  EXPECT_NEAR(f.overlap, 0.002, 1e-12);
  const double r1 = kAxes.x() * kAxes.x() / kAxes.z(), r2 = kAxes.y() * kAxes.y() / kAxes.z();
  EXPECT_NEAR(f.effective_radius, std::sqrt(r1 * r2), 1e-9);
}

TEST(Ellipsoid, TurnedPairMatchesAFineSearch) {
  const PlacedEllipsoid i{kAxes, Vec3::Zero(), Quaternion(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))};
  const PlacedEllipsoid j{kAxes, Vec3(0.55, 0.25, 0.1),
                          Quaternion(Eigen::AngleAxisd(-1.2, Vec3(0, 1, 1).normalized()))};
  const EllipsoidContact c = ellipsoid_contact(i, j);
  // The minimum of j's potential over i's surface, by brute force on a fine grid.
  const Eigen::Matrix3d ri = i.orientation.toRotationMatrix(), rj = j.orientation.toRotationMatrix();
  double best = 1e300;
  for (double t = 0.0; t < std::numbers::pi; t += 0.002) {
    for (double p = 0.0; p < 2.0 * std::numbers::pi; p += 0.002) {
      const Vec3 local(kAxes.x() * std::sin(t) * std::cos(p), kAxes.y() * std::sin(t) * std::sin(p),
                       kAxes.z() * std::cos(t));
      const Vec3 in_j = rj.transpose() * (i.centre + ri * local - j.centre);
      best = std::min(best, (in_j.array() / kAxes.array()).matrix().squaredNorm() - 1.0);
    }
  }
  const Vec3 in_i = ri.transpose() * (c.first_point - i.centre);
  EXPECT_NEAR((in_i.array() / kAxes.array()).matrix().squaredNorm(), 1.0, 1e-12);  // P_i lies on i
  const Vec3 in_j = rj.transpose() * (c.first_point - j.centre);
  const double found = (in_j.array() / kAxes.array()).matrix().squaredNorm() - 1.0;
  std::printf("overlap %.6f, min f_j over i's surface: Newton %.8f, grid %.8f\n", c.overlap, found, best);
  EXPECT_LE(found, best + 1e-9);
  EXPECT_NEAR(found, best, 1e-4);
  // Warm start gives the same answer.
  const EllipsoidContact warm = ellipsoid_contact(i, j, c.multiplier_i, c.multiplier_j);
  EXPECT_NEAR(warm.overlap, c.overlap, 1e-12);
}

// The force pass starts each search where the last cycle's ended. Along a
// pair moved a step at a time (settling steps of 1e-5 m and 1e-4 rad), the
// warm-started searches give the points a search from scratch gives, to
// 1e-12 m: stopping early on a warm start costs no accuracy.
TEST(Ellipsoid, WarmStartedSearchesFollowAMovingPairExactly) {
  std::mt19937_64 random(43);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto jiggle = [&] { return Vec3(unit(random), unit(random), unit(random)); };
  const auto turn = [&](double angle) { return Quaternion(Eigen::AngleAxisd(angle, jiggle().normalized())); };
  double worst = 0.0;
  int touching = 0;
  for (int pair = 0; pair < 50; ++pair) {
    PlacedEllipsoid i{kAxes, Vec3(1, 2, 3), turn(3.0)};
    PlacedEllipsoid j{kAxes, i.centre + 0.45 * jiggle().normalized(), turn(3.0)};
    EllipsoidContact warm = ellipsoid_contact(i, j);
    for (int step = 0; step < 200; ++step) {
      j.centre += 1e-5 * jiggle();
      j.orientation = (turn(1e-4 * unit(random)) * j.orientation).normalized();
      warm = ellipsoid_contact(i, j, warm.multiplier_i, warm.multiplier_j);
      const EllipsoidContact cold = ellipsoid_contact(i, j);
      worst = std::max({worst, (warm.first_point - cold.first_point).norm(),
                        (warm.second_point - cold.second_point).norm(), std::abs(warm.overlap - cold.overlap)});
      touching += cold.overlap > 0.0;
    }
  }
  std::printf("largest difference warm - cold over 10,000 steps (%d touching): %.3g m\n", touching, worst);
  EXPECT_GT(touching, 1000);
  EXPECT_LT(worst, 1e-12);
}

// ellipsoid_contacts takes several contacts at once across vector lanes
// with the same operations as ellipsoid_contact: every field comes out
// with the same bits, whichever way each search goes - warm and ending
// after one evaluation (settling and loading steps), warm but needing
// more (steps of 1e-3 m and 1e-2 rad), from scratch, a centre inside the
// other body - and whatever its neighbours in the lanes do.
TEST(Ellipsoid, BatchedSearchesGiveTheSameBitsAsOneByOne) {
  std::mt19937_64 random(47);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto jiggle = [&] { return Vec3(unit(random), unit(random), unit(random)); };
  const auto turn = [&](double angle) { return Quaternion(Eigen::AngleAxisd(angle, jiggle().normalized())); };
  constexpr int kPairs = 7;  // not a multiple of the lanes' contacts
  struct Pair {
    PlacedEllipsoid i, j;
    double mu_i = 0.0, mu_j = 0.0;
  };
  std::vector<Pair> pairs(kPairs);
  for (int k = 0; k < kPairs; ++k) {
    const double distance = k == 3 ? 0.05 : 0.45;  // pair 3: each centre inside the other body
    pairs[k].i = {kAxes, Vec3(1, 2, 3), turn(3.0)};
    pairs[k].j = {kAxes, pairs[k].i.centre + distance * jiggle().normalized(), turn(3.0)};
  }
  const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
  const auto same = [&](const Vec3& a, const Vec3& b) {
    return bits(a.x()) == bits(b.x()) && bits(a.y()) == bits(b.y()) && bits(a.z()) == bits(b.z());
  };
  int differing = 0, compared = 0, touching = 0;
  for (int step = 0; step < 3000; ++step) {
    std::vector<EllipsoidFrame> frames_i(kPairs), frames_j(kPairs);
    std::vector<EllipsoidQuery> queries(kPairs);
    for (int k = 0; k < kPairs; ++k) {
      Pair& p = pairs[k];
      // Each pair its own mix of steps, changing as the steps go on.
      const int kind = (step / 100 + k) % 4;
      const double shift = kind == 0 ? 1e-5 : kind == 1 ? 1.4e-7 : 1e-3, angle = kind == 2 ? 1e-2 : 1e-4;
      if (k != 3) p.j.centre += shift * jiggle();
      p.j.orientation = (turn(angle * unit(random)) * p.j.orientation).normalized();
      if (kind == 3 && step % 3 == 0) p.mu_i = p.mu_j = 0.0;  // from scratch
      frames_i[k] = ellipsoid_frame(p.i.axes, p.i.orientation);
      frames_j[k] = ellipsoid_frame(p.j.axes, p.j.orientation);
      queries[k] = {&frames_i[k], &frames_j[k], p.i.centre, p.j.centre, p.mu_i, p.mu_j};
    }
    std::vector<EllipsoidContact> batched(kPairs);
    ellipsoid_contacts(queries.data(), batched.data(), kPairs);
    for (int k = 0; k < kPairs; ++k) {
      Pair& p = pairs[k];
      const EllipsoidContact one = ellipsoid_contact(frames_i[k], p.i.centre, frames_j[k], p.j.centre, p.mu_i, p.mu_j);
      const EllipsoidContact& b = batched[k];
      const bool equal = bits(b.overlap) == bits(one.overlap) && same(b.normal, one.normal) &&
                         same(b.point, one.point) && bits(b.effective_radius) == bits(one.effective_radius) &&
                         same(b.first_point, one.first_point) && same(b.second_point, one.second_point) &&
                         bits(b.multiplier_i) == bits(one.multiplier_i) &&
                         bits(b.multiplier_j) == bits(one.multiplier_j);
      differing += !equal;
      ++compared;
      touching += one.overlap > 0.0;
      p.mu_i = one.multiplier_i;
      p.mu_j = one.multiplier_j;
    }
  }
  std::printf("%d of %d batched contacts differ from one by one in any bit (%d touching)\n", differing, compared,
              touching);
  EXPECT_GT(touching, 5000);
  EXPECT_EQ(differing, 0);
}

// ellipsoid_frames: four bodies' frames at once, the same bits as one by
// one (bodies of three sizes, the axes in any order, any orientation).
TEST(Ellipsoid, BatchedFramesGiveTheSameBitsAsOneByOne) {
  std::mt19937_64 random(59);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
  const auto same = [&](const SymmetricMatrix& a, const SymmetricMatrix& b) {
    return bits(a.xx) == bits(b.xx) && bits(a.xy) == bits(b.xy) && bits(a.xz) == bits(b.xz) &&
           bits(a.yy) == bits(b.yy) && bits(a.yz) == bits(b.yz) && bits(a.zz) == bits(b.zz);
  };
  int differing = 0;
  for (int trial = 0; trial < 2500; ++trial) {
    std::array<Vec3, 4> axes;
    std::array<Quaternion, 4> orientation;
    for (int k = 0; k < 4; ++k) {
      const double size = std::pow(10.0, 2.0 * unit(random));  // 0.01 to 100 m
      axes[k] = size * Vec3(1.0 + unit(random), 1.0 + unit(random), 1.0 + unit(random)) + Vec3::Constant(1e-3 * size);
      orientation[k] = Quaternion(
          Eigen::AngleAxisd(3.2 * unit(random), Vec3(unit(random), unit(random), unit(random)).normalized()));
    }
    EllipsoidFrame batched[4];
    ellipsoid_frames(axes, orientation, batched);
    for (int k = 0; k < 4; ++k) {
      const EllipsoidFrame one = ellipsoid_frame(axes[k], orientation[k]);
      differing += !same(batched[k].potential, one.potential) || !same(batched[k].reach, one.reach);
    }
  }
  EXPECT_EQ(differing, 0);
}

// Body j pressed on body i (fixed) to an overlap `target` along `direction`,
// i and j turned as given: j's centre.
Vec3 pressed(const Vec3& axes, const Quaternion& qi, const Quaternion& qj, const Vec3& direction, double target) {
  const EllipsoidFrame fi = ellipsoid_frame(axes, qi), fj = ellipsoid_frame(axes, qj);
  double near = 0.0, far = 2.0 * axes.maxCoeff() + 0.1;
  for (int step = 0; step < 200; ++step) {
    const double middle = 0.5 * (near + far);
    (ellipsoid_contact(fi, Vec3::Zero(), fj, middle * direction).overlap > target ? near : far) = middle;
  }
  return near * direction;
}

// The work of a Hertz force along the contact normal, acting on j at its
// surface point P_j (as the force pass applies it), while j's centre and
// orientation go round a closed loop: a shift of `shift` along e1 and a
// turn of `turn` about e2 out of phase. Returned over the contact's
// elastic energy (2/5) k delta^2.5 at the start.
double loop_work(const Vec3& axes, const Quaternion& qi, const Quaternion& q0, const Vec3& c0, const Vec3& e1,
                 const Vec3& e2, double shift, double turn) {
  constexpr double k = 1e10;  // N/m^1.5: the law's constant does not matter, only its shape (Miyata eq. 47)
  const EllipsoidFrame fi = ellipsoid_frame(axes, qi);
  constexpr int kSteps = 4000;
  double work = 0.0, elastic = 0.0;
  Vec3 last_force, last_torque, last_centre;
  Quaternion last_turn;
  for (int s = 0; s <= kSteps; ++s) {
    const double t = 2.0 * std::numbers::pi * s / kSteps;
    const Vec3 centre = c0 + shift * std::cos(t) * e1;
    const Quaternion q = Quaternion(Eigen::AngleAxisd(turn * std::sin(t), e2)) * q0;
    const EllipsoidContact c = ellipsoid_contact(fi, Vec3::Zero(), ellipsoid_frame(axes, q), centre);
    EXPECT_GT(c.overlap, 0.0);
    const Vec3 force = k * std::pow(c.overlap, 1.5) * c.normal;  // on j, away from i
    const Vec3 torque = (c.second_point - centre).cross(force);
    if (s == 0) {
      elastic = 0.4 * k * std::pow(c.overlap, 2.5);
    } else {
      const Eigen::AngleAxisd step(q * last_turn.inverse());
      work += 0.5 * (force + last_force).dot(centre - last_centre) +
              0.5 * (torque + last_torque).dot(step.angle() * step.axis());
    }
    last_force = force, last_torque = torque, last_centre = centre, last_turn = q;
  }
  return work / elastic;
}

// The contact force of the potential method (Miyata 2.4, eqs. 43-48) is
// the overlap's gradient only approximately: carried round a closed loop
// of one body's position and orientation it does a little work. Measured
// on Miyata's rocks at 0.5 mm of overlap (a 700 kPa plate's contacts),
// loops of 0.2 mm by 2 mrad: at most 1.1e-3 of the contact's elastic
// energy; equal semi-axes (spheres) none. Too little to buckle a force
// chain against friction (docs/VALIDATION.md, "Miyata 3D").
TEST(Ellipsoid, ContactForceIsNearlyConservative) {
  for (const bool spheres : {false, true}) {
    const Vec3 axes = spheres ? Vec3::Constant(0.2596) : kAxes;
    double largest = 0.0;
    for (int pose = 0; pose < 6; ++pose) {
      const Quaternion qi(Eigen::AngleAxisd(0.3 * pose, Vec3(1, 2, 3).normalized()));
      const Quaternion q0(Eigen::AngleAxisd(0.7 * pose + 0.2, Vec3(-2, 1, 1).normalized()));
      const Vec3 direction = Vec3(std::cos(1.1 * pose), std::sin(1.1 * pose), 0.5 - 0.2 * pose).normalized();
      const Vec3 c0 = pressed(axes, qi, q0, direction, 5e-4);
      const Vec3 e1 = direction.cross(Vec3::UnitZ()).normalized(), e2 = direction.cross(e1);
      largest = std::max(largest, std::abs(loop_work(axes, qi, q0, c0, e1, e2, 2e-4, 2e-3)));
    }
    std::printf("%s: largest loop work %.2e of the elastic energy\n", spheres ? "spheres" : "Miyata's rocks", largest);
    EXPECT_LT(largest, spheres ? 1e-12 : 2e-3);
  }
}

TEST(Ellipsoid, MassAndInertiaOfASphere) {
  const EllipsoidMass m = ellipsoid_mass(Vec3::Constant(0.1));
  EXPECT_NEAR(m.volume, 4.0 / 3.0 * std::numbers::pi * 1e-3, 1e-15);
  EXPECT_NEAR(m.principal_moments.x(), 0.4 * m.volume * 0.01, 1e-15);  // 2/5 m r^2 per unit density
}

}  // namespace
}  // namespace dem
