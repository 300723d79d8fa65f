// Cundall & Strack (1979) verification test (Figs. 10-13, Tables 1-3): the
// photoelastic assembly brought by four servo walls to F_H/F_V = 0.4
// (stage A) and then to stage B (F_V up 4.348 %, F_H down as much), with
// Table 1's springs and friction, Table 2's k_s = k_n and Table 3's tan phi
// of 0.40 and 0.08. The checks are dem_validate's
// (tools/dem_validate/verification.cpp); everything is printed.
#include <gtest/gtest.h>

#include "verification.h"

namespace dem::validation {
namespace {

void run_table(const char* file) {
  const VerificationRun run = run_verification(std::filesystem::path(DEM_CASES_DIR "/ball") / file);
  print_verification(stdout, run);
  const Verdict verdict = judge_verification(run);
  verdict.print(stdout, run.name);
  EXPECT_TRUE(verdict.passed()) << verdict;
}

TEST(Verification, Table1StagesAAndB) { run_table("verification_assembly.case.txtpb"); }
TEST(Verification, Table2ShearStiffnessEqualToNormal) { run_table("verification_assembly_table2.case.txtpb"); }
TEST(Verification, Table3LowerFriction) { run_table("verification_assembly_table3.case.txtpb"); }

}  // namespace
}  // namespace dem::validation
