// Cundall & Strack (1979) verification test (Figs. 10-13, Tables 1-3): the
// photoelastic assembly loaded as the seed's numerical test was, by moving
// its walls - translated inward to stage A, then moved on to stage B - with
// Table 1's springs and friction, Table 2's k_s = k_n and Table 3's tan phi
// of 0.40 and 0.08, on three packings. The checks are dem_validate's
// (tools/dem_validate/verification.cpp); everything is printed.
#include <gtest/gtest.h>

#include "verification.h"

namespace dem::validation {
namespace {

// Table 3's ratios above Table 1's on every packing and by the seed's
// margin, each table near its Table, the eccentricities of the seed's size.
TEST(Verification, Tables1To3ByWallDisplacement) {
  const auto packings = run_verification_tables(DEM_CASES_DIR "/ball", {1979, 1, 2});
  Verdict verdict;
  for (const VerificationTables& p : packings) {
    for (const VerificationRun& run : p.tables) {
      print_verification(stdout, run);
      verdict.add(judge_verification(run));
    }
  }
  print_verification_tables(stdout, packings);
  verdict.add(judge_verification_tables(packings));
  verdict.print(stdout, "verification");
  EXPECT_TRUE(verdict.passed()) << verdict;
}

}  // namespace
}  // namespace dem::validation
