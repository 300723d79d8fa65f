#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dem/io/case_conversion.h"
#include "dem/io/world_checks.h"
#include "io_test_support.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;

World built(const proto::Case& message) { return World(convert_case(message).world); }

TEST(WorldChecks, AStepWithinTheCriticalStepPasses) {
  const World world = built(test::valid_case());
  EXPECT_NO_THROW(check_built_world(world));
}

TEST(WorldChecks, AFixedStepAboveTheCriticalStepIsRefused) {
  proto::Case c = test::valid_case();
  const double critical = built(c).critical_time_step();
  c.mutable_time_step()->set_fixed(critical);  // at the limit: allowed
  EXPECT_NO_THROW(check_built_world(built(c)));
  c.mutable_time_step()->set_fixed(critical * 1.01);
  try {
    check_built_world(built(c), {.name = "case.txtpb"});
    FAIL() << "a step above the critical one passed";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb: time_step.fixed: "));
    EXPECT_THAT(error.what(), HasSubstr("exceeds the critical time step"));
  }
}

// A stage may set its own fixed step from its start on (stage.time_step).
TEST(WorldChecks, AStagesFixedStepAboveTheCriticalStepIsRefused) {
  proto::Case c = test::valid_case();
  ASSERT_GT(c.stage_size(), 0);
  const double critical = built(c).critical_time_step();
  c.mutable_stage(0)->mutable_time_step()->set_fixed(critical);
  CaseDefinition definition = convert_case(c);
  EXPECT_NO_THROW(check_built_world(World(definition.world), definition.stages));
  c.mutable_stage(0)->mutable_time_step()->set_fixed(critical * 1.5);
  definition = convert_case(c);
  try {
    check_built_world(World(definition.world), definition.stages, {.name = "case.txtpb"});
    FAIL() << "a stage's step above the critical one passed";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb: stage[0].time_step.fixed: "));
    EXPECT_THAT(error.what(), HasSubstr("exceeds the critical time step"));
  }
}

// A stage's damping moves the critical step (the dashpots shorten it): the
// fixed step kept from before it is checked against the new one.
TEST(WorldChecks, AStagesDampingThatLeavesTheFixedStepAboveTheCriticalStepIsRefused) {
  proto::Case c = test::valid_case();
  ASSERT_GT(c.stage_size(), 0);
  const double critical = built(c).critical_time_step();
  c.mutable_time_step()->set_fixed(0.9 * critical);
  c.mutable_stage(0)->mutable_damping()->set_contact_beta(1.0);
  CaseDefinition definition = convert_case(c);
  const World world(definition.world);
  ASSERT_LT(world.critical_time_step_with(*definition.stages[0].damping), 0.9 * critical);
  try {
    check_built_world(world, definition.stages, {.name = "case.txtpb"});
    FAIL() << "a stage's damping with a step above its critical one passed";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb: time_step.fixed: with stage[0].damping, "));
    EXPECT_THAT(error.what(), HasSubstr("exceeds the critical time step"));
  }
  // A step of the stage's own that fits passes.
  c.mutable_stage(0)->mutable_time_step()->set_fixed(0.5 *
                                                     world.critical_time_step_with(*definition.stages[0].damping));
  definition = convert_case(c);
  EXPECT_NO_THROW(check_built_world(World(definition.world), definition.stages));
}

// A fraction is of the undamped critical step; one whose step is above the
// critical step with the dashpots is refused, naming the largest that fits.
TEST(WorldChecks, AFractionAboveTheDampedCriticalStepIsRefused) {
  proto::Case c = test::valid_case();
  c.mutable_damping()->set_contact_beta(1.0);
  c.mutable_time_step()->set_fraction(1.0);
  const World world = built(c);
  ASSERT_LT(world.critical_time_step(), world.undamped_critical_time_step());
  try {
    check_built_world(world, {.name = "case.txtpb"});
    FAIL() << "a fraction above the damped critical step passed";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb: time_step.fraction: gives "));
    EXPECT_THAT(error.what(), HasSubstr("exceeds the critical time step"));
  }
  c.mutable_time_step()->set_fraction(0.99 * world.critical_time_step() / world.undamped_critical_time_step());
  EXPECT_NO_THROW(check_built_world(built(c)));
}

}  // namespace
}  // namespace dem::io
