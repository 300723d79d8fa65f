// The case's flat structs converted and checked by their field lists and
// rules (io/src/case_fields.h, case_rules.h): every list entry meets its case.proto
// field, and a list line with its rule is all a field needs.
#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "case_fields.h"
#include "dem/case.pb.h"
#include "dem/snapshot.pb.h"

// A made-up struct of one member, whose list names a field
// proto::Material has (friction), and one whose list names a field it lacks.
namespace dem::case_fields_test {
struct Slippery {
  double friction = 0.25;
};
struct Coloured {
  double colour = 0.0;
};
}  // namespace dem::case_fields_test
template <>
struct dem::SnapshotFields<dem::case_fields_test::Slippery> {
  static constexpr auto list = std::make_tuple(Field{"friction", &dem::case_fields_test::Slippery::friction});
};
template <>
struct dem::io::CaseRules<dem::case_fields_test::Slippery> {
  static constexpr std::array list = {FieldRule{.name = "friction", .check = Check::kNonNegative}};
};
template <>
struct dem::SnapshotFields<dem::case_fields_test::Coloured> {
  static constexpr auto list = std::make_tuple(Field{"colour", &dem::case_fields_test::Coloured::colour});
};
template <>
struct dem::io::CaseRules<dem::case_fields_test::Coloured> {
  static constexpr std::array list = {FieldRule{.name = "colour", .check = Check::kFinite}};
};

namespace dem::io {
namespace {

// Reading and checking a message of each struct's case.proto type walks
// every entry of its list: one the schema lacks throws naming it.
template <class T>
void expect_every_field_found(const google::protobuf::Message& message) {
  T def;
  EXPECT_NO_THROW(read_fields(message, def)) << message.GetDescriptor()->full_name();
  ProblemList problems;
  EXPECT_NO_THROW(check_fields<T>(message, "x", problems)) << message.GetDescriptor()->full_name();
}

TEST(CaseFields, EveryListedFieldHasItsCaseField) {
  expect_every_field_found<MaterialDef>(proto::Material());
  expect_every_field_found<LinearLawDef>(proto::LinearLaw());
  expect_every_field_found<LinearLawDef>(proto::LinearRestitutionLaw());
  expect_every_field_found<HertzDampingDef>(proto::HertzLaw());
  expect_every_field_found<RollingResistanceDef>(proto::RollingResistance());
  expect_every_field_found<ContactModelDef>(proto::ContactModel());
  expect_every_field_found<DampingDef>(proto::Damping());
  expect_every_field_found<ServoDef>(proto::Servo());
  expect_every_field_found<BoxAxisDef>(proto::BoxAxis());
  expect_every_field_found<BoxControlT<2>>(proto::BoxControl());
  expect_every_field_found<BoxControlT<3>>(proto::BoxControl());
  expect_every_field_found<StopConditions>(proto::Until());
  expect_every_field_found<ParticleDefT<2>>(proto::Particle());
  expect_every_field_found<ParticleDefT<3>>(proto::Particle());
  expect_every_field_found<WallDefT<2>>(proto::Wall());
  expect_every_field_found<WallDefT<3>>(proto::Wall());
  expect_every_field_found<WallMotionT<2>>(proto::WallMotion());
  expect_every_field_found<WallMotionT<3>>(proto::WallMotion());
  expect_every_field_found<CentripetalGravityT<2>>(proto::CentripetalGravity());
  expect_every_field_found<CentripetalGravityT<3>>(proto::CentripetalGravity());
  expect_every_field_found<PeriodicDefT<2>>(proto::Periodic());
  expect_every_field_found<PeriodicDefT<3>>(proto::Periodic());
  expect_every_field_found<ShapeDefT<2>>(proto::Superquadric());
  expect_every_field_found<ShapeDefT<3>>(proto::Ellipsoid());
  expect_every_field_found<LatticeDefT<2>>(proto::Lattice());
  expect_every_field_found<LatticeDefT<3>>(proto::Lattice());
  expect_every_field_found<RandomPackingDefT<2>>(proto::RandomPacking());
  expect_every_field_found<RandomPackingDefT<3>>(proto::RandomPacking());
  expect_every_field_found<TrimDef>(proto::Trim());
  expect_every_field_found<analysis::ForceDistributionSettings>(proto::ForceDistributionOutput());
  expect_every_field_found<analysis::CompressionSettings>(proto::CompressionOutput());
}

// The snapshot's settings are checked by the same rules, its fields named
// as the members behind a flattened struct's prefix.
TEST(CaseFields, TheSnapshotsFieldsMeetTheSameRules) {
  ProblemList problems;
  proto::SnapshotMaterial material;
  material.set_poisson_ratio(0.5);
  check_snapshot_fields<MaterialDef>(material, "settings.materials[0]", problems);
  proto::SnapshotContactModel model;
  model.set_linear_normal_stiffness(1e6);
  model.set_rolling_friction(-1);
  model.set_hertz_restitution(2);
  check_snapshot_fields<LinearLawDef>(model, "m", problems, "linear_");
  check_snapshot_fields<RollingResistanceDef>(model, "m", problems, "rolling_");
  check_snapshot_fields<HertzDampingDef>(model, "m", problems, "hertz_");
  EXPECT_NO_THROW(check_snapshot_fields<DampingDef>(proto::SnapshotDamping(), "settings.damping", problems));
  const std::vector<CaseProblem> found = problems.take();
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].path + ": " + found[0].message,
            "settings.materials[0].poisson_ratio: must be in (-1, 0.5) (got 0.5)");
  EXPECT_EQ(found[1].path + ": " + found[1].message, "m.rolling_friction: must be >= 0 (got -1)");
  EXPECT_EQ(found[2].path + ": " + found[2].message, "m.hertz_restitution: must be in (0, 1] (got 2)");
}

TEST(CaseFields, AListLineAndItsRuleAreConversionAndValidation) {
  using case_fields_test::Slippery;
  proto::Material material;
  material.set_friction(0.6);
  Slippery def;
  read_fields(material, def);
  EXPECT_EQ(def.friction, 0.6);

  material.set_friction(-1);
  ProblemList problems;
  check_fields<Slippery>(material, "material[3]", problems);
  const std::vector<CaseProblem> found = problems.take();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].path, "material[3].friction");
  EXPECT_EQ(found[0].message, "must be >= 0 (got -1)");
}

TEST(CaseFields, AListLineTheSchemaLacksIsNamedNeverSkipped) {
  case_fields_test::Coloured def;
  try {
    read_fields(proto::Material(), def);
    FAIL() << "a list entry without its field was skipped";
  } catch (const std::logic_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind("dem.proto.Material has no field colour", 0), 0u) << error.what();
  }
  ProblemList problems;
  EXPECT_THROW(check_fields<case_fields_test::Coloured>(proto::Material(), "material[0]", problems), std::logic_error);
}

// proto3 cannot tell an unset number from 0: a wall material's density left
// out keeps MaterialDef's default, its other numbers are the case's.
TEST(CaseFields, AZeroTheRuleKeepsLeavesTheDefault) {
  proto::Material material;
  material.set_name("steel");
  material.set_friction(0.0);
  material.set_youngs_modulus(2e11);
  MaterialDef def;
  def.friction = 0.5;
  read_fields(material, def);
  EXPECT_EQ(def.name, "steel");
  EXPECT_EQ(def.density, MaterialDef{}.density);
  EXPECT_EQ(def.friction, 0.0);
  EXPECT_EQ(def.youngs_modulus, 2e11);
}

// Fields with presence are read and checked only when set: a Hertz law's
// restitution, a damping's rotational constants.
TEST(CaseFields, AFieldLeftOutIsNeitherReadNorChecked) {
  proto::HertzLaw law;
  law.set_damping_ratio(-0.1);
  law.set_tangential_damping(true);
  HertzDampingDef hertz;
  read_fields(law, hertz);
  EXPECT_FALSE(hertz.restitution.has_value());
  EXPECT_TRUE(hertz.tangential);
  ProblemList problems;
  check_fields<HertzDampingDef>(law, "contact_model[0].hertz_mindlin", problems);
  const std::vector<CaseProblem> found = problems.take();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].path, "contact_model[0].hertz_mindlin.damping_ratio");

  proto::Damping damping;
  damping.set_local_alpha(0.7);
  DampingDef def;
  read_fields(damping, def);
  EXPECT_EQ(def.local_alpha, 0.7);
  EXPECT_FALSE(def.local_alpha_rotation.has_value());
}

// A contact model's own numbers by ContactModelDef's rules: the
// restitution law's e from the law's message, friction and cohesion when
// set, rolling resistance by its own rules; the materials and the law are
// converted elsewhere (case_conversion.cpp, case_laws.cpp).
TEST(CaseFields, AContactModelsOwnNumbersFollowItsRules) {
  proto::ContactModel model;
  model.add_materials("sand");
  model.mutable_linear_restitution()->set_normal_stiffness(1e6);
  model.mutable_linear_restitution()->set_restitution(0.8);
  model.set_friction(0.3);
  model.mutable_rolling()->set_friction(0.1);
  ContactModelDef def;
  read_fields(model, def);
  EXPECT_EQ(def.restitution, 0.8);
  EXPECT_EQ(def.friction, 0.3);
  EXPECT_FALSE(def.cohesion.has_value());
  EXPECT_EQ(def.rolling.friction, 0.1);
  EXPECT_EQ(def.rolling.damping_ratio, 0.0);
  EXPECT_EQ(def.material_a, kInvalidId);                                    // by name, elsewhere
  EXPECT_EQ(def.linear.normal_stiffness, LinearLawDef{}.normal_stiffness);  // the law's list, case_laws.cpp

  // Another law: e keeps its default, the law's message holds none.
  proto::ContactModel linear;
  linear.mutable_linear()->set_normal_stiffness(1e6);
  ContactModelDef plain;
  read_fields(linear, plain);
  EXPECT_EQ(plain.restitution, ContactModelDef{}.restitution);
  EXPECT_FALSE(plain.friction.has_value());

  // Checked in the rules' order: e (with the law's parameters), then friction, cohesion, rolling.
  model.mutable_linear_restitution()->set_restitution(0);
  model.set_friction(-0.1);
  model.set_cohesion(-2);
  model.mutable_rolling()->set_damping_ratio(-1);
  ProblemList problems;
  check_fields<ContactModelDef>(model, "contact_model[0]", problems);
  std::vector<std::string> lines;
  for (const CaseProblem& problem : problems.take()) lines.push_back(problem.path + ": " + problem.message);
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "contact_model[0].linear_restitution.restitution: must be in (0, 1] (got 0)",
                       "contact_model[0].friction: must be >= 0 (got -0.1)",
                       "contact_model[0].cohesion: must be >= 0 (got -2)",
                       "contact_model[0].rolling.damping_ratio: must be >= 0 (got -1)",
                   }));

  // Left out, nothing is checked: no restitution law, no friction, no rolling.
  ProblemList none;
  check_fields<ContactModelDef>(linear, "contact_model[1]", none);
  EXPECT_TRUE(none.take().empty());
}

// A stage's stop conditions: the numbers by StopConditions' list, set or
// left out; the walls and the region are named, so converted elsewhere.
TEST(CaseFields, AStagesStopConditionsFollowTheirRules) {
  proto::Until until;
  until.set_kinetic_to_elastic_below(1e-4);
  until.set_servo_tolerance(0.02);
  until.set_min_cycles(300);
  until.mutable_wall_stress_above()->set_wall("top");
  until.mutable_wall_stress_above()->set_value(1e5);
  StopConditions def;
  read_fields(until, def);
  EXPECT_EQ(def.kinetic_to_elastic_below, 1e-4);
  EXPECT_EQ(def.servo_tolerance, 0.02);
  EXPECT_FALSE(def.kinetic_energy_below.has_value());
  EXPECT_FALSE(def.wall_stress_above.has_value());
  EXPECT_EQ(def.min_cycles, 300u);
  EXPECT_EQ(def.check_interval, StopConditions{}.check_interval);  // 0 keeps the default
  until.set_check_interval(25);
  read_fields(until, def);
  EXPECT_EQ(def.check_interval, 25u);

  until.set_kinetic_to_elastic_below(0);
  until.set_deviator_strain_above(-0.1);
  ProblemList problems;
  check_fields<StopConditions>(until, "stage[1].until", problems);
  EXPECT_TRUE(problems.reported("stage[1].until.deviator_strain_above"));
  std::vector<std::string> lines;
  for (const CaseProblem& problem : problems.take()) lines.push_back(problem.path + ": " + problem.message);
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "stage[1].until.deviator_strain_above: must be > 0 (got -0.1)",
                       "stage[1].until.kinetic_to_elastic_below: must be > 0 (got 0)",
                   }));
}

// Miyata et al. (2002) eq. 60's trim: a smooth cut's wavelength left out
// keeps TrimDef's; the height and amplitude by their rules.
TEST(CaseFields, ATrimFollowsItsRules) {
  proto::Trim trim;
  trim.set_height(0.2);
  TrimDef def;
  read_fields(trim, def);
  EXPECT_EQ(def.height, 0.2);
  EXPECT_EQ(def.amplitude, 0.0);
  EXPECT_EQ(def.wavelength, TrimDef{}.wavelength);
  trim.set_amplitude(0.01);
  trim.set_wavelength(0.05);
  read_fields(trim, def);
  EXPECT_EQ(def.amplitude, 0.01);
  EXPECT_EQ(def.wavelength, 0.05);

  trim.set_height(std::numeric_limits<double>::infinity());
  trim.set_amplitude(-1);
  ProblemList problems;
  check_fields<TrimDef>(trim, "stage[0].trim", problems);
  std::vector<std::string> lines;
  for (const CaseProblem& problem : problems.take()) lines.push_back(problem.path + ": " + problem.message);
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "stage[0].trim.height: must be a finite number (got inf)",
                       "stage[0].trim.amplitude: must be >= 0 (got -1)",
                   }));
}

// A box control's gain, maximum speed and continuum by its list, an
// axis's strain rate or stress by its own - whichever of the oneof is
// set; the walls, the axis's control and the path are converted by hand.
TEST(CaseFields, ABoxControlsNumbersFollowTheirRules) {
  proto::BoxControl box;
  box.set_gain(1e-6);
  box.set_max_speed(0.01);
  box.set_continuum(true);
  box.set_stress_ratio(2);
  BoxControlT<2> def;
  read_fields(box, def);
  EXPECT_EQ(def.gain, 1e-6);
  EXPECT_EQ(def.max_speed, 0.01);
  EXPECT_TRUE(def.continuum);
  EXPECT_EQ(def.path, StressPath::kNone);  // by hand
  EXPECT_EQ(def.path_value, 0.0);

  proto::BoxAxis axis;
  axis.set_lower_wall("bottom");
  axis.set_stress(-1e3);
  BoxAxisDef a;
  a.strain_rate = 0.5;  // the oneof's other member, left out: kept
  read_fields(axis, a);
  EXPECT_EQ(a.stress, -1e3);
  EXPECT_EQ(a.strain_rate, 0.5);
  EXPECT_EQ(a.lower, kInvalidId);
  ProblemList problems;
  check_fields<BoxAxisDef>(axis, "box_control.axis[1]", problems);
  axis.set_strain_rate(std::numeric_limits<double>::quiet_NaN());
  check_fields<BoxAxisDef>(axis, "box_control.axis[0]", problems);
  std::vector<std::string> lines;
  for (const CaseProblem& problem : problems.take()) lines.push_back(problem.path + ": " + problem.message);
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "box_control.axis[1].stress: must be > 0 (got -1000)",
                       "box_control.axis[0].strain_rate: must be a finite number (got nan)",
                   }));
}

// The plate loading analyses' settings: 0 keeps a default, the force
// distribution is none unless set (its count an unsigned field, the
// engine's int), each stress of contacts_at_stress checked by its index.
TEST(CaseFields, TheCompressionOutputFollowsItsRules) {
  proto::CompressionOutput out;
  out.set_loading_plate("top");
  out.set_final_stress(300e3);
  out.add_contacts_at_stress(100e3);
  out.add_contacts_at_stress(200e3);
  analysis::CompressionSettings def;
  read_fields(out, def);
  const analysis::CompressionSettings defaults;
  EXPECT_EQ(def.transition_stress, defaults.transition_stress);
  EXPECT_EQ(def.final_stress, 300e3);
  EXPECT_EQ(def.contacts_at_stress, (std::vector<double>{100e3, 200e3}));
  EXPECT_FALSE(def.force_distribution.has_value());
  EXPECT_EQ(def.stress_drop_fraction, defaults.stress_drop_fraction);
  EXPECT_EQ(def.loading_plate, kInvalidId);  // by name, elsewhere

  proto::ForceDistributionOutput& d = *out.mutable_force_distribution();
  d.set_stress_from(1e5);
  d.set_stress_to(2e5);
  d.set_snapshots(4);
  read_fields(out, def);
  ASSERT_TRUE(def.force_distribution.has_value());
  EXPECT_EQ(def.force_distribution->stress_from, 1e5);
  EXPECT_EQ(def.force_distribution->stress_to, 2e5);
  EXPECT_EQ(def.force_distribution->snapshots, 4);
  EXPECT_EQ(def.force_distribution->bin_width, analysis::ForceDistributionSettings{}.bin_width);

  out.set_contacts_at_stress(1, -5);
  d.set_stress_from(0);
  d.set_tail_from(-1);
  ProblemList problems;
  check_fields<analysis::CompressionSettings>(out, "output.compression", problems);
  std::vector<std::string> lines;
  for (const CaseProblem& problem : problems.take()) lines.push_back(problem.path + ": " + problem.message);
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "output.compression.contacts_at_stress[1]: must be > 0 (got -5)",
                       "output.compression.force_distribution.stress_from: must be > 0 (got 0)",
                       "output.compression.force_distribution.tail_from: must be >= 0 (got -1)",
                   }));
}

// The particle generators: a Vector as the case's dimension's vector
// (zero when left out), an unsigned count as an int, 0 layers the
// default; the material, a lattice's spacing and arrangement and a
// packing's size classes and attempts are converted by hand.
TEST(CaseFields, ALatticeAndAPackingFollowTheirLists) {
  proto::Lattice lattice;
  lattice.set_material("sand");
  lattice.set_radius(0.01);
  lattice.mutable_origin()->set_x(0.5);
  lattice.mutable_origin()->set_z(0.25);
  lattice.set_columns(4);
  lattice.set_rows(3);
  lattice.set_spacing(0.05);
  LatticeDefT<3> def;
  read_fields(lattice, def);
  EXPECT_EQ(def.radius, 0.01);
  EXPECT_EQ(def.origin, Vec3(0.5, 0, 0.25));
  EXPECT_EQ(def.columns, 4);
  EXPECT_EQ(def.rows, 3);
  EXPECT_EQ(def.layers, 1);                          // 0 keeps the default
  EXPECT_EQ(def.spacing, LatticeDefT<3>{}.spacing);  // by hand
  LatticeDefT<2> flat;
  read_fields(lattice, flat);
  EXPECT_EQ(flat.origin, Vec2(0.5, 0));

  lattice.set_radius(-1);
  ProblemList problems;
  check_fields<LatticeDefT<2>>(lattice, "particles[0].lattice", problems);
  EXPECT_TRUE(problems.reported("particles[0].lattice.radius"));

  proto::RandomPacking packing;
  packing.mutable_min()->set_x(-1);
  packing.set_seed(42);
  packing.set_next_size_when_full(true);
  packing.add_size()->set_radius(0.01);
  RandomPackingDefT<2> random;
  read_fields(packing, random);
  EXPECT_EQ(random.min, Vec2(-1, 0));
  EXPECT_EQ(random.max, Vec2(0, 0));  // left out: zero, as the case says
  EXPECT_EQ(random.seed, 42u);
  EXPECT_TRUE(random.next_size_when_full);
  EXPECT_TRUE(random.sizes.empty());  // by hand
}

// A superquadric's angle is given in degrees and held in radians, as
// before (angle_deg x pi / 180); its numbers' problems name the case's
// fields. An ellipsoid's semi-axes are its Vector.
TEST(CaseFields, AShapeFollowsItsRules) {
  proto::Superquadric shape;
  shape.set_a(0.02);
  shape.set_b(0.01);
  shape.set_n(4);
  shape.set_angle_deg(30);
  ShapeDefT<2> def;
  read_fields(shape, def);
  EXPECT_EQ(def.a, 0.02);
  EXPECT_EQ(def.b, 0.01);
  EXPECT_EQ(def.n, 4);
  EXPECT_EQ(def.angle, 30 * std::numbers::pi / 180.0);

  shape.set_n(1);
  shape.set_angle_deg(std::numeric_limits<double>::infinity());
  ProblemList problems;
  check_fields<ShapeDefT<2>>(shape, "particles[1].particle.superquadric", problems);
  std::vector<std::string> lines;
  for (const CaseProblem& problem : problems.take()) lines.push_back(problem.path + ": " + problem.message);
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "particles[1].particle.superquadric.n: must be in (1, 10] (got 1)",
                       "particles[1].particle.superquadric.angle_deg: must be a finite number (got inf)",
                   }));

  proto::Ellipsoid ellipsoid;
  ellipsoid.mutable_semi_axes()->set_x(0.03);
  ellipsoid.mutable_semi_axes()->set_y(0.02);
  ellipsoid.mutable_semi_axes()->set_z(0.01);
  ellipsoid.mutable_orientation()->set_w(2);
  ShapeDefT<3> solid;
  read_fields(ellipsoid, solid);
  EXPECT_EQ(solid.axes, Vec3(0.03, 0.02, 0.01));
  EXPECT_TRUE(solid.orientation.isApprox(Quaternion::Identity()));  // by hand
}

// A wall's motion: its velocity as the dimension's vector, its servo
// walked (and checked) by ServoDef's rules when set; the angular velocity
// by hand. A centripetal field's and a periodic cell's vectors likewise.
TEST(CaseFields, AWallsMotionAndTheBodyForcesFollowTheirLists) {
  proto::WallMotion motion;
  motion.mutable_velocity()->set_y(-0.05);
  WallMotionT<2> def;
  read_fields(motion, def);
  EXPECT_EQ(def.velocity, Vec2(0, -0.05));
  EXPECT_FALSE(def.servo.has_value());
  motion.mutable_servo()->set_target_force(100);
  motion.mutable_servo()->set_gain(-1);
  read_fields(motion, def);
  ASSERT_TRUE(def.servo.has_value());
  EXPECT_EQ(def.servo->target_force, 100);
  ProblemList problems;
  check_fields<WallMotionT<3>>(motion, "wall[2].motion", problems);
  const std::vector<CaseProblem> found = problems.take();
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].path + ": " + found[0].message, "wall[2].motion.servo.gain: must be > 0 (got -1)");
  EXPECT_EQ(found[1].path + ": " + found[1].message, "wall[2].motion.servo.max_speed: must be > 0 (got 0)");

  proto::CentripetalGravity field;
  field.mutable_centre()->set_x(1);
  field.set_acceleration(-2);
  CentripetalGravityT<3> centripetal;
  read_fields(field, centripetal);
  EXPECT_EQ(centripetal.centre, Vec3(1, 0, 0));
  EXPECT_EQ(centripetal.acceleration, -2);
  check_fields<CentripetalGravityT<2>>(field, "centripetal_gravity", problems);
  EXPECT_TRUE(problems.reported("centripetal_gravity.acceleration"));

  proto::Periodic cell;
  cell.set_x(true);
  cell.mutable_max()->set_x(2);
  PeriodicDefT<2> periodic;
  read_fields(cell, periodic);
  EXPECT_EQ(periodic.max, Vec2(2, 0));
  EXPECT_FALSE(periodic.axes[0]);  // by hand
}

// A particle's and a wall's own numbers by their lists; materials,
// directions, shapes, spins, motions and faces by hand.
TEST(CaseFields, AParticleAndAWallFollowTheirLists) {
  proto::Particle particle;
  particle.mutable_position()->set_x(0.1);
  particle.mutable_position()->set_z(0.3);
  particle.set_radius(0.01);
  particle.mutable_velocity()->set_y(2);
  ParticleDefT<3> ball;
  read_fields(particle, ball);
  EXPECT_EQ(ball.position, Vec3(0.1, 0, 0.3));
  EXPECT_EQ(ball.radius, 0.01);
  EXPECT_EQ(ball.velocity, Vec3(0, 2, 0));

  proto::Wall wall;
  wall.set_name("lid");
  wall.mutable_point()->set_z(1);
  wall.mutable_direction()->set_x(2);
  wall.set_h1(-1);
  wall.set_h2(1);
  wall.set_k1(-0.5);
  wall.set_k2(0.5);
  WallDefT<3> def;
  read_fields(wall, def);
  EXPECT_EQ(def.name, "lid");
  EXPECT_EQ(def.point, Vec3(0, 0, 1));
  EXPECT_EQ(def.h1, -1);
  EXPECT_EQ(def.h2, 1);
  EXPECT_EQ(def.k1, -0.5);
  EXPECT_EQ(def.k2, 0.5);
  EXPECT_EQ(def.direction, WallDefT<3>{}.direction);  // made unit by hand
  WallDefT<2> flat;
  read_fields(wall, flat);
  EXPECT_EQ(flat.point, Vec2(0, 0));
  EXPECT_EQ(flat.h2, 1);
}

}  // namespace
}  // namespace dem::io
