// What a snapshot may not hold even when its arrays fit together: unknown
// enum values, duplicate names, thread counts and particle counts beyond
// the limits, numbers the force arithmetic cannot carry, values a case
// could not give (its rules, applied after decoding), a cycle counter that
// could wrap. Each is refused naming its field.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dem/io/snapshot_conversion.h"
#include "snapshot_worlds.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;
using testing::settling_box;
using testing::sphere_stack;

std::string problems_of(const proto::Snapshot& message, const ResourceLimits& limits = machine_limits()) {
  try {
    snapshot_from_proto<2>(message, nullptr, limits);
  } catch (const SnapshotError& error) {
    return error.what();
  }
  return "";
}

std::string problems_of_3d(const proto::Snapshot& message) {
  try {
    snapshot_from_proto<3>(message, nullptr, machine_limits());
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

// A payload edited and signed again passes the frame's checksum: the
// case's rules (case_validation.cpp, contact_model_checks.cpp) refuse what
// no case could hold, by the snapshot's field.
TEST(SnapshotChecks, ValuesNoCaseCouldHoldAreRefused) {
  for (const double stiffness : {0.0, -1e6}) {
    proto::Snapshot m = good_snapshot();
    m.mutable_settings()->mutable_contact_models(0)->set_linear_normal_stiffness(stiffness);
    EXPECT_THAT(problems_of(m), HasSubstr("settings.contact_models[0].linear_normal_stiffness: must be > 0"));
  }
  proto::Snapshot m = good_snapshot();
  m.mutable_settings()->mutable_contact_models(0)->set_linear_shear_stiffness(-5);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.contact_models[0].linear_shear_stiffness: must be >= 0 (got -5)"));
  m = good_snapshot();
  m.mutable_settings()->mutable_materials(0)->set_poisson_ratio(2);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.materials[0].poisson_ratio: must be in (-1, 0.5) (got 2)"));
  m = good_snapshot();
  m.mutable_settings()->mutable_materials(0)->set_density(0);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.materials[0].density: must be > 0 (got 0)"));
  m = good_snapshot();
  m.mutable_settings()->mutable_materials(0)->set_friction(-0.3);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.materials[0].friction: must be >= 0 (got -0.3)"));
  m = good_snapshot();
  m.mutable_settings()->mutable_damping()->set_local_alpha(1);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.damping.local_alpha: must be in [0, 1) (got 1)"));
  m = good_snapshot();
  m.mutable_settings()->set_time_step_fraction(1.5);
  EXPECT_THAT(problems_of(m), HasSubstr("settings.time_step_fraction: must be in (0, 1] (got 1.5)"));
}

TEST(SnapshotChecks, AHertzSnapshotNeedsTheParticlesElasticConstants) {
  World3 world(sphere_stack(ContactLaw::kHertzMindlin));
  world.cycle(20);
  const proto::Snapshot good = snapshot_to_proto(world.snapshot(), SnapshotInfo{});
  EXPECT_EQ(problems_of_3d(good), "");
  proto::Snapshot m = good;
  m.mutable_settings()->mutable_materials(m.particles().material(0))->set_youngs_modulus(0);
  EXPECT_THAT(problems_of_3d(m), HasSubstr(".youngs_modulus: must be > 0 (got 0)"));
  m = good;
  m.mutable_settings()->mutable_contact_models(0)->set_hertz_damping_ratio(-0.1);
  EXPECT_THAT(problems_of_3d(m), HasSubstr("settings.contact_models[0].hertz_damping_ratio: must be >= 0 (got -0.1)"));
}

TEST(SnapshotChecks, AZeroQuaternionIsRefused) {
  World3 world(sphere_stack(ContactLaw::kLinear));
  world.cycle(20);
  proto::Snapshot m = snapshot_to_proto(world.snapshot(), SnapshotInfo{});
  for (int k = 4; k < 8; ++k) m.mutable_particles()->set_rotation(k, 0.0);
  EXPECT_THAT(problems_of_3d(m),
              HasSubstr("particles.rotation[1]: must be a unit quaternion, an orientation (got one of length 0)"));
  m.mutable_particles()->set_rotation(4, 2.0);
  EXPECT_THAT(problems_of_3d(m), HasSubstr("particles.rotation[1]: must be a unit quaternion"));
}

// A counter near 2^64 wrapped to 19 after 20 cycles; a snapshot stands at
// most at 2^62, from where no run can reach the wrap.
TEST(SnapshotChecks, ACycleCounterThatCouldWrapIsRefused) {
  proto::Snapshot m = good_snapshot();
  m.set_cycle(~std::uint64_t{0});
  EXPECT_THAT(problems_of(m), HasSubstr("cycle: is 18446744073709551615, beyond 2^62 (4611686018427387904)"));
  m.set_cycle(std::uint64_t{1} << 62);
  EXPECT_EQ(problems_of(m), "");
  m = good_snapshot();
  m.set_sorted_cycle(m.cycle() + 1);
  EXPECT_THAT(problems_of(m), HasSubstr("sorted_cycle: is 51, after the snapshot's cycle 50"));
}

}  // namespace
}  // namespace dem::io
