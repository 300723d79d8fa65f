// Delta F / F in a region (Cundall & Strack 1979, Table 1 note 2; Randall
// 1989, 6.4.2-6.5.2: quasi-equilibrium judged inside his measurement
// circles), and the stage condition that waits for it.
#include <gtest/gtest.h>

#include "dem/packing.h"
#include "dem/programme.h"
#include "dem/region.h"
#include "dem/world.h"
#include "snapshot_worlds.h"

namespace dem {
namespace {

using testing::settling_box;

Region ball(const char* name, Vec2 centre, double radius) {
  Region r;
  r.name = name;
  r.shape = RegionShape::kBall;
  r.centre = centre;
  r.radius = radius;
  return r;
}

// Two discs under gravity: A rests on the floor with its spring at m_A g,
// B falls far above it, touching nothing. The whole assembly's largest
// resultant is B's m_B g and its largest contact force A's m_A g, so Delta
// F / F = (r_B / r_A)^2; a circle around A alone finds it in equilibrium,
// one around B alone finds no contact (0).
TEST(OutOfBalance, ARegionsRatioIsTheRatioOfItsParticles) {
  WorldDef def = settling_box();
  def.walls[2].motion = {};
  def.walls[3].motion = {};
  def.damping = {};
  const double ra = 0.01, rb = 0.005, mass_a = 2650.0 * 3.141592653589793 * ra * ra;
  def.particles = {ParticleDef{{0.05, ra - mass_a * 9.81 / 1e6}, ra, MaterialId{0}, {0.0, 0.0}, 0.0},
                   ParticleDef{{0.2, 0.25}, rb, MaterialId{0}, {0.0, 0.0}, 0.0}};
  World world(def);
  world.cycle(10);
  ASSERT_EQ(world.contacts().size(), 1u);
  Region whole;
  whole.name = "all";
  const double all = world.out_of_balance(whole);
  const double around_a = world.out_of_balance(ball("a", {0.05, 0.01}, 0.02));
  const double around_b = world.out_of_balance(ball("b", {0.2, 0.25}, 0.02));
  std::printf("Delta F / F: whole %.12f ((r_B / r_A)^2 = 0.25), around A %.3e, around B %.3e\n", all, around_a,
              around_b);
  EXPECT_EQ(all, world.assembly_measures().out_of_balance);
  EXPECT_NEAR(all, 0.25, 1e-9);
  EXPECT_LT(around_a, 1e-9);
  EXPECT_EQ(around_b, 0.0);
}

// A stage that waits for quasi-equilibrium inside a circle ends when the
// ratio there is below the threshold, and not before.
TEST(OutOfBalance, AStageWaitsForItInARegion) {
  World world(settling_box());
  const Region circle = ball("circle", {0.15, 0.06}, 0.05);
  StageDef settle;
  settle.cycles = 200000;
  settle.until.region_out_of_balance_below = RegionThreshold{circle, 0.05};
  settle.until.min_cycles = 500;
  settle.until.check_interval = 50;
  double last_checked = 1.0;
  const StageResult result = run_stage(world, settle, 50, [&](const World& w) {
    last_checked = w.out_of_balance(circle);
    return true;
  });
  std::printf("settled inside the circle after %llu cycles: Delta F / F %.4f there, %.4f overall\n",
              static_cast<unsigned long long>(result.cycles_run), world.out_of_balance(circle),
              world.assembly_measures().out_of_balance);
  ASSERT_TRUE(result.condition_met);
  EXPECT_LT(world.out_of_balance(circle), 0.05);
  EXPECT_GT(result.cycles_run, 500u);
  EXPECT_LT(result.cycles_run, 200000u);
}

}  // namespace
}  // namespace dem
