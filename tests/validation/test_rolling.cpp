// Rolling resistance (Iwashita & Oda 1998; Ai et al. 2011, model C): a
// disc and a sphere rolling to rest on a plane against the closed form
// (deceleration mu_r g / (1 + I / (m R^2))), and the angle of repose of a
// fixed-base heap growing with the rolling friction (the published trend),
// judged on the median of five packings: one collapse's angle moves by
// several degrees from packing to packing.
// The checks are dem_validate's (tools/dem_validate/rolling.cpp).
#include <gtest/gtest.h>

#include "rolling.h"
#include "validation_test_support.h"

namespace dem::validation {
namespace {

TEST(RollingResistance, ABallRollsToRestWhereTheClosedFormSays) {
  expect_passed(report_rolling_to_rest(out_dir("rolling_to_rest")), "rolling-to-rest");
}

TEST(RollingResistance, TheAngleOfReposeGrowsWithRollingFriction) {
  expect_passed(report_angle_of_repose(out_dir("angle_of_repose"), {0.0, 0.05, 0.1, 0.2, 0.4}, {11, 12, 13, 14, 15}),
                "angle-of-repose");
}

}  // namespace
}  // namespace dem::validation
