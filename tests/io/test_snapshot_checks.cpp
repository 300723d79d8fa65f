// What a snapshot may not hold even when its arrays fit together: unknown
// enum values, duplicate names, thread counts and particle counts beyond
// the limits, numbers the force arithmetic cannot carry. Each is refused
// naming its field.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dem/io/snapshot_conversion.h"
#include "snapshot_worlds.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;
using testing::settling_box;

std::string problems_of(const proto::Snapshot& message, const ResourceLimits& limits = machine_limits()) {
  try {
    snapshot_from_proto<2>(message, nullptr, limits);
  } catch (const SnapshotError& error) {
    return error.what();
  }
  return "";
}

proto::Snapshot good_snapshot() {
  World world(settling_box());
  world.cycle(50);
  return snapshot_to_proto(world.snapshot(), SnapshotInfo{});
}

TEST(SnapshotChecks, AGoodSnapshotPasses) { EXPECT_EQ(problems_of(good_snapshot()), ""); }

TEST(SnapshotChecks, UnknownEnumValuesAreRefused) {
  proto::Snapshot m = good_snapshot();
  ASSERT_GT(m.settings().contact_models_size(), 0);
  m.mutable_settings()->mutable_contact_models(0)->set_law(static_cast<proto::SnapshotContactLaw>(7));
  EXPECT_THAT(problems_of(m), HasSubstr("settings.contact_models[0].law: is 7, not a known SnapshotContactLaw"));
}

TEST(SnapshotChecks, DuplicateNamesAreRefused) {
  proto::Snapshot m = good_snapshot();
  ASSERT_GE(m.walls_size(), 2);
  m.mutable_walls(1)->set_name(m.walls(0).name());
  EXPECT_THAT(problems_of(m),
              HasSubstr("walls[1].name: duplicate wall name \"" + m.walls(0).name() + "\" (walls[0] has it too)"));
  m = good_snapshot();
  m.mutable_settings()->add_materials()->set_name(m.settings().materials(0).name());
  EXPECT_THAT(problems_of(m), HasSubstr("duplicate material name"));
}

TEST(SnapshotChecks, NegativeOrExcessiveCountsAreRefused) {
  proto::Snapshot m = good_snapshot();
  m.mutable_settings()->set_threads(-4);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.threads: must be >= 0 (0 = every core), got -4"));
  m.mutable_settings()->set_threads(100000);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.threads: asks for 100000 threads"));
  m = good_snapshot();
  m.mutable_walls(0)->set_contacts(-1);
  EXPECT_THAT(problems_of(m), HasSubstr("walls[0].contacts: must be >= 0 (got -1)"));
  m = good_snapshot();
  EXPECT_THAT(problems_of(m, limits_with_budget(10, 0)),
              HasSubstr("particles: holds 100 particles, more than the particle budget of 10"));
}

TEST(SnapshotChecks, NumbersTheForceArithmeticCannotCarryAreRefused) {
  proto::Snapshot m = good_snapshot();
  m.mutable_settings()->mutable_materials(0)->set_density(4.9e-324);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.materials[0].density: is 5e-324, below 1e-30"));
  m = good_snapshot();
  m.mutable_settings()->mutable_contact_models(0)->set_linear_normal_stiffness(1e308);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.contact_models[0].linear_normal_stiffness: is 1e+308, beyond 1e+30"));
  m = good_snapshot();
  m.mutable_particles()->set_position(6, -2e31);
  EXPECT_THAT(problems_of(m), HasSubstr("particles.position[6]: is -2e+31, beyond 1e+30"));
  m = good_snapshot();
  m.mutable_settings()->mutable_damping()->set_global_alpha(std::numeric_limits<double>::infinity());
  EXPECT_THAT(problems_of(m), HasSubstr("settings.damping.global_alpha: is not a finite number (inf)"));
}

}  // namespace
}  // namespace dem::io
