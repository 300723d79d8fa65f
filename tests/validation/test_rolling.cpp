// Rolling resistance (Iwashita & Oda 1998; Ai et al. 2011, model C): a
// disc and a sphere rolling to rest on a plane against the closed form
// (deceleration mu_r g / (1 + I / (m R^2))), and the angle of repose of a
// fixed-base heap growing with the rolling friction (the published trend).
// The checks are dem_validate's (tools/dem_validate/rolling.cpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "rolling.h"

namespace dem::validation {
namespace {

std::filesystem::path out_dir(const char* name) {
  const auto dir = std::filesystem::path(DEM_VALIDATION_TEST_OUTPUT) / name;
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(RollingResistance, ABallRollsToRestWhereTheClosedFormSays) {
  const Verdict verdict = report_rolling_to_rest(out_dir("rolling_to_rest"));
  verdict.print(stdout, "rolling-to-rest");
  EXPECT_TRUE(verdict.passed()) << verdict;
}

TEST(RollingResistance, TheAngleOfReposeGrowsWithRollingFriction) {
  const Verdict verdict = report_angle_of_repose(out_dir("angle_of_repose"), {0.0, 0.05, 0.1, 0.2, 0.4});
  verdict.print(stdout, "angle-of-repose");
  EXPECT_TRUE(verdict.passed()) << verdict;
}

}  // namespace
}  // namespace dem::validation
