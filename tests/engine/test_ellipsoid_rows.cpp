// The batched geometry of ellipsoid pair rows against EllipsoidShape::pair
// row by row.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "ellipsoid_rows.h"

namespace dem {
namespace {

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}
bool same_bits(const ContactGeometry<3>& a, const ContactGeometry<3>& b) {
  return same_bits(a.overlap, b.overlap) && same_bits(a.normal, b.normal) && same_bits(a.point, b.point) &&
         same_bits(a.arm_first, b.arm_first) && same_bits(a.arm_second, b.arm_second) &&
         same_bits(a.effective_radius, b.effective_radius);
}
bool same_bits(const ContactSearch& a, const ContactSearch& b) {
  return a.valid == b.valid && same_bits(a.first, b.first) && same_bits(a.second, b.second);
}

// Section 3.3's rocks in a periodic box, every pair within twice the
// bounding diameter a row (apart, spheres meeting but supports apart, and
// touching), moved and turned over settling-sized and larger steps: each
// row's geometry and search state, batched and row by row, with the same
// bits, with and without the geometry of rows apart.
template <bool kApartGeometry>
void compare_rows() {
  std::mt19937_64 random(53);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto jiggle = [&] { return Vec3(unit(random), unit(random), unit(random)); };
  const auto turn = [&](double angle) { return Quaternion(Eigen::AngleAxisd(angle, jiggle().normalized())); };
  const Vec3 axes(0.371, 0.260, 0.182);
  constexpr int kBodies = 60;
  constexpr double kSide = 2.5;
  Particles<3> p;
  std::vector<Quaternion> orientation;
  for (int k = 0; k < kBodies; ++k) {
    p.position.push_back(kSide * 0.5 * (jiggle() + Vec3::Ones()));
    p.radius.push_back(axes.x());
    orientation.push_back(turn(3.2));
  }
  Periodic<3> periodic;
  periodic.length = Vec3(kSide, kSide, kSide);
  std::vector<Slot> first;
  std::vector<std::int32_t> second;
  for (int a = 0; a < kBodies; ++a) {
    for (int b = a + 1; b < kBodies; ++b) {
      if (periodic.separation(p.position[a], p.position[b]).norm() < 4.0 * axes.x()) {
        first.push_back(a);
        second.push_back(b);
      }
    }
  }
  const int rows = static_cast<int>(first.size());
  Walls<3> walls;
  const ContactParamTable params;
  std::vector<ContactSearch> one_by_one(rows), batched(rows);
  std::vector<ContactGeometry<3>> expected(rows), got(rows);
  std::vector<EllipsoidFrame> frames(kBodies);
  int differing = 0, searched = 0, touching = 0;
  for (int step = 0; step < 200; ++step) {
    const double shift = step % 50 < 40 ? 1e-5 : 1e-3, angle = step % 50 < 40 ? 1e-4 : 1e-2;
    for (int k = 0; k < kBodies; ++k) {
      p.position[k] += shift * jiggle();
      orientation[k] = (turn(angle * unit(random)) * orientation[k]).normalized();
      frames[k] = ellipsoid_frame(axes, orientation[k]);
    }
    const PassInputs<3> in{p, walls, periodic, params, nullptr, nullptr, 1e-6, 0, 0.0, frames.data()};
    for (int r = 0; r < rows; ++r)
      expected[r] = EllipsoidShape::pair<kApartGeometry>(in, first[r], second[r], one_by_one[r]);
    ellipsoid_pair_geometry<kApartGeometry>(in, first.data(), second.data(), batched.data(), rows, got.data());
    for (int r = 0; r < rows; ++r) {
      differing += !same_bits(expected[r], got[r]) || !same_bits(one_by_one[r], batched[r]);
      searched += one_by_one[r].valid;
      touching += expected[r].overlap > 0.0;
    }
  }
  std::printf("%d rows over 200 steps, %d searched, %d touching: %d differ in any bit\n", rows * 200, searched,
              touching, differing);
  EXPECT_GT(searched, 1000);
  EXPECT_GT(touching, 500);
  EXPECT_LT(searched, rows * 200);
  EXPECT_EQ(differing, 0);
}

// The frames of a run of bodies, four at a time, from any first body and
// any count: ellipsoid_frame's bits body by body, the bodies outside the
// run untouched.
TEST(EllipsoidRows, FramesOfARunAreBodyByBodysBitForBit) {
  std::mt19937_64 random(61);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Particles<3> p;
  constexpr int kBodies = 23;
  for (int k = 0; k < kBodies; ++k) {
    ShapeDefT<3> shape;
    shape.axes = Vec3(0.3 + 0.1 * unit(random), 0.2 + 0.1 * unit(random), 0.15 + 0.1 * unit(random));
    p.shape.push_back(shape);
    p.rotation.push_back(
        Quaternion(Eigen::AngleAxisd(3.2 * unit(random), Vec3(unit(random), unit(random), unit(random)).normalized())));
  }
  const auto same = [](const SymmetricMatrix& a, const SymmetricMatrix& b) {
    return same_bits(a.xx, b.xx) && same_bits(a.xy, b.xy) && same_bits(a.xz, b.xz) && same_bits(a.yy, b.yy) &&
           same_bits(a.yz, b.yz) && same_bits(a.zz, b.zz);
  };
  int differing = 0, runs = 0;
  for (int begin = 0; begin < kBodies; begin += 3) {
    for (int end = begin; end <= kBodies; end += 5) {
      std::vector<EllipsoidFrame> frames(kBodies, EllipsoidFrame{{7, 7, 7, 7, 7, 7}, {7, 7, 7, 7, 7, 7}});
      ellipsoid_frames_of(p, frames.data(), begin, end);
      for (int k = 0; k < kBodies; ++k) {
        const EllipsoidFrame expected = k >= begin && k < end ? ellipsoid_frame(p.shape[k].axes, p.rotation[k])
                                                              : EllipsoidFrame{{7, 7, 7, 7, 7, 7}, {7, 7, 7, 7, 7, 7}};
        differing += !same(frames[k].potential, expected.potential) || !same(frames[k].reach, expected.reach);
      }
      ++runs;
    }
  }
  EXPECT_GT(runs, 20);
  EXPECT_EQ(differing, 0);
}

TEST(EllipsoidRows, BatchedGeometryIsRowByRowsBitForBit) { compare_rows<false>(); }
TEST(EllipsoidRows, BatchedGeometryOfRowsApartIsRowByRowsBitForBit) { compare_rows<true>(); }

}  // namespace
}  // namespace dem
