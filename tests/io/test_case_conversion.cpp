#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <variant>

#include "case_laws.h"
#include "dem/io/case_conversion.h"
#include "dem/io/world_checks.h"
#include "dem/law_traits.h"
#include "dem/programme.h"
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

// A case names its law by the field of ContactModel's `law` oneof, whose
// name is the engine's name of the law (dem/law_traits.h): each field is a
// law of the engine's list, each law of the list has its field, and a
// model setting it reads as that law (case_laws.h).
TEST_F(CaseConversion, EveryLawOfTheSchemaIsALawOfTheEngine) {
  const google::protobuf::OneofDescriptor* laws = proto::ContactModel::descriptor()->FindOneofByName("law");
  ASSERT_NE(laws, nullptr);
  EXPECT_EQ(static_cast<std::size_t>(laws->field_count()), contact_laws().size());
  for (const ContactLawTraits& law : contact_laws()) {
    const google::protobuf::FieldDescriptor* field = proto::ContactModel::descriptor()->FindFieldByName(law.name);
    ASSERT_NE(field, nullptr) << law.name << " is no field of ContactModel";
    EXPECT_EQ(field->containing_oneof(), laws) << law.name;
    proto::ContactModel model;
    model.GetReflection()->MutableMessage(&model, field);  // the law set, its parameters at their defaults
    EXPECT_EQ(case_law(model).law, law.law) << law.name;
  }
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
  EXPECT_EQ(same.material_a, MaterialId{0});
  EXPECT_EQ(same.material_b, MaterialId{0});
  EXPECT_EQ(same.linear.normal_stiffness, 1e6);
  EXPECT_EQ(same.linear.shear_stiffness, 5e5);
  EXPECT_FALSE(same.friction);
  EXPECT_FALSE(same.cohesion);
  const ContactModelDef& mixed = world.contact_models[1];
  EXPECT_EQ(mixed.material_a, MaterialId{0});
  EXPECT_EQ(mixed.material_b, MaterialId{1});
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
  EXPECT_EQ(particles[8].material, MaterialId{0});
  // The single particle.
  EXPECT_EQ(particles[9].position, Vec2(0.09, 0.01));
  EXPECT_EQ(particles[9].material, MaterialId{2});
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
  // 35 discs would cover 92% of the box: room enough by area, but random
  // placement jams near 55%.
  packing.mutable_size(0)->set_count(35);
  packing.set_max_attempts(50);
  try {
    convert_case(case_, {.name = "case.txtpb"});
    FAIL() << "35 discs fitted in the box";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb: particles[2].random_packing: "));
    EXPECT_THAT(error.what(), HasSubstr("after 50 attempts"));
  }
}

// A packing that leaves max_attempts unset tries the engine's default
// (100,000 a particle) - unless the limits allow fewer: then the limit
// bounds the work, as it does for a case that asks.
TEST_F(CaseConversion, AnUnsetMaxAttemptsIsCappedByTheLimit) {
  auto& packing = *case_.mutable_particles(2)->mutable_random_packing();
  packing.mutable_size(0)->set_count(35);  // jams, as above
  packing.clear_max_attempts();
  ResourceLimits limits = machine_limits();
  limits.max_packing_attempts = 70;
  try {
    convert_case(case_, {.name = "case.txtpb"}, limits);
    FAIL() << "35 discs fitted in the box";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("after 70 attempts"));
  }
  // Under the machine's limit (10,000,000) the engine's own default stays.
  try {
    convert_case(case_, {.name = "case.txtpb"});
    FAIL() << "35 discs fitted in the box";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("after 100000 attempts"));
  }
}

// Every pair within the tolerance gets a contact-table row: one far
// beyond a particle's size would make the table quadratic.
TEST_F(CaseConversion, AContactToleranceBeyondTheLargestDiameterIsRefused) {
  case_.mutable_numerics()->set_contact_tolerance(0.02);  // the largest diameter: allowed
  EXPECT_NO_THROW(convert_case(case_));
  case_.mutable_numerics()->set_contact_tolerance(0.5);
  try {
    convert_case(case_, {.name = "case.txtpb"});
    FAIL() << "a tolerance of 25 diameters passed";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case.txtpb: numerics.contact_tolerance: must be at most the largest "
                                        "particle's diameter (0.02 m), got 0.5 m"));
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
  EXPECT_EQ(walls[1].material, MaterialId{1});
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

TEST_F(CaseConversion, PeriodicCell) {
  case_.mutable_periodic()->set_x(true);
  case_.mutable_periodic()->mutable_min()->set_x(-0.1);
  case_.mutable_periodic()->mutable_max()->set_x(0.2);
  const WorldDef world = convert_case(case_).world;
  EXPECT_TRUE(world.periodic.axes[0]);
  EXPECT_FALSE(world.periodic.axes[1]);
  EXPECT_EQ(world.periodic.min.x(), -0.1);
  EXPECT_EQ(world.periodic.max.x(), 0.2);
}

TEST_F(CaseConversion, MiyataDampingForms) {
  case_.mutable_damping()->set_global_alpha_rotation(3.0);  // Miyata eq. 32
  case_.mutable_damping()->set_local_alpha(0.7);            // Miyata eq. 33
  const WorldDef world = convert_case(case_).world;
  EXPECT_EQ(world.damping.global_alpha_rotation, 3.0);
  EXPECT_EQ(world.damping.local_alpha, 0.7);
  EXPECT_FALSE(world.damping.local_alpha_rotation.has_value());
}

TEST_F(CaseConversion, DampingGravityTimeStepAndNumerics) {
  case_.mutable_numerics()->set_contact_tolerance(0.001);
  case_.mutable_time_step()->set_fixed(1e-5);
  const WorldDef world = convert_case(case_).world;
  EXPECT_EQ(world.damping.contact_beta, 1e-5);
  EXPECT_EQ(world.damping.global_alpha, 2);
  EXPECT_FALSE(world.damping.global_alpha_rotation.has_value());
  EXPECT_EQ(world.damping.local_alpha, 0.0);
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
  EXPECT_EQ(stages[1].wall_motions[0].first, WallId{2});  // "top"
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

TEST_F(CaseConversion, AStageSetsTheTimeStepAndFrictionFromThenOn) {
  case_.mutable_stage(0)->mutable_time_step()->set_fixed(2e-5);
  case_.mutable_stage(2)->mutable_time_step()->set_fraction(0.05);
  auto* friction = case_.mutable_stage(2)->add_friction();
  friction->set_material(case_.material(1).name());
  friction->set_friction(0.25);
  const CaseDefinition def = convert_case(case_);
  ASSERT_TRUE(def.stages[0].time_step);
  EXPECT_EQ(def.stages[0].time_step->fixed, 2e-5);
  EXPECT_FALSE(def.stages[1].time_step);
  EXPECT_TRUE(def.stages[1].frictions.empty());
  ASSERT_TRUE(def.stages[2].time_step);
  EXPECT_EQ(def.stages[2].time_step->fixed, 0.0);
  EXPECT_EQ(def.stages[2].time_step->fraction, 0.05);
  ASSERT_EQ(def.stages[2].frictions.size(), 1u);
  EXPECT_EQ(def.stages[2].frictions[0], (std::pair<MaterialId, double>{1, 0.25}));

  // The world takes them when the stage starts.
  World world(def.world);
  StageDef first = def.stages[0];
  first.until = {};
  first.cycles = 1;
  run_stage(world, first);
  EXPECT_EQ(world.time_step(), 2e-5);
  StageDef third = def.stages[2];
  third.cycles = 1;
  run_stage(world, third);
  EXPECT_EQ(world.time_step(), 0.05 * world.undamped_critical_time_step());
  EXPECT_EQ(world.materials()[1].friction, 0.25);
}

TEST_F(CaseConversion, Output) {
  OutputSettings output = convert_case(case_).output;
  EXPECT_EQ(output.interval, 50u);
  EXPECT_TRUE(output.contacts_file);
  ASSERT_EQ(output.probes.size(), 2u);
  EXPECT_EQ(output.probes[1].name, "middle");
  EXPECT_EQ(output.probes[1].first, ParticleId{4});
  EXPECT_EQ(output.probes[1].second, ParticleId{7});

  case_.mutable_output()->set_no_contacts_file(true);
  EXPECT_FALSE(convert_case(case_).output.contacts_file);
}

// Element-test control and measurement regions (Randall 1989, 4.5.2, 4.6).
TEST(CaseConversion2d, ABiaxialBoxItsStagesAndItsRegions) {
  const LoadedCase loaded = load_case_file(test::data_path("biaxial.case.txtpb"));
  const CaseDefinition def = convert_case(loaded.message, loaded.source);
  ASSERT_TRUE(def.world.box_control.has_value());
  const BoxControl& box = *def.world.box_control;
  EXPECT_EQ(box.axes[0].lower, WallId{3});  // left
  EXPECT_EQ(box.axes[0].upper, WallId{1});  // right
  EXPECT_EQ(box.axes[1].control, AxisControl::kStress);
  EXPECT_EQ(box.axes[1].stress, 1e4);
  EXPECT_EQ(box.gain, 5e-6);
  ASSERT_EQ(def.stages.size(), 2u);
  ASSERT_TRUE(def.stages[1].box_control.has_value());
  EXPECT_EQ(def.stages[1].box_control->axes[0].control, AxisControl::kStrainRate);
  EXPECT_EQ(def.stages[1].box_control->axes[0].strain_rate, -0.1);
  EXPECT_EQ(def.stages[1].until.deviator_strain_above, 0.002);
  ASSERT_EQ(def.output.regions.size(), 3u);
  EXPECT_EQ(def.output.regions[0].shape, analysis::RegionShape::kWhole);
  const analysis::Region circle = region_for<2>(def.output.regions[2]);
  EXPECT_EQ(circle.shape, analysis::RegionShape::kBall);
  EXPECT_EQ(circle.radius, 0.02);
  EXPECT_EQ(circle.centre, Vec2(0.035, 0.035));
  const analysis::Region core = region_for<2>(def.output.regions[1]);
  EXPECT_EQ(core.max, Vec2(0.055, 0.055));
  const World world(def.world);
  EXPECT_TRUE(world.box_control().has_value());
}

// Randall's preparation (1989): dense generation (4.4), a box whose field
// carries the particles (4.5.2), the centripetal field of 6.4.2 from the
// start and switched by stages, and quasi-equilibrium judged in a region.
TEST(CaseConversion2d, RandallsPreparationControls) {
  LoadedCase loaded = load_case_file(test::data_path("biaxial.case.txtpb"));
  proto::Case& c = loaded.message;
  c.mutable_particles(0)->mutable_random_packing()->set_next_size_when_full(true);
  c.mutable_box_control()->set_continuum(true);
  c.mutable_centripetal_gravity()->mutable_centre()->set_x(0.035);
  c.mutable_centripetal_gravity()->mutable_centre()->set_y(0.03);
  c.mutable_centripetal_gravity()->set_acceleration(20);
  c.mutable_stage(0)->mutable_body_force()->mutable_gravity()->set_y(-9.81);
  proto::RegionThreshold& quiet = *c.mutable_stage(1)->mutable_until()->mutable_region_out_of_balance_below();
  quiet.set_region("circle");
  quiet.set_value(0.1);
  const CaseDefinition def = convert_case(c, loaded.source);
  ASSERT_TRUE(def.world.box_control.has_value());
  EXPECT_TRUE(def.world.box_control->continuum);
  ASSERT_TRUE(def.world.centripetal_gravity.has_value());
  EXPECT_EQ(def.world.centripetal_gravity->centre, Vec2(0.035, 0.03));
  EXPECT_EQ(def.world.centripetal_gravity->acceleration, 20.0);
  // The stage's body force replaces both: gravity set, the field gone.
  ASSERT_TRUE(def.stages[0].body_force.has_value());
  EXPECT_EQ(def.stages[0].body_force->gravity, Vec2(0.0, -9.81));
  EXPECT_FALSE(def.stages[0].body_force->centripetal.has_value());
  EXPECT_FALSE(def.stages[1].body_force.has_value());
  ASSERT_TRUE(def.stages[1].until.region_out_of_balance_below.has_value());
  const auto& threshold = *def.stages[1].until.region_out_of_balance_below;
  const auto* circle = std::get_if<RegionT<2>>(&threshold.region);
  ASSERT_NE(circle, nullptr);
  EXPECT_EQ(circle->name, "circle");
  EXPECT_EQ(circle->shape, RegionShape::kBall);
  EXPECT_EQ(circle->radius, 0.02);
  EXPECT_EQ(threshold.value, 0.1);
  const World world(def.world);
  EXPECT_TRUE(world.box_control()->continuum);
  EXPECT_EQ(world.centripetal_gravity()->acceleration, 20.0);
}

TEST_F(CaseConversion, AStageRemovesAWallAndReleasesTheBox) {
  case_.mutable_stage(2)->add_remove_wall("top");
  case_.mutable_stage(2)->set_release_box_control(true);
  const CaseDefinition def = convert_case(case_);
  EXPECT_EQ(def.stages[2].remove_walls, (std::vector<WallId>{WallId{2}}));
  EXPECT_TRUE(def.stages[2].release_box_control);
  EXPECT_FALSE(def.stages[2].box_control.has_value());
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
  EXPECT_EQ(world.find_wall("top"), WallId{2});
}

TEST_F(CaseConversion, A2dCaseIsTwoDimensionalAndOfDiscs) {
  EXPECT_EQ(case_dimension(case_), 2);
  const AnyCaseDefinition any = convert_any_case(case_);
  ASSERT_TRUE(std::holds_alternative<CaseDefinition>(any));
  EXPECT_EQ(std::get<CaseDefinition>(any).world.planar_particle, PlanarParticle::kDisc);
  EXPECT_EQ(std::get<CaseDefinition>(any).world.contact_models[0].law, ContactLaw::kLinear);
}

TEST_F(CaseConversion, A2dCaseIsNotRead3d) {
  try {
    convert_case<3>(case_, {.name = "case.txtpb"});
    FAIL() << "a 2D case converted to 3D";
  } catch (const CaseError& error) {
    EXPECT_EQ(std::string(error.what()), "case.txtpb: dimension: the case is 2D, but a 3D case is expected here");
  }
}

// The 2D case of tests/io/data/hertz_2d.case.txtpb: the newer laws, spheres
// in the plane, and discs from a CSV file.
TEST(CaseConversion2d, HertzLawsSpheresInThePlaneAndAParticleFile) {
  const LoadedCase loaded = load_case_file(test::data_path("hertz_2d.case.txtpb"));
  const CaseDefinition def = convert_case(loaded.message, loaded.source);
  EXPECT_EQ(def.world.planar_particle, PlanarParticle::kSphere);
  EXPECT_EQ(def.world.materials[0].youngs_modulus, 7e10);
  EXPECT_EQ(def.world.materials[0].poisson_ratio, 0.25);
  const ContactModelDef& pairs = def.world.contact_models[0];
  EXPECT_EQ(pairs.law, ContactLaw::kHertzLinearTangential);
  EXPECT_EQ(pairs.hertz.damping_ratio, 0.1);
  EXPECT_FALSE(pairs.hertz.restitution);
  EXPECT_FALSE(pairs.hertz.tangential);
  const ContactModelDef& walls = def.world.contact_models[1];
  EXPECT_EQ(walls.law, ContactLaw::kLinearRestitution);
  EXPECT_EQ(walls.linear.normal_stiffness, 1e7);
  EXPECT_EQ(walls.linear.shear_stiffness, 5e6);
  EXPECT_EQ(walls.restitution, 0.5);
  // discs_2d.csv (no header), then the explicit particle.
  ASSERT_EQ(def.world.particles.size(), 3u);
  EXPECT_EQ(def.world.particles[1].position, Vec2(0.08, 0.05));
  EXPECT_EQ(def.world.particles[1].radius, 0.01);
  EXPECT_EQ(def.world.particles[1].material, MaterialId{0});
  EXPECT_EQ(def.world.particles[2].angular_velocity, 2);
  const World world(def.world);
  EXPECT_EQ(world.particle_count(), 3);
}

class CaseConversion3d : public ::testing::Test {
 protected:
  CaseDefinition3 convert() const { return convert_case<3>(loaded_.message, loaded_.source); }

  LoadedCase loaded_ = test::valid_3d_case();
};

TEST_F(CaseConversion3d, TheCaseDeclaresItsDimension) {
  EXPECT_EQ(case_dimension(loaded_.message), 3);
  const AnyCaseDefinition any = convert_any_case(loaded_.message, loaded_.source);
  ASSERT_TRUE(std::holds_alternative<CaseDefinition3>(any));
  EXPECT_EQ(std::get<CaseDefinition3>(any).name, "spheres_3d");
}

TEST_F(CaseConversion3d, IsNotRead2d) {
  try {
    convert_case(loaded_.message, loaded_.source);
    FAIL() << "a 3D case converted to 2D";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("valid_3d.case.txtpb:9:1: dimension: the case is 3D, but a 2D case is "
                                        "expected here"));
  }
}

TEST_F(CaseConversion3d, MaterialsCarryTheirElasticConstants) {
  const WorldDef3 world = convert().world;
  ASSERT_EQ(world.materials.size(), 3u);
  EXPECT_EQ(world.materials[0].youngs_modulus, 2.1e11);
  EXPECT_EQ(world.materials[0].poisson_ratio, 0.28);
  EXPECT_EQ(world.materials[1].youngs_modulus, 6.3e10);
  EXPECT_EQ(world.materials[2].youngs_modulus, 0);  // a rigid wall
}

TEST_F(CaseConversion3d, HertzMindlinLawsAndTheirDamping) {
  const WorldDef3 world = convert().world;
  ASSERT_EQ(world.contact_models.size(), 3u);
  const ContactModelDef& fallback = world.contact_models[0];
  EXPECT_EQ(fallback.material_a, kInvalidId);
  EXPECT_EQ(fallback.law, ContactLaw::kHertzMindlin);
  EXPECT_EQ(fallback.hertz.restitution, 0.8);
  EXPECT_TRUE(fallback.hertz.tangential);
  const ContactModelDef& steel_wall = world.contact_models[1];
  EXPECT_EQ(steel_wall.material_a, MaterialId{0});
  EXPECT_EQ(steel_wall.material_b, MaterialId{2});
  EXPECT_EQ(steel_wall.law, ContactLaw::kHertzMindlin);
  EXPECT_EQ(steel_wall.hertz.damping_ratio, 0.05);
  EXPECT_FALSE(steel_wall.hertz.restitution);
  EXPECT_FALSE(steel_wall.hertz.tangential);
  EXPECT_EQ(steel_wall.friction, 0.5);
}

TEST_F(CaseConversion3d, ParticleSourcesExpandInOrder) {
  const std::vector<ParticleDef3> particles = convert().world.particles;
  ASSERT_EQ(particles.size(), 21u);
  // The single sphere.
  EXPECT_EQ(particles[0].position, Vec3(0.005, 0.005, 0.004));
  EXPECT_EQ(particles[0].velocity, Vec3(0, 0, -0.1));
  EXPECT_EQ(particles[0].angular_velocity, Vec3(1, 2, 3));
  EXPECT_EQ(particles[0].material, MaterialId{1});
  // The lattice: 3 columns x 2 rows x 2 layers, the second layer above the first.
  EXPECT_EQ(particles[1].position, Vec3(0.001, 0.001, 0.001));
  EXPECT_NEAR(particles[7].position.z(), 0.003, 1e-15);
  EXPECT_NEAR(particles[12].position.x(), 0.005, 1e-15);
  EXPECT_NEAR(particles[12].position.y(), 0.003, 1e-15);
  // The random packing, inside its box.
  for (std::size_t i = 13; i < 18; ++i) {
    EXPECT_EQ(particles[i].radius, 0.0008);
    EXPECT_GE(particles[i].position.z(), 0.0068);
    EXPECT_LE(particles[i].position.z(), 0.0092);
  }
  // spheres_3d.csv, shifted by the offset, of the source's material.
  EXPECT_EQ(particles[18].position, Vec3(0.008, 0.002, 0.001));
  EXPECT_EQ(particles[19].position, Vec3(0.008, 0.006, 0.001));
  EXPECT_EQ(particles[20].radius, 0.0009);
  EXPECT_EQ(particles[20].material, MaterialId{0});
}

TEST_F(CaseConversion3d, WallsAreRectanglesFacingTheParticles) {
  const std::vector<WallDef3> walls = convert().world.walls;
  ASSERT_EQ(walls.size(), 6u);
  EXPECT_EQ(walls[0].name, "floor");
  EXPECT_EQ(walls[0].point, Vec3(0, 0, 0));
  EXPECT_EQ(walls[0].direction, Vec3(1, 0, 0));
  EXPECT_EQ(walls[0].direction2, Vec3(0, 1, 0));
  EXPECT_EQ(walls[0].h2, 0.01);
  EXPECT_EQ(walls[1].k2, 0.012);
  EXPECT_EQ(walls[4].direction, Vec3(1, 0, 0));  // direction { x: 2 }, normalised
  EXPECT_EQ(walls[2].material, MaterialId{2});
  // Each normal u x v points into the box.
  const Vec3 inward[] = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, -1}};
  for (std::size_t i = 0; i < walls.size(); ++i) {
    EXPECT_EQ(walls[i].direction.cross(walls[i].direction2), inward[i]) << walls[i].name;
  }
}

TEST_F(CaseConversion3d, NearlyPerpendicularSidesAreMadeOrthonormal) {
  auto& direction2 = *loaded_.message.mutable_wall(0)->mutable_direction2();
  direction2.set_x(1e-7);
  direction2.set_y(3);
  const WallDef3 floor = convert().world.walls[0];
  EXPECT_EQ(floor.direction.dot(floor.direction2), 0);
  EXPECT_NEAR(floor.direction2.norm(), 1, 1e-15);
}

TEST_F(CaseConversion3d, GravityStagesAndMotion) {
  const CaseDefinition3 def = convert();
  EXPECT_EQ(def.world.gravity, Vec3(0, 0, -9.81));
  EXPECT_EQ(def.world.time_step_fraction, 0.2);
  ASSERT_EQ(def.stages.size(), 2u);
  EXPECT_EQ(def.stages[0].until.kinetic_energy_below, 1e-15);
  ASSERT_EQ(def.stages[1].wall_motions.size(), 1u);
  EXPECT_EQ(def.stages[1].wall_motions[0].first, WallId{5});  // "lid"
  EXPECT_EQ(def.stages[1].wall_motions[0].second.velocity, Vec3(0, 0, -0.05));
  EXPECT_EQ(def.stages[1].wall_motions[0].second.angular_velocity, Vec3(0, 0, 0.1));
  ASSERT_EQ(def.output.probes.size(), 1u);
  EXPECT_EQ(def.output.probes[0].second, ParticleId{2});
}

TEST_F(CaseConversion3d, TheEngineAcceptsTheResult) {
  const World3 world(convert().world);
  EXPECT_EQ(world.particle_count(), 21);
  EXPECT_EQ(world.wall_count(), 6);
  EXPECT_EQ(world.find_wall("lid"), WallId{5});
}

TEST_F(CaseConversion3d, AMissingParticleFileIsNamed) {
  loaded_.message.mutable_particles(3)->mutable_csv_file()->set_path("no_such.csv");
  try {
    convert();
    FAIL() << "a missing particle file converted";
  } catch (const CaseError& error) {
    ASSERT_EQ(error.problems().size(), 1u);
    EXPECT_THAT(error.problems()[0], HasSubstr("valid_3d.case.txtpb:55:13: particles[3].csv_file: " +
                                               test::data_path("no_such.csv").string() +
                                               ": cannot read the particle file: No such file or directory"));
  }
}

TEST_F(CaseConversion3d, MalformedParticleFileRowsAreNamedByLine) {
  loaded_.message.mutable_particles(3)->mutable_csv_file()->set_path("malformed_3d.csv");
  try {
    convert();
    FAIL() << "a malformed particle file converted";
  } catch (const CaseError& error) {
    ASSERT_EQ(error.problems().size(), 3u);
    const std::string file = test::data_path("malformed_3d.csv").string();
    EXPECT_THAT(error.problems()[0], HasSubstr("particles[3].csv_file: " + file +
                                               ":4: expected 4 values (x,y,z,r), got 3 (x,y,r is a 2D row; the case "
                                               "is 3D)"));
    EXPECT_THAT(error.problems()[1], HasSubstr(file + ":5: column 2 (y): \"north\" is not a number"));
    EXPECT_THAT(error.problems()[2], HasSubstr(file + ":6: column 4 (r): the radius must be > 0 (got -0.001)"));
  }
}

TEST_F(CaseConversion3d, AnAbsoluteParticleFilePathStaysAsItIs) {
  loaded_.message.mutable_particles(3)->mutable_csv_file()->set_path(test::data_path("spheres_3d.csv").string());
  loaded_.source.directory = "/nowhere";
  EXPECT_EQ(convert().world.particles.size(), 21u);
}

TEST_F(CaseConversion3d, ProbeIdsAreCheckedOnceTheParticleFilesAreRead) {
  loaded_.message.mutable_output()->mutable_probe(0)->set_second(21);
  try {
    convert();
    FAIL() << "a probe of a particle that does not exist converted";
  } catch (const CaseError& error) {
    EXPECT_THAT(error.what(), HasSubstr("output.probe[0].second: no particle with id 21 (the case defines 21 "
                                        "particles, ids 0 to 20)"));
  }
}

// Validation cannot see a particle file's radii (0.001 m here): the
// tolerance is held to them once the file is read.
TEST_F(CaseConversion3d, TheContactToleranceIsCheckedOnceTheParticleFilesAreRead) {
  loaded_.message.mutable_numerics()->set_contact_tolerance(0.003);
  EXPECT_TRUE(find_case_problems(loaded_.message).empty());
  try {
    convert();
    FAIL() << "a tolerance beyond every particle's diameter converted";
  } catch (const CaseError& error) {
    ASSERT_EQ(error.problems().size(), 1u);
    EXPECT_THAT(error.problems()[0], HasSubstr("numerics.contact_tolerance: must be at most the largest particle's "
                                               "diameter (0.002 m), got 0.003 m; leave it out for a tenth of the "
                                               "mean radius"));
  }
}

class SuperquadricConversion : public ::testing::Test {
 protected:
  proto::Case case_ = load_case_file(test::data_path("superquadrics.case.txtpb")).message;
};

TEST_F(SuperquadricConversion, ExplicitParticlesCarryTheirShapeAndAngle) {
  const WorldDef world = convert_case(case_).world;
  ASSERT_EQ(world.particles.size(), 22u);
  const ShapeDefT<2>& first = world.particles[0].shape;
  EXPECT_EQ(first.a, 0.05);
  EXPECT_EQ(first.b, 0.025);
  EXPECT_EQ(first.n, 4);
  EXPECT_DOUBLE_EQ(first.angle, std::numbers::pi / 2);
  EXPECT_EQ(world.particles[1].shape.angle, 0);
  EXPECT_EQ(world.particles[1].shape.n, 2.5);
}

TEST_F(SuperquadricConversion, APackedClassTurnsEachParticleAtRandom) {
  const WorldDef world = convert_case(case_).world;
  double smallest = 10, largest = -10;
  for (std::size_t i = 2; i < world.particles.size(); ++i) {
    const ShapeDefT<2>& s = world.particles[i].shape;
    EXPECT_EQ(s.a, 0.04);
    EXPECT_EQ(s.b, 0.02);
    EXPECT_GE(world.particles[i].radius, 0.04);  // placed by its bounding circle
    smallest = std::min(smallest, s.angle);
    largest = std::max(largest, s.angle);
  }
  EXPECT_GT(largest - smallest, 1.0);
  EXPECT_NO_THROW(World{world});
}

TEST_F(SuperquadricConversion, StagesTrimPlaceAndStopOnThePlate) {
  const std::vector<StageDef> stages = convert_case(case_).stages;
  ASSERT_EQ(stages.size(), 3u);
  EXPECT_FALSE(stages[0].trim);
  EXPECT_FALSE(stages[0].place_wall);
  ASSERT_TRUE(stages[1].trim);
  EXPECT_EQ(stages[1].trim->height, 0.3);
  EXPECT_EQ(stages[1].trim->amplitude, 0.05);
  EXPECT_EQ(stages[1].trim->wavelength, 0.5);
  ASSERT_TRUE(stages[2].place_wall);
  EXPECT_EQ(stages[2].place_wall->wall, WallId{1});
  EXPECT_EQ(stages[2].place_wall->clearance, 0.002);
  ASSERT_TRUE(stages[2].until.wall_settlement_above);
  EXPECT_EQ(stages[2].until.wall_settlement_above->wall, WallId{1});
  EXPECT_EQ(stages[2].until.wall_settlement_above->value, 0.005);
  ASSERT_TRUE(stages[2].until.wall_stress_above);
  EXPECT_EQ(stages[2].until.wall_stress_above->value, 1e5);
}

TEST_F(SuperquadricConversion, ASmoothTrimKeepsTheDefaultWavelength) {
  case_.mutable_stage(1)->mutable_trim()->clear_amplitude();
  case_.mutable_stage(1)->mutable_trim()->clear_wavelength();
  const std::optional<TrimDef> trim = convert_case(case_).stages[1].trim;
  ASSERT_TRUE(trim);
  EXPECT_EQ(trim->amplitude, 0);
  EXPECT_EQ(trim->wavelength, TrimDef{}.wavelength);
}

TEST_F(SuperquadricConversion, CompressionOutputWithItsDefaults) {
  const std::optional<analysis::CompressionSettings> compression = convert_case(case_).output.compression;
  ASSERT_TRUE(compression);
  const analysis::CompressionSettings defaults;
  EXPECT_EQ(compression->loading_plate, WallId{1});
  EXPECT_EQ(compression->bottom_plate, WallId{0});
  EXPECT_EQ(compression->loading_stage, 2);  // the stage that places the plate
  EXPECT_EQ(compression->transition_stress, defaults.transition_stress);
  EXPECT_EQ(compression->final_stress, defaults.final_stress);
  EXPECT_TRUE(compression->contacts_at_stress.empty());
  EXPECT_FALSE(compression->force_distribution);
  EXPECT_EQ(compression->stress_drop_fraction, defaults.stress_drop_fraction);
}

TEST_F(SuperquadricConversion, CompressionOutputAsTheCaseSetsIt) {
  proto::CompressionOutput& out = *case_.mutable_output()->mutable_compression();
  out.set_transition_stress(40e3);
  out.set_final_stress(300e3);
  out.add_contacts_at_stress(50e3);
  out.add_contacts_at_stress(900e3);
  out.set_stress_drop_fraction(0.05);
  out.mutable_force_distribution()->set_stress_from(400e3);
  out.mutable_force_distribution()->set_stress_to(600e3);
  out.mutable_force_distribution()->set_bin_width(0.2);
  case_.mutable_stage(2)->clear_place_wall();
  const analysis::CompressionSettings compression = *convert_case(case_).output.compression;
  EXPECT_EQ(compression.loading_stage, 0);  // no stage places the plate
  EXPECT_EQ(compression.transition_stress, 40e3);
  EXPECT_EQ(compression.final_stress, 300e3);
  EXPECT_EQ(compression.contacts_at_stress, (std::vector<double>{50e3, 900e3}));
  EXPECT_EQ(compression.stress_drop_fraction, 0.05);
  ASSERT_TRUE(compression.force_distribution);
  EXPECT_EQ(compression.force_distribution->stress_from, 400e3);
  EXPECT_EQ(compression.force_distribution->stress_to, 600e3);
  EXPECT_EQ(compression.force_distribution->snapshots, 10);  // the seed's
  EXPECT_EQ(compression.force_distribution->bin_width, 0.2);
  EXPECT_EQ(compression.force_distribution->tail_from, 1.0);
}

class EllipsoidConversion : public ::testing::Test {
 protected:
  proto::Case case_ = load_case_file(test::data_path("ellipsoids.case.txtpb")).message;
};

TEST_F(EllipsoidConversion, AnExplicitEllipsoidKeepsItsAxesAndNormalisedOrientation) {
  const WorldDef3 world = convert_case<3>(case_).world;
  ASSERT_EQ(world.particles.size(), 13u);
  const ShapeDefT<3>& first = world.particles[0].shape;
  EXPECT_TRUE(first.ellipsoid());
  EXPECT_EQ(first.axes, Vec3(0.1, 0.07, 0.05));
  // w: 1, z: 1 is a quarter turn about z once normalised.
  const Vec3 turned = first.orientation * Vec3::UnitX();
  EXPECT_NEAR(turned.x(), 0.0, 1e-15);
  EXPECT_NEAR(turned.y(), 1.0, 1e-15);
  EXPECT_NEAR(first.orientation.norm(), 1.0, 1e-15);
}

TEST_F(EllipsoidConversion, APackedClassTakesRandomOrientations) {
  const WorldDef3 world = convert_case<3>(case_).world;
  double smallest_w = 1.0;
  for (std::size_t i = 1; i < world.particles.size(); ++i) {
    const ShapeDefT<3>& s = world.particles[i].shape;
    EXPECT_EQ(s.axes, Vec3(0.08, 0.06, 0.04));
    EXPECT_GE(world.particles[i].radius, 0.08);  // placed by its bounding sphere
    smallest_w = std::min(smallest_w, std::abs(s.orientation.w()));
  }
  EXPECT_LT(smallest_w, 0.9);  // not all left at the identity
}

TEST_F(EllipsoidConversion, AWallOfFacesTakesTheirExtentAndArea) {
  const WorldDef3 world = convert_case<3>(case_).world;
  const WallDefT<3>& floor = world.walls[0];
  ASSERT_EQ(floor.triangles.size(), 2u);
  EXPECT_EQ(floor.triangles[0][1], Vec3(2, -1, 0));
  EXPECT_EQ(floor.triangles[1][2], Vec3(-1, 2, 0));
  EXPECT_EQ(floor.h1, -1.0);
  EXPECT_EQ(floor.h2, 2.0);
  EXPECT_EQ(floor.k1, -1.0);
  EXPECT_EQ(floor.k2, 2.0);
  EXPECT_TRUE(world.walls[1].triangles.empty());
  const World3 built(world);
  EXPECT_DOUBLE_EQ(built.wall_area(WallId{0}), 9.0);
}

// The particles fall onto the faces and rest on them: the floor carries
// their weight once they settle (a short check that faces hold ellipsoids).
TEST_F(EllipsoidConversion, EllipsoidsComeToRestOnTheFaces) {
  const CaseDefinition3 def = convert_case<3>(case_);
  World3 world(def.world);
  DampingDef damping;
  damping.local_alpha = 0.5;
  world.set_damping(damping);
  world.cycle(250000);
  double weight = 0.0;
  for (double mass : world.particles().mass) weight += mass * 9.81;
  const double floor = world.wall_measures()[0].normal_force;
  double lowest = 1e9;
  for (const Vec3& x : world.particles().position) lowest = std::min(lowest, x.z());
  std::printf("weight %.6g N, floor %.6g N after %.3g s, lowest centre %.4g\n", weight, floor, world.time(), lowest);
  EXPECT_NEAR(floor, weight, 0.02 * weight);
}

// Built, and its steps checked as dem_run and dem_server check them (a
// fixed step within the critical step under the damping in force).
template <int Dim>
int built_particles(const CaseDefinitionT<Dim>& def, const CaseSource& source) {
  const BasicWorld<Dim> world(def.world);
  check_built_world(world, def.stages, source);
  return world.particle_count();
}

// Every case the repository ships converts, and the engine accepts it.
TEST(ShippedCases, ConvertAndBuild) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(DEM_CASES_DIR)) {
    if (!entry.path().string().ends_with(".case.txtpb")) continue;
    SCOPED_TRACE(entry.path().string());
    const LoadedCase loaded = load_case_file(entry.path());
    std::visit([&](const auto& def) { EXPECT_GT(built_particles(def, loaded.source), 0); },
               convert_any_case(loaded.message, loaded.source));
    ++count;
  }
  EXPECT_GE(count, 20);
}

}  // namespace
}  // namespace dem::io
