// Cundall & Strack (1979) verification test (Fig. 11, Table 1): the
// photoelastic assembly compressed by four walls to F_H/F_V of about 0.4,
// with wall forces, eccentricities and the out-of-balance ratio reported.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/programme.h"

namespace dem {
namespace {

TEST(Verification, AssemblyReachesTable1State) {
  const io::LoadedCase loaded = io::load_case_file(DEM_CASES_DIR "/ball/verification_assembly.case.txtpb");
  const io::CaseDefinition def = io::convert_case(loaded.message, loaded.source);
  World world(def.world);
  ASSERT_EQ(world.particle_count(), 197);
  for (const StageDef& stage : def.stages) {
    const StageResult result = run_stage(world, stage);
    EXPECT_TRUE(result.condition_met) << "stage " << stage.name << " did not settle within " << stage.cycles
                                      << " cycles";
  }

  const auto walls = world.wall_measures();
  const double vertical = 0.5 * (walls[0].normal_force + walls[2].normal_force);
  const double horizontal = 0.5 * (walls[1].normal_force + walls[3].normal_force);
  const AssemblyMeasures a = world.assembly_measures();
  std::printf("after %llu cycles: F_H/F_V = %.4f (seed Fig. 11: 0.43 and 0.40)\n",
              static_cast<unsigned long long>(world.cycle_count()), horizontal / vertical);
  std::printf("wall   F_1          F_2          e/(L/2)   contacts\n");
  for (const WallMeasure& m : walls) {
    std::printf("%d      %+.4e  %+.4e  %6.2f%%   %d\n", m.wall + 1, m.force.x(), m.force.y(), 100.0 * m.eccentricity,
                m.contacts);
  }
  std::printf("Delta F / F = %.3f%% (seed Table 1: 0.9-4.2%%), %d contacts, %d sliding\n", 100.0 * a.out_of_balance,
              a.contacts, a.sliding_contacts);
  EXPECT_NEAR(horizontal / vertical, 0.4, 0.02);
  EXPECT_LT(a.out_of_balance, 0.01);
  for (const WallMeasure& m : walls) {
    EXPECT_GT(m.contacts, 2);
    EXPECT_LT(std::abs(m.eccentricity), 0.5);
  }
}

}  // namespace
}  // namespace dem
