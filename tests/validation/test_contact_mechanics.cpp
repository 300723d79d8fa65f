// Randall (1989) ch. 5 and Miyata et al. (2002) eq. 17: the contact laws
// against the theory of Hertz, Mindlin-Deresiewicz and Maw et al. Each test
// runs dem_validate's check (tools/dem_validate/contact_mechanics.cpp) and
// asserts its verdict, so the bounds are written once, beside the runs; the
// figures and every check are printed.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "contact_mechanics.h"
#include "validation_test_support.h"

namespace dem::validation {
namespace {

TEST(HertzImpact, Randall5_12ContactDurationAndPeakForce) {
  expect_passed(report_hertz_impact(out_dir("hertz_impact")), "hertz-impact");
}

TEST(Restitution, Miyata17GivesTheRequestedRestitution) {
  expect_passed(report_restitution(out_dir("restitution")), "restitution");
}

TEST(MindlinLoading, Randall5_2ClosedFormAndVaryingNormalForce) {
  expect_passed(report_mindlin_loading(out_dir("mindlin_loading")), "mindlin-loading");
}

TEST(ObliqueImpact, Randall5_4ThreeRegimesOfMaw) {
  expect_passed(report_oblique_impact(out_dir("oblique_impact")), "oblique-impact");
}

TEST(BoxSettle, FloorCarriesTheWeightAndTheEnergyBudgetCloses) {
  expect_passed(report_box_settle(DEM_CASES_DIR "/validation/box_settle.case.txtpb", out_dir("box_settle")),
                "box-settle");
}

// A verdict fails when a bound does not hold, and says which.
TEST(Verdict, NamesTheChecksThatFail) {
  Verdict verdict;
  verdict.near("close", 1.004, 1.0, 0.01);
  verdict.below("too big", 2.0, 1.0);
  EXPECT_FALSE(verdict.passed());
  EXPECT_EQ(verdict.failures(), 1);
  std::ostringstream text;
  text << verdict;
  EXPECT_EQ(text.str(), "failed: too big: 2, expected below 1\n");
}

}  // namespace
}  // namespace dem::validation
