// Randall (1989) ch. 5 and Miyata et al. (2002) eq. 17: the contact laws
// against the theory of Hertz, Mindlin-Deresiewicz and Maw et al.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "box_settle.h"
#include "contact_mechanics.h"
#include "impact.h"
#include "mindlin_loading.h"

namespace dem::validation {
namespace {

double sphere_mass(const Sphere& s) { return s.density * 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius, 3); }
double contact_modulus(const Sphere& s) { return s.youngs_modulus / (2.0 * (1.0 - s.poisson_ratio * s.poisson_ratio)); }

TEST(HertzImpact, Randall5_12ContactDurationAndPeakForce) {
  const Sphere s = maw_sphere();
  for (double v : {0.1, 0.4, 1.0}) {
    const ImpactResult wall = sphere_wall_impact(s, hertz_mindlin_model(), v, 0.0, kImpactTimeStepFraction);
    const HertzTheory tw = hertz_theory(sphere_mass(s), s.radius, contact_modulus(s), v);
    const ImpactResult pair = sphere_sphere_impact(s, hertz_mindlin_model(), v, kImpactTimeStepFraction);
    const HertzTheory tp = hertz_theory(0.5 * sphere_mass(s), 0.5 * s.radius, contact_modulus(s), v);
    std::printf("V = %.1f: wall T_c %+.3f%% N_max %+.4f%% e %.6f; pair T_c %+.3f%% N_max %+.4f%% e %.6f\n", v,
                100 * (wall.contact_duration / tw.contact_duration - 1), 100 * (wall.peak_normal_force / tw.peak_normal_force - 1),
                wall.restitution, 100 * (pair.contact_duration / tp.contact_duration - 1),
                100 * (pair.peak_normal_force / tp.peak_normal_force - 1), pair.restitution);
    EXPECT_NEAR(wall.contact_duration / tw.contact_duration, 1.0, 0.01);
    EXPECT_NEAR(wall.peak_normal_force / tw.peak_normal_force, 1.0, 0.01);
    EXPECT_NEAR(pair.contact_duration / tp.contact_duration, 1.0, 0.01);
    EXPECT_NEAR(pair.peak_normal_force / tp.peak_normal_force, 1.0, 0.01);
    // Elastic, undamped: the spheres leave as fast as they came.
    EXPECT_NEAR(wall.restitution, 1.0, 1e-4);
    EXPECT_NEAR(pair.restitution, 1.0, 1e-4);
  }
}

TEST(Restitution, Miyata17GivesTheRequestedRestitution) {
  const Sphere s = maw_sphere();
  for (double e : {0.1, 0.5, 0.9}) {
    const ImpactResult wall = sphere_wall_impact(s, restitution_model(e), 0.4, 0.0, kRestitutionTimeStepFraction);
    const ImpactResult pair = sphere_sphere_impact(s, restitution_model(e), 0.4, kRestitutionTimeStepFraction);
    std::printf("e = %.1f: sphere-wall %.5f, sphere-sphere %.5f\n", e, wall.restitution, pair.restitution);
    EXPECT_NEAR(wall.restitution / e, 1.0, 0.01);
    EXPECT_NEAR(pair.restitution / e, 1.0, 0.01);
  }
}

TEST(MindlinLoading, Randall5_2ConstantNormalForceMatchesClosedForm) {
  const MindlinLoadingResult r = mindlin_constant_normal_force(2000);
  std::printf("N = %.3f N; loading, unloading, reloading: largest error %.4f%% of mu N over %zu points\n",
              r.normal_force, 100 * r.largest_error, r.points.size());
  EXPECT_NEAR(r.normal_force, 88.0, 1e-6);
  ASSERT_EQ(r.points.size(), 60u);
  for (const MindlinPoint& p : r.points) {
    // 2% of the theoretical force (or of 0.1 mu N near T = 0, where a relative error means nothing).
    EXPECT_NEAR(p.simulated, p.theory, 0.02 * std::max(std::abs(p.theory), 0.1 * r.friction_force))
        << p.branch << " at " << p.displacement;
  }
  // The loop closes inside the first: unloading passed through zero and reloading went back up.
  EXPECT_LT(r.points[39].simulated, 0.0);
  EXPECT_GT(r.points.back().simulated, r.points[19].simulated * 0.99);
}

TEST(MindlinLoading, VaryingNormalForceNeverExceedsMuNAndLagsWithThetaOne) {
  const VaryingNormalResult r = mindlin_varying_normal_force();
  std::printf("largest |T|/(mu N) %.9f, %d sliding steps, %d lagging steps (largest error %.2e)\n", r.largest_ratio,
              r.sliding_steps, r.lagging_checks, r.largest_lag_error);
  EXPECT_LE(r.largest_ratio, 1.0 + 1e-12);
  EXPECT_GT(r.sliding_steps, 0) << "the history must reach sliding";
  EXPECT_GT(r.lagging_checks, 100) << "the history must include dT < mu dN";
  EXPECT_LT(r.largest_lag_error, 1e-9);  // Randall 3.98: theta = 1
}

TEST(ObliqueImpact, Randall5_4ThreeRegimesOfMaw) {
  const Sphere s = maw_sphere();
  const double chi = maw_chi(s.poisson_ratio);
  const double boundary = 4.0 * chi - 1.0;
  double min_restitution = 2.0, psi1_at_min = 0.0, angle_at_min = 0.0;
  int below_one = 0, middle = 0, sliding = 0;
  for (double angle = 2.5; angle < 90.0; angle += 2.5) {
    const ImpactResult r = sphere_wall_impact(s, hertz_mindlin_model(), 0.4, angle, kImpactTimeStepFraction);
    const double psi1 = maw_psi(s.poisson_ratio, s.friction, std::tan(angle * std::numbers::pi / 180.0));
    const double psi2 = maw_psi(s.poisson_ratio, s.friction, r.tangential_velocity_after / r.normal_velocity_after);
    if (psi1 < 1.0) {
      EXPECT_GT(psi2, 0.0) << "psi1 " << psi1;
      ++below_one;
    } else if (psi1 < boundary) {
      EXPECT_LT(psi2, 0.0) << "psi1 " << psi1;
      EXPECT_FALSE(r.sliding_throughout) << "psi1 " << psi1;
      ++middle;
    } else {
      EXPECT_TRUE(r.sliding_throughout) << "psi1 " << psi1 << ": |T| = mu N at every step of contact";
      ++sliding;
    }
    if (r.restitution < min_restitution) {
      min_restitution = r.restitution;
      psi1_at_min = psi1;
      angle_at_min = angle;
    }
  }
  const ImpactResult normal = sphere_wall_impact(s, hertz_mindlin_model(), 0.4, 0.0, kImpactTimeStepFraction);
  std::printf("regimes: %d below psi1 = 1, %d between, %d sliding throughout; restitution at 0 deg %.6f, minimum %.5f "
              "at %.1f deg (psi1 = %.2f, 4 chi - 1 = %.2f; Randall's simulation: minimum at 50 deg)\n",
              below_one, middle, sliding, normal.restitution, min_restitution, angle_at_min, psi1_at_min, boundary);
  EXPECT_GE(below_one, 2);
  EXPECT_GE(middle, 5);
  EXPECT_GE(sliding, 10);
  EXPECT_NEAR(normal.restitution, 1.0, 1e-4);
  // The minimum lies where sliding lasts throughout, as in Randall Fig. 5.17
  // (50 deg; he relates it to psi1 of about 4 chi - 1).
  EXPECT_GE(psi1_at_min, boundary);
  EXPECT_LE(psi1_at_min, 2.0 * boundary);
  EXPECT_LT(min_restitution, 0.95);
}

TEST(BoxSettle, FloorCarriesTheWeightAndTheEnergyBudgetCloses) {
  const BoxSettleResult r = box_settle(DEM_CASES_DIR "/validation/box_settle.case.txtpb");
  const EnergyBudget& e = r.energy;
  std::printf("%d spheres at rest after %llu cycles: floor %.6e N of weight %.6e N (%+.4f%%); energy residual %+.4f%% "
              "of the potential energy drop %.4e J (dashpots %.3e, friction %.3e, local damping %.3e, strain %.2e)\n",
              r.particles, static_cast<unsigned long long>(r.cycles), r.floor_force, r.weight,
              100.0 * (r.floor_force / r.weight - 1.0), 100.0 * e.residual() / e.gravity_work, e.gravity_work,
              e.contact_damping, e.friction, e.local_damping, e.strain);
  EXPECT_EQ(r.particles, 2000);
  EXPECT_TRUE(r.at_rest);
  EXPECT_NEAR(r.floor_force / r.weight, 1.0, 0.005);
  EXPECT_LT(std::abs(e.residual()), 0.01 * e.gravity_work);
  EXPECT_LT(e.kinetic, 1e-6 * e.gravity_work);
}

}  // namespace
}  // namespace dem::validation
