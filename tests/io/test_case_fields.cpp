// The case's flat structs converted and checked by their field lists and
// rules (io/src/case_fields.h, case_rules.h): every list entry meets its case.proto
// field, and a list line with its rule is all a field needs.
#include <gtest/gtest.h>

#include <array>
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

}  // namespace
}  // namespace dem::io
