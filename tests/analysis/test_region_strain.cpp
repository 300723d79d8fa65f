// The average strain of a region (BALL's strain tensor of a measurement
// circle, Randall 1989 2.3 and Fig. 6.8) on deformations whose answer is
// known by hand: a homogeneous one is read exactly, a rigid motion reads
// no strain, the reference state picks the particles, and too few or
// collinear particles are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dem/analysis/region_strain.h"

namespace dem::analysis {
namespace {

// A 7 x 7 square of centres, 1 apart, around the origin (2D), or 5^3 (3D).
template <int Dim>
AssemblySampleT<Dim> grid() {
  AssemblySampleT<Dim> s;
  const int n = Dim == 2 ? 7 : 5, half = n / 2;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < (Dim == 2 ? 1 : n); ++k) {
        Vec<Dim> x;
        x[0] = i - half;
        x[1] = j - half;
        if constexpr (Dim == 3) x[2] = k - half;
        s.position.push_back(x);
        s.radius.push_back(0.5);
        s.rotation.push_back(0.0);
      }
    }
  }
  return s;
}

// Every centre moved by x -> x + u0 + G x.
template <int Dim>
AssemblySampleT<Dim> deformed(AssemblySampleT<Dim> s, const Tensor<Dim>& g, const Vec<Dim>& u0) {
  for (Vec<Dim>& x : s.position) x = x + u0 + g * x;
  return s;
}

Region circle(double radius) {
  Region r;
  r.name = "circle";
  r.shape = RegionShape::kBall;
  r.radius = radius;
  return r;
}

TEST(RegionStrain, HomogeneousDeformationIsReadExactly) {
  const AssemblySample reference = grid<2>();
  Tensor<2> g;
  g << -0.004, 0.001, 0.003, 0.002;  // shortened along x, stretched along y, sheared
  const RegionStrain s = measure_region_strain(reference, deformed(reference, g, Vec2(0.3, -0.1)), circle(2.5));
  EXPECT_EQ(s.particles, 21);  // the centres within 2.5 of the origin
  EXPECT_NEAR(s.displacement_gradient(0, 0), -0.004, 1e-12);
  EXPECT_NEAR(s.displacement_gradient(1, 0), 0.003, 1e-12);
  // Compression positive: eps = -(G + G^T) / 2.
  EXPECT_NEAR(s.strain(0, 0), 0.004, 1e-12);
  EXPECT_NEAR(s.strain(1, 1), -0.002, 1e-12);
  EXPECT_NEAR(s.strain(0, 1), -0.002, 1e-12);
  EXPECT_NEAR(s.volumetric, 0.002, 1e-12);  // contraction
  // Principal strains of [[4, -2], [-2, -2]] e-3: 1 +- sqrt(13) e-3.
  EXPECT_NEAR(s.principal.values[0], 1e-3 + std::sqrt(13.0) * 1e-3, 1e-12);
  EXPECT_NEAR(s.deviator, 2.0 * std::sqrt(13.0) * 1e-3, 1e-12);
  EXPECT_NEAR(s.rotation, 0.001, 1e-12);
  EXPECT_LT(s.fit_residual, 1e-12);
}

TEST(RegionStrain, RigidRotationAndTranslationReadNoStrain) {
  const AssemblySample reference = grid<2>();
  const double angle = 1e-3;
  AssemblySample turned = reference;
  for (Vec2& x : turned.position) {
    x = Vec2(std::cos(angle) * x.x() - std::sin(angle) * x.y() + 5.0,
             std::sin(angle) * x.x() + std::cos(angle) * x.y() - 2.0);
  }
  const RegionStrain s = measure_region_strain(reference, turned, circle(3.2));
  // A finite rotation leaves a second-order strain (1 - cos) ~ angle^2 / 2.
  EXPECT_LT(s.strain.cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_NEAR(s.rotation, angle, 1e-9);
}

TEST(RegionStrain, TheReferenceStatePicksTheParticlesAndIdsMatchThem) {
  AssemblySample reference = grid<2>();
  for (std::size_t k = 0; k < reference.particle_count(); ++k) reference.ids.push_back(ParticleId::from_index(k));
  Tensor<2> g = Tensor<2>::Zero();
  g(0, 0) = 0.01;
  AssemblySample current = deformed(reference, g, Vec2(0.0, 0.0));
  // Inside the circle the field is homogeneous; one particle outside it
  // moves far: it is not one of the region's.
  current.position.front() += Vec2(10.0, 10.0);
  // The current sample lists its particles in another order.
  std::swap(current.position[3], current.position[30]);
  std::swap(current.ids[3], current.ids[30]);
  const RegionStrain s = measure_region_strain(reference, current, circle(2.5));
  EXPECT_NEAR(s.strain(0, 0), -0.01, 1e-12);  // stretched: negative
  EXPECT_NEAR(s.volumetric, -0.01, 1e-12);    // dilation
  // A particle gone from the current state (a trim) is left out.
  current.position.erase(current.position.begin() + 24);  // the centre
  current.ids.erase(current.ids.begin() + 24);
  EXPECT_EQ(measure_region_strain(reference, current, circle(2.5)).particles, 20);
}

TEST(RegionStrain, ThreeDimensions) {
  const AssemblySample3 reference = grid<3>();
  Tensor<3> g = Tensor<3>::Zero();
  g(2, 2) = -0.005;
  g(0, 0) = 0.001;
  g(1, 1) = 0.001;
  Region3 r;
  r.name = "sphere";
  r.shape = RegionShape::kBall;
  r.radius = 1.8;
  const RegionStrain3 s = measure_region_strain(reference, deformed(reference, g, Vec3(0.1, 0.2, 0.3)), r);
  EXPECT_NEAR(s.principal.values[0], 0.005, 1e-12);
  EXPECT_NEAR(s.principal.values[2], -0.001, 1e-12);
  EXPECT_NEAR(s.volumetric, 0.003, 1e-12);
  EXPECT_NEAR(s.deviator, 0.006, 1e-12);
}

TEST(RegionStrain, TooFewOrCollinearParticlesAreRefused) {
  const AssemblySample reference = grid<2>();
  EXPECT_THROW(measure_region_strain(reference, reference, circle(0.5)), std::invalid_argument);  // one particle
  Region row;
  row.name = "row";
  row.shape = RegionShape::kBox;
  row.min = Vec2(-3.5, -0.5);
  row.max = Vec2(3.5, 0.5);
  EXPECT_THROW(measure_region_strain(reference, reference, row), std::invalid_argument);  // seven on a line
  AssemblySample periodic = reference;
  periodic.periodic.axes = {true, false};
  EXPECT_THROW(measure_region_strain(periodic, periodic, circle(2.5)), std::invalid_argument);
}

}  // namespace
}  // namespace dem::analysis
