#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "dem/io/case_conversion.h"
#include "dem/world.h"
#include "io_test_support.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;

class CaseConversion : public ::testing::Test {
 protected:
  proto::Case case_ = test::valid_case();
};

TEST_F(CaseConversion, NameAndDescription) {
  const CaseDefinition def = convert_case(case_);
  EXPECT_EQ(def.name, "nine_discs");
  EXPECT_EQ(def.description, "Nine discs in a box, then a compression");
}

TEST_F(CaseConversion, MaterialsMapByNameInOrder) {
  const WorldDef world = convert_case(case_).world;
  ASSERT_EQ(world.materials.size(), 3u);
  EXPECT_EQ(world.materials[0].name, "disc");
  EXPECT_EQ(world.materials[0].density, 2650);
  EXPECT_EQ(world.materials[0].friction, 0.5);
  EXPECT_EQ(world.materials[1].name, "steel");
  // Walls ignore density; a wall material may leave it out.
  EXPECT_EQ(world.materials[1].density, MaterialDef{}.density);
  EXPECT_EQ(world.materials[2].name, "glass");
}

TEST_F(CaseConversion, ContactModelsNameTheirMaterials) {
  const WorldDef world = convert_case(case_).world;
  ASSERT_EQ(world.contact_models.size(), 3u);
  const ContactModelDef& same = world.contact_models[0];
  EXPECT_EQ(same.material_a, 0);
  EXPECT_EQ(same.material_b, 0);
  EXPECT_EQ(same.linear.normal_stiffness, 1e6);
  EXPECT_EQ(same.linear.shear_stiffness, 5e5);
  EXPECT_FALSE(same.friction);
  EXPECT_FALSE(same.cohesion);
  const ContactModelDef& mixed = world.contact_models[1];
  EXPECT_EQ(mixed.material_a, 0);
  EXPECT_EQ(mixed.material_b, 1);
  EXPECT_EQ(mixed.friction, 0.25);
  const ContactModelDef& fallback = world.contact_models[2];
  EXPECT_EQ(fallback.material_a, kInvalidId);
  EXPECT_EQ(fallback.material_b, kInvalidId);
}

TEST_F(CaseConversion, ParticleSourcesExpandInOrder) {
  const std::vector<ParticleDef> particles = convert_case(case_).world.particles;
  ASSERT_EQ(particles.size(), 14u);
  // The lattice: 3 x 3 at the default spacing, 2 * radius.
  EXPECT_EQ(particles[0].position, Vec2(0.01, 0.01));
  EXPECT_NEAR(particles[1].position.x(), 0.03, 1e-15);
  EXPECT_NEAR(particles[3].position.y(), 0.03, 1e-15);
  EXPECT_EQ(particles[8].material, 0);
  // The single particle.
  EXPECT_EQ(particles[9].position, Vec2(0.09, 0.01));
  EXPECT_EQ(particles[9].material, 2);
  EXPECT_EQ(particles[9].velocity, Vec2(-0.1, 0));
  // The random packing, inside its box.
  for (std::size_t i = 10; i < 14; ++i) {
    EXPECT_EQ(particles[i].radius, 0.005);
    EXPECT_GE(particles[i].position.y(), 0.075);
    EXPECT_LE(particles[i].position.y(), 0.095);
  }
}

TEST_F(CaseConversion, LatticeSpacingAndArrangementPassThrough) {
  auto& lattice = *case_.mutable_particles(0)->mutable_lattice();
  lattice.set_spacing(0.025);
  lattice.set_arrangement(proto::LATTICE_HEXAGONAL);
  const std::vector<ParticleDef> particles = convert_case(case_).world.particles;
  EXPECT_NEAR(particles[1].position.x() - particles[0].position.x(), 0.025, 1e-15);
  // Every other row is shifted by half the spacing, rows sqrt(3)/2 spacing apart.
  EXPECT_NEAR(particles[3].position.x() - particles[0].position.x(), 0.0125, 1e-15);
  EXPECT_NEAR(particles[3].position.y() - particles[0].position.y(), 0.025 * std::sqrt(3.0) / 2, 1e-15);
}

TEST_F(CaseConversion, RandomPackingIsSeeded) {
  const auto first = convert_case(case_).world.particles;
  EXPECT_EQ(convert_case(case_).world.particles[12].position, first[12].position);
  case_.mutable_particles(2)->mutable_random_packing()->set_seed(8);
  EXPECT_NE(convert_case(case_).world.particles[12].position, first[12].position);
}

TEST_F(CaseConversion, GeneratorFailureNamesTheSource) {
  auto& packing = *case_.mutable_particles(2)->mutable_random_packing();
  packing.mutable_size(0)->set_count(500);
  packing.set_max_attempts(50);
  try {
    convert_case(case_, {"case.txtpb", nullptr});
    FAIL() << "500 discs fitted in the box";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb: particles[2].random_packing: "));
    EXPECT_THAT(error.what(), HasSubstr("after 50 attempts"));
  }
}

TEST_F(CaseConversion, WallsGetUnitDirections) {
  const std::vector<WallDef> walls = convert_case(case_).world.walls;
  ASSERT_EQ(walls.size(), 4u);
  EXPECT_EQ(walls[0].name, "bottom");
  EXPECT_EQ(walls[0].direction, Vec2(1, 0));
  EXPECT_NEAR(walls[1].direction.x(), 0, 1e-15);  // angle_deg: 90
  EXPECT_NEAR(walls[1].direction.y(), 1, 1e-15);
  EXPECT_EQ(walls[2].direction, Vec2(-1, 0));      // direction { x: -2 }
  EXPECT_NEAR(walls[3].direction.y(), -1, 1e-15);  // angle_deg: 270
  EXPECT_EQ(walls[2].point, Vec2(0.1, 0.2));
  EXPECT_EQ(walls[1].h2, 0.2);
  EXPECT_EQ(walls[1].material, 1);
  EXPECT_FALSE(walls[1].motion.servo);
}

TEST_F(CaseConversion, WallMotionAndServo) {
  auto& motion = *case_.mutable_wall(1)->mutable_motion();
  motion.mutable_velocity()->set_x(-0.5);
  motion.set_angular_velocity(0.25);
  auto& servo = *case_.mutable_wall(0)->mutable_motion()->mutable_servo();
  servo.set_target_force(100);
  servo.set_gain(1e-3);
  servo.set_max_speed(0.5);
  const std::vector<WallDef> walls = convert_case(case_).world.walls;
  EXPECT_EQ(walls[1].motion.velocity, Vec2(-0.5, 0));
  EXPECT_EQ(walls[1].motion.angular_velocity, 0.25);
  ASSERT_TRUE(walls[0].motion.servo);
  EXPECT_EQ(walls[0].motion.servo->target_force, 100);
  EXPECT_EQ(walls[0].motion.servo->gain, 1e-3);
  EXPECT_EQ(walls[0].motion.servo->max_speed, 0.5);
}

TEST_F(CaseConversion, DampingGravityTimeStepAndNumerics) {
  case_.mutable_numerics()->set_contact_tolerance(0.001);
  case_.mutable_time_step()->set_fixed(1e-5);
  const WorldDef world = convert_case(case_).world;
  EXPECT_EQ(world.damping.contact_beta, 1e-5);
  EXPECT_EQ(world.damping.global_alpha, 2);
  EXPECT_EQ(world.gravity, Vec2(0, -9.81));
  EXPECT_EQ(world.time_step_fraction, 0.2);
  EXPECT_EQ(world.fixed_time_step, 1e-5);
  EXPECT_EQ(world.contact_tolerance, 0.001);
  EXPECT_EQ(world.threads, 1);
}

TEST_F(CaseConversion, UnsetNumbersKeepTheirDefaults) {
  case_.clear_time_step();
  case_.clear_numerics();
  case_.mutable_output()->clear_interval();
  case_.mutable_particles(2)->mutable_random_packing()->clear_max_attempts();
  const CaseDefinition def = convert_case(case_);
  EXPECT_EQ(def.world.time_step_fraction, 0.1);
  EXPECT_EQ(def.world.fixed_time_step, 0);
  EXPECT_EQ(def.world.contact_tolerance, 0);
  EXPECT_EQ(def.world.threads, 0);
  EXPECT_EQ(def.output.interval, 100u);
}

TEST_F(CaseConversion, Stages) {
  const std::vector<StageDef> stages = convert_case(case_).stages;
  ASSERT_EQ(stages.size(), 3u);

  EXPECT_EQ(stages[0].name, "settle");
  EXPECT_EQ(stages[0].cycles, 400u);
  EXPECT_TRUE(stages[0].wall_motions.empty());
  EXPECT_FALSE(stages[0].damping);
  EXPECT_EQ(stages[0].until.kinetic_energy_below, 1e-12);
  EXPECT_FALSE(stages[0].until.out_of_balance_below);
  EXPECT_FALSE(stages[0].until.servo_tolerance);
  EXPECT_EQ(stages[0].until.min_cycles, 50u);
  EXPECT_EQ(stages[0].until.check_interval, 10u);  // the default

  ASSERT_EQ(stages[1].wall_motions.size(), 1u);
  EXPECT_EQ(stages[1].wall_motions[0].first, 2);  // "top"
  ASSERT_TRUE(stages[1].wall_motions[0].second.servo);
  EXPECT_EQ(stages[1].wall_motions[0].second.servo->target_force, 10);
  ASSERT_TRUE(stages[1].damping);
  EXPECT_EQ(stages[1].damping->global_alpha, 0.5);
  EXPECT_EQ(stages[1].damping->contact_beta, 0);
  EXPECT_EQ(stages[1].until.servo_tolerance, 0.05);
  EXPECT_EQ(stages[1].until.check_interval, 20u);

  EXPECT_EQ(stages[2].wall_motions[0].second.velocity, Vec2(0, 0.01));
  EXPECT_FALSE(stages[2].wall_motions[0].second.servo);
  EXPECT_FALSE(stages[2].until.kinetic_energy_below);
  EXPECT_EQ(stages[2].until.check_interval, StopConditions{}.check_interval);
}

TEST_F(CaseConversion, Output) {
  OutputSettings output = convert_case(case_).output;
  EXPECT_EQ(output.interval, 50u);
  EXPECT_TRUE(output.contacts_file);
  ASSERT_EQ(output.probes.size(), 2u);
  EXPECT_EQ(output.probes[1].name, "middle");
  EXPECT_EQ(output.probes[1].first, 4);
  EXPECT_EQ(output.probes[1].second, 7);

  case_.mutable_output()->set_no_contacts_file(true);
  EXPECT_FALSE(convert_case(case_).output.contacts_file);
}

TEST_F(CaseConversion, ValidatesFirst) {
  case_.mutable_wall(0)->set_material("iron");
  case_.mutable_stage(0)->set_cycles(0);
  try {
    convert_case(case_);
    FAIL() << "an invalid case converted";
  } catch (const CaseError& error) {
    ASSERT_EQ(error.problems().size(), 2u);
    EXPECT_THAT(error.problems()[0], HasSubstr("wall[0].material: unknown material \"iron\""));
    EXPECT_THAT(error.problems()[1], HasSubstr("stage[0].cycles: must be > 0"));
  }
}

TEST_F(CaseConversion, TheEngineAcceptsTheResult) {
  const CaseDefinition def = convert_case(case_);
  const World world(def.world);
  EXPECT_EQ(world.particle_count(), 14);
  EXPECT_EQ(world.wall_count(), 4);
  EXPECT_EQ(world.find_wall("top"), 2);
}

}  // namespace
}  // namespace dem::io
