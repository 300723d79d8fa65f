// Snapshots through Protocol Buffers: exact in 2D and 3D, and every
// inconsistency named by its field.
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "dem/io/snapshot_conversion.h"
#include "dem/law_traits.h"
#include "dem/snapshot_fields.h"
#include "snapshot_conversion_fields.h"
#include "snapshot_worlds.h"

// Made-up structs whose lists disagree with the schema: a name it lacks,
// and a type its field cannot carry.
namespace dem::schema_test {
struct Recoloured {
  double density = 1.0;
  double colour = 0.0;
};
struct Renumbered {
  double name = 0.0;  // a string in dem.proto.SnapshotMaterial
};
}  // namespace dem::schema_test
template <>
struct dem::SnapshotFields<dem::schema_test::Recoloured> {
  using T = dem::schema_test::Recoloured;
  static constexpr auto list = std::make_tuple(Field{"density", &T::density}, Field{"colour", &T::colour});
};
template <>
struct dem::SnapshotFields<dem::schema_test::Renumbered> {
  using T = dem::schema_test::Renumbered;
  static constexpr auto list = std::make_tuple(Field{"name", &T::name});
};

namespace dem::io {
namespace {

using testing::settling_box;
using testing::sphere_stack;

std::string problems_of(const proto::Snapshot& message) {
  try {
    snapshot_from_proto<2>(message);
  } catch (const SnapshotError& error) {
    return error.what();
  }
  return "";
}

TEST(SnapshotConversion, TwoDimensionalRunContinuesBitForBit) {
  World original(settling_box());
  original.cycle(3000);
  const proto::Snapshot message = snapshot_to_proto(original.snapshot(), SnapshotInfo{"box", "settling"});
  SnapshotInfo info;
  World restored(snapshot_from_proto<2>(message, &info));
  EXPECT_EQ(info.case_name, "box");
  EXPECT_EQ(info.description, "settling");
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  original.cycle(1500);
  restored.cycle(1500);
  EXPECT_GT(original.contacts().size(), 100u);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  EXPECT_EQ(restored.wall_measures()[2].normal_force, original.wall_measures()[2].normal_force);
}

// Randall's fields (1989, 4.5.2 and 6.4.2) through the file: a box whose
// continuum field carries the particles, the field of the last step and a
// centripetal gravity come back, and the run continues bit for bit.
TEST(SnapshotConversion, RandallsFieldsComeBackAndTheRunContinuesBitForBit) {
  WorldDef def = settling_box();
  for (WallDef& wall : def.walls) wall.motion = {};
  BoxControl box;
  box.axes[0] = BoxAxisDef{WallId{3}, WallId{1}, AxisControl::kStrainRate, 0.5, 0.0};
  box.axes[1] = BoxAxisDef{WallId{0}, WallId{2}, AxisControl::kStrainRate, 0.3, 0.0};
  box.continuum = true;
  def.box_control = box;
  def.centripetal_gravity = CentripetalGravity{{0.15, 0.14}, 3.0};
  World original(def);
  original.cycle(2000);
  const WorldSnapshot back = snapshot_from_proto<2>(snapshot_to_proto(original.snapshot(), SnapshotInfo{}));
  ASSERT_TRUE(back.continuum.has_value());
  EXPECT_EQ(back.continuum->rate, original.snapshot().continuum->rate);
  EXPECT_EQ(back.continuum->centre, original.snapshot().continuum->centre);
  ASSERT_TRUE(back.def.centripetal_gravity.has_value());
  EXPECT_EQ(back.def.centripetal_gravity->centre, Vec2(0.15, 0.14));
  EXPECT_EQ(back.def.centripetal_gravity->acceleration, 3.0);
  ASSERT_TRUE(back.def.box_control.has_value());
  EXPECT_TRUE(back.def.box_control->continuum);
  World restored(back);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  original.cycle(1500);
  restored.cycle(1500);
  EXPECT_GT(original.contacts().size(), 50u);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
}

// Ids stay with their particles through a trim (engine/include/dem/world.h):
// the snapshot keeps them, so the restored world names the same particles
// and continues bit for bit.
TEST(SnapshotConversion, IdsAfterATrimComeBackAndTheRunContinuesBitForBit) {
  World original(settling_box());
  original.cycle(2000);
  const int before = original.particle_count();
  original.remove_particles(std::vector<ParticleId>{ParticleId{0}, ParticleId{5}, ParticleId{before - 1}});
  original.cycle(200);
  const proto::Snapshot message = snapshot_to_proto(original.snapshot(), SnapshotInfo{});
  EXPECT_EQ(message.particle_ids_size(), before - 3);
  EXPECT_EQ(message.particle_ids(0), 1);
  EXPECT_EQ(message.particle_id_count(), before);
  World restored(snapshot_from_proto<2>(message));
  EXPECT_EQ(std::vector<ParticleId>(restored.particle_ids().begin(), restored.particle_ids().end()),
            std::vector<ParticleId>(original.particle_ids().begin(), original.particle_ids().end()));
  EXPECT_EQ(restored.missing_particle(ParticleId{before - 1}),
            "particle " + std::to_string(before - 1) + " was removed");
  EXPECT_EQ(restored.particles().position[ParticleId{6}], original.particles().position[ParticleId{6}]);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  original.cycle(500);
  restored.cycle(500);
  std::printf("trimmed box after 2000 + 200 + 500 cycles: original %016llx, restored %016llx\n",
              static_cast<unsigned long long>(original.state_hash()),
              static_cast<unsigned long long>(restored.state_hash()));
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  // A contact that names a removed id is refused.
  proto::Snapshot stale = message;
  stale.mutable_contacts()->set_first(0, 0);
  EXPECT_THROW(World(snapshot_from_proto<2>(stale)), std::exception);
}

// A snapshot written before ids were saved (no particle_ids): ids 0 .. n-1.
TEST(SnapshotConversion, ASnapshotWithoutIdsLoadsWithIdsInOrder) {
  World original(settling_box());
  original.cycle(500);
  const proto::Snapshot message = snapshot_to_proto(original.snapshot(), SnapshotInfo{});
  EXPECT_EQ(message.particle_ids_size(), 0);  // nothing removed: nothing to save
  EXPECT_EQ(message.particle_id_count(), 0);
  World restored(snapshot_from_proto<2>(message));
  ASSERT_EQ(restored.particle_count(), original.particle_count());
  for (int k = 0; k < restored.particle_count(); ++k) EXPECT_EQ(restored.particle_ids()[k], ParticleId{k});
  EXPECT_EQ(restored.state_hash(), original.state_hash());
}

TEST(SnapshotConversion, ThreeDimensionalRunContinuesBitForBit) {
  World3 original(sphere_stack(ContactLaw::kLinear));
  original.cycle(300);
  ASSERT_GT(original.contacts().size(), 20u);
  const proto::Snapshot message = snapshot_to_proto(original.snapshot(), SnapshotInfo{"stack", ""});
  EXPECT_EQ(message.dimension(), 3u);
  World3 restored(snapshot_from_proto<3>(message));
  original.cycle(2000);
  restored.cycle(2000);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
}

// Rolling resistance's torques, an element test's box control and a removed
// wall go through the file as well.
TEST(SnapshotConversion, RollingTorquesBoxControlAndRemovedWallsContinueBitForBit) {
  WorldDef3 def = sphere_stack(ContactLaw::kLinear);
  def.contact_models[0].rolling = RollingResistanceDef{0.1, 0.2};
  World3 original(def);
  original.cycle(300);
  World3 restored(snapshot_from_proto<3>(snapshot_to_proto(original.snapshot(), SnapshotInfo{})));
  original.cycle(300);
  restored.cycle(300);
  EXPECT_EQ(restored.state_hash(), original.state_hash());

  WorldDef box = testing::settling_box();
  box.walls[2].motion.servo.reset();
  BoxControl control;
  control.axes[0] = BoxAxisDef{WallId{3}, WallId{1}, AxisControl::kStrainRate, 0.5, 0.0};
  control.axes[1] = BoxAxisDef{WallId{0}, WallId{2}, AxisControl::kStress, 0.0, 300.0};
  control.gain = 1e-5;
  control.max_speed = 0.05;
  box.box_control = control;
  box.walls.push_back(WallDef{"spare", {0.15, 0.15}, {1, 0}, -0.01, 0.01, MaterialId{1}, {}});
  World boxed(box);
  boxed.remove_wall(WallId{4});
  boxed.cycle(500);
  const proto::Snapshot message = snapshot_to_proto(boxed.snapshot(), SnapshotInfo{});
  EXPECT_TRUE(message.has_box_control());
  EXPECT_TRUE(message.walls(4).removed());
  World again(snapshot_from_proto<2>(message));
  EXPECT_TRUE(again.wall(WallId{4}).removed);
  EXPECT_EQ(again.box_control()->reference_extent, boxed.box_control()->reference_extent);
  boxed.cycle(500);
  again.cycle(500);
  EXPECT_EQ(again.state_hash(), boxed.state_hash());
}

TEST(SnapshotConversion, HertzMindlinHistoryAndEnergyContinueBitForBit) {
  World3 original(sphere_stack(ContactLaw::kHertzMindlin));
  original.cycle(15);
  ASSERT_GT(original.contacts().size(), 20u);
  World3 restored(snapshot_from_proto<3>(snapshot_to_proto(original.snapshot(), SnapshotInfo{})));
  original.cycle(400);
  restored.cycle(400);
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  const EnergyBudget a = original.assembly_measures().energy, b = restored.assembly_measures().energy;
  EXPECT_EQ(a.contact_damping, b.contact_damping);
  EXPECT_EQ(a.friction, b.friction);
}

// Ellipsoids settling on a plate of triangle faces: the faces, the contact
// searches' end points and the neighbour-list bookkeeping survive the trip.
TEST(SnapshotConversion, EllipsoidsOnTriangleFacesContinueBitForBit) {
  WorldDef3 def;
  def.materials = {MaterialDef{"rock", 2650.0, 0.6, 0.0, 1e8, 0.2}};
  ContactModelDef hertz;
  hertz.law = ContactLaw::kHertzLinearTangential;
  hertz.hertz.restitution = 0.4;
  def.contact_models = {hertz};
  RandomPackingDef3 packing;
  packing.max = {0.2, 0.2, 0.3};
  packing.sizes = {{0.0, 20, ShapeDefT<3>{{0.03, 0.021, 0.015}, Quaternion::Identity()}}};
  def.particles = generate_random_packing(packing);
  WallDef3 plate;
  plate.name = "plate";
  plate.h1 = plate.k1 = -0.5;
  plate.h2 = plate.k2 = 0.5;
  const Vec3 a(-0.5, -0.5, 0.0), b(0.7, -0.5, 0.0), c(0.7, 0.7, 0.0), d(-0.5, 0.7, 0.0);
  plate.triangles = {{a, b, c}, {a, c, d}};
  def.walls = {plate};
  def.periodic.axes = {true, true, false};
  def.periodic.max = {0.2, 0.2, 0.0};
  def.gravity = {0.0, 0.0, -9.81};
  def.time_step_fraction = 0.2;
  World3 original(def);
  original.cycle(2500);
  ASSERT_GT(original.wall_measures()[0].contacts, 3);
  const proto::Snapshot message = snapshot_to_proto(original.snapshot(), SnapshotInfo{});
  EXPECT_EQ(message.walls(0).triangles_size(), 18);
  EXPECT_GT(message.contacts().first_size(),
            static_cast<int>(original.contacts().size()));  // rows that do not touch too
  World3 restored(snapshot_from_proto<3>(message));
  original.cycle(1500);
  restored.cycle(1500);
  std::printf("ellipsoids on faces: %zu contacts, hashes %016llx and %016llx\n", original.contacts().size(),
              static_cast<unsigned long long>(original.state_hash()),
              static_cast<unsigned long long>(restored.state_hash()));
  EXPECT_EQ(restored.state_hash(), original.state_hash());
  EXPECT_EQ(snapshot_to_proto(restored.snapshot(), SnapshotInfo{}).SerializeAsString(),
            snapshot_to_proto(original.snapshot(), SnapshotInfo{}).SerializeAsString());

  proto::Snapshot broken = message;
  broken.mutable_walls(0)->mutable_triangles()->RemoveLast();
  broken.mutable_reference_positions()->RemoveLast();
  try {
    snapshot_from_proto<3>(broken);
    FAIL() << "a cut face was accepted";
  } catch (const SnapshotError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("walls[0].triangles: has 17 values"), std::string::npos) << what;
    EXPECT_NE(what.find("reference_positions: has"), std::string::npos) << what;
  }
}

TEST(SnapshotConversion, ConversionIsLossless) {
  World world(settling_box());
  world.cycle(500);
  const proto::Snapshot message = snapshot_to_proto(world.snapshot(), SnapshotInfo{"box", ""});
  const proto::Snapshot again = snapshot_to_proto(snapshot_from_proto<2>(message), SnapshotInfo{"box", ""});
  EXPECT_EQ(again.SerializeAsString(), message.SerializeAsString());
  // 3D, with a Hertz law's settings, elastic constants and vector histories.
  World3 stack(sphere_stack(ContactLaw::kHertzMindlin));
  stack.cycle(20);  // while the grown stack is in contact (it springs apart later)
  ASSERT_FALSE(stack.contacts().empty());
  const proto::Snapshot message3 = snapshot_to_proto(stack.snapshot(), SnapshotInfo{"stack", ""});
  EXPECT_EQ(message3.settings().contact_models(0).law(), proto::SNAPSHOT_LAW_HERTZ_MINDLIN);
  EXPECT_EQ(message3.settings().contact_models(0).hertz_restitution(), 0.8);
  EXPECT_EQ(message3.settings().materials(0).youngs_modulus(), 210e9);
  EXPECT_EQ(message3.particles().rotation_size(), 4 * 27);
  const proto::Snapshot again3 = snapshot_to_proto(snapshot_from_proto<3>(message3), SnapshotInfo{"stack", ""});
  EXPECT_EQ(again3.SerializeAsString(), message3.SerializeAsString());
}

// Every field of the definition and state structs, walked by their field
// lists (SnapshotFields, dem/snapshot_fields.h), filled with a value of its
// own and compared after engine snapshot -> message -> engine snapshot. The
// contact table has its own test (test_snapshot_contacts.cpp), as have the
// particle ids, which must stay a permutation (IdsAfterATrim... above).
bool kept_apart(std::string_view field) {
  return field == "contacts" || field == "particle_order" || field == "particle_ids" || field == "particle_id_count";
}

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <class T>
struct IsVector : std::false_type {};
template <class T>
struct IsVector<std::vector<T>> : std::true_type {};
template <class T>
struct IsArray : std::false_type {};
template <class T, std::size_t N>
struct IsArray<std::array<T, N>> : std::true_type {};
template <class T>
struct IsId : std::false_type {};
template <class T>
constexpr bool kIsContactRow = std::is_same_v<T, ContactSnapshotT<2>> || std::is_same_v<T, ContactSnapshotT<3>>;
template <class Tag>
struct IsId<Id<Tag>> : std::true_type {};

// Values a snapshot's checks accept: ids in range (`materials`, `walls`),
// small thread counts, other numbers exact binary fractions unlike any
// physical default.
struct Filler {
  std::size_t materials, walls;
  int k = 0;  // fields filled so far

  double next() { return 3.0 + 0.25 * ++k; }
  template <class T>
  void fill(T& v) {
    if constexpr (kIsContactRow<T>) {
      return;  // kept apart (above)
    } else if constexpr (HasSnapshotFields<T>) {
      std::apply([&](const auto&... f) { ((kept_apart(f.name) ? void() : fill(v.*f.member)), ...); },
                 SnapshotFields<T>::list);
    } else if constexpr (IsOptional<T>::value) {
      if (!v) v.emplace();
      fill(*v);
    } else if constexpr (IsVector<T>::value || IsArray<T>::value) {
      for (auto& item : v) fill(item);
    } else if constexpr (IsId<T>::value) {
      const std::size_t n = std::is_same_v<T, MaterialId> ? materials : walls;
      v = T::from_index((static_cast<std::size_t>(++k) + (v.valid() ? v.index() : 0)) % n);
    } else if constexpr (std::is_same_v<T, bool>) {
      v = !v;
      ++k;
    } else if constexpr (std::is_same_v<T, std::string>) {
      v = "field " + std::to_string(++k);
    } else if constexpr (std::is_enum_v<T>) {
      v = static_cast<T>(static_cast<int>(v) == 1 ? 0 : 1);  // every engine enum has two values at least
      ++k;
    } else if constexpr (std::is_same_v<T, std::uint64_t>) {
      v = 1000 + static_cast<std::uint64_t>(++k);
    } else if constexpr (std::is_integral_v<T>) {
      v = static_cast<T>(1 + ++k % 3);  // a thread count the limits accept
    } else if constexpr (std::is_floating_point_v<T>) {
      v = next();
    } else if constexpr (std::is_same_v<T, Quaternion>) {
      v = Quaternion(0.5, 0.5, -0.5, 0.5);  // unit, and no default
      v.coeffs()[static_cast<Eigen::Index>(++k % 4)] *= -1.0;
    } else {
      for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = next();
    }
  }
};

// Where a and b differ, by field path ("def.walls[2].motion.servo.gain").
template <class T>
void compare(const T& a, const T& b, const std::string& path, std::vector<std::string>& differ, int& compared) {
  if constexpr (kIsContactRow<T>) {
    return;  // kept apart (above)
  } else if constexpr (HasSnapshotFields<T>) {
    std::apply(
        [&](const auto&... f) {
          ((kept_apart(f.name) ? void()
                               : compare(a.*f.member, b.*f.member,
                                         path + (path.empty() ? "" : ".") + std::string(f.name), differ, compared)),
           ...);
        },
        SnapshotFields<T>::list);
  } else if constexpr (IsOptional<T>::value) {
    if (a.has_value() != b.has_value()) {
      differ.push_back(path + " (set or not)");
    } else if (a) {
      compare(*a, *b, path, differ, compared);
    }
  } else if constexpr (IsVector<T>::value || IsArray<T>::value) {
    if (a.size() != b.size()) {
      differ.push_back(path + " (size)");
      return;
    }
    for (std::size_t i = 0; i < a.size(); ++i)
      compare(a[i], b[i], path + "[" + std::to_string(i) + "]", differ, compared);
  } else {
    bool same;
    if constexpr (std::is_same_v<T, Quaternion>) {
      ++compared;
      same = a.coeffs() == b.coeffs();
    } else if constexpr (requires { a.rows(); }) {
      compared += static_cast<int>(a.size());  // an Eigen vector: a value per component, as filled
      same = a == b;
    } else {
      ++compared;
      same = a == b;
    }
    if (!same) differ.push_back(path);
  }
}

// The case's rules bound a few fields (io/src/snapshot_rules.cpp): they get
// values of their own within their ranges, so the filled snapshot is one a
// case could give and its reader accepts it.
template <int Dim>
void keep_within_the_rules(WorldSnapshotT<Dim>& snap) {
  double value = 0.0;
  const auto fraction = [&value] { return value += 0.0078125; };
  for (MaterialDef& material : snap.def.materials) material.poisson_ratio = fraction();
  for (ContactModelDef& model : snap.def.contact_models) {
    model.restitution = fraction();
    if (model.hertz.restitution) model.hertz.restitution = fraction();
  }
  snap.def.damping.local_alpha = fraction();
  if (snap.def.damping.local_alpha_rotation) snap.def.damping.local_alpha_rotation = fraction();
  snap.def.time_step_fraction = fraction();
  if constexpr (Dim == 2) {
    for (ParticleDefT<2>& particle : snap.def.particles) particle.shape.n = 1.0 + fraction();
  }
}

template <int Dim>
void expect_every_field_round_trips(WorldSnapshotT<Dim> snap) {
  Filler filler{snap.def.materials.size(), snap.def.walls.size()};
  filler.fill(snap);
  keep_within_the_rules(snap);
  snap.def.threads = 1;
  const WorldSnapshotT<Dim> back = snapshot_from_proto<Dim>(snapshot_to_proto(snap, SnapshotInfo{"fields", ""}));
  std::vector<std::string> differ;
  int compared = 0;
  compare(back, snap, "", differ, compared);
  for (const std::string& path : differ) ADD_FAILURE() << path << " did not come back as it went";
  std::printf("%dD: %d values filled, %d compared after the round trip, %zu differ\n", Dim, filler.k, compared,
              differ.size());
  EXPECT_EQ(compared, filler.k);
}

// The conversion finds every field by its list's name (dem/snapshot_fields.h,
// io/src/snapshot_conversion_fields.h): each list entry must have its field
// in idl/dem/snapshot.proto, of a type that carries it. A list line added
// without its schema field fails here, by name.
TEST(SnapshotConversion, EveryListedFieldHasItsFieldInTheSchema) {
  for (const int dim : {2, 3}) {
    int checked = 0;
    const std::vector<std::string> problems =
        dim == 2 ? snapshot_schema_problems<2>(&checked) : snapshot_schema_problems<3>(&checked);
    for (const std::string& p : problems) ADD_FAILURE() << dim << "D: " << p;
    std::printf("%dD: %d list entries found in the schema, %zu problems\n", dim, checked, problems.size());
    EXPECT_GT(checked, 80);  // the walk reached into the nested structs
  }
}

TEST(SnapshotConversion, AListEntryTheSchemaLacksIsNamedNeverSkipped) {
  using schema_test::Recoloured;
  std::vector<std::string> problems;
  int checked = 0;
  fields::schema_problems<Recoloured>({proto::SnapshotMaterial::descriptor()}, "", {}, problems, checked);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], "dem.proto.SnapshotMaterial has no field colour");
  EXPECT_EQ(checked, 1);
  fields::schema_problems<schema_test::Renumbered>({proto::SnapshotMaterial::descriptor()}, "", {}, problems, checked);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[1], "dem.proto.SnapshotMaterial.name: a double wants a double field");
  // At run time, both directions throw naming the field.
  proto::SnapshotMaterial message;
  for (const bool writing : {true, false}) {
    try {
      Recoloured value;
      if (writing) {
        fields::put_struct(value, fields::Scope<google::protobuf::Message>(&message));
      } else {
        fields::get_struct(value, fields::Scope<const google::protobuf::Message>(&message));
      }
      ADD_FAILURE() << "a list entry without its field was passed over";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("dem.proto.SnapshotMaterial has no field colour"), std::string::npos)
          << e.what();
    }
  }
}

// The walker checks lengths itself, behind the structure checks: an empty
// array (a field added after a file was written) leaves the member at its
// default, another length is refused by field.
TEST(SnapshotConversion, TheWalkerKeepsDefaultsForEmptyArraysAndRefusesOtherLengths) {
  proto::SnapshotWall message;
  message.add_force(1.0);
  message.add_force(2.0);
  WallSnapshotT<2> state;
  state.initial_point = {5.0, 6.0};
  fields::get_struct(state, fields::Scope<const google::protobuf::Message>(&message));
  EXPECT_EQ(state.force, Vec2(1.0, 2.0));
  EXPECT_EQ(state.initial_point, Vec2(5.0, 6.0));
  message.add_initial_point(1.0);
  try {
    fields::get_struct(state, fields::Scope<const google::protobuf::Message>(&message));
    ADD_FAILURE() << "a point of one value was read";
  } catch (const SnapshotError& e) {
    EXPECT_STREQ(e.what(), "dem.proto.SnapshotWall.initial_point: has 1 values, expected 2");
  }
}

// Enums go by number: every law of the engine's list (dem/law_traits.h)
// has the schema's value of its name (SNAPSHOT_LAW_ and the name in
// capitals), lands on it and comes back; the schema has no other value.
TEST(SnapshotConversion, EveryContactLawKeepsItsSchemaValue) {
  const google::protobuf::EnumDescriptor* schema = proto::SnapshotContactLaw_descriptor();
  EXPECT_EQ(static_cast<std::size_t>(schema->value_count()), contact_laws().size());
  for (const ContactLawTraits& law : contact_laws()) {
    std::string name = std::string("SNAPSHOT_LAW_") + law.name;
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const google::protobuf::EnumValueDescriptor* value = schema->FindValueByName(name);
    ASSERT_NE(value, nullptr) << name << " is missing from SnapshotContactLaw";
    EXPECT_EQ(value->number(), static_cast<int>(law.law)) << name;
    ContactModelDef model;
    model.law = law.law;
    proto::SnapshotContactModel message;
    fields::put_struct(model, fields::Scope<google::protobuf::Message>(&message));
    EXPECT_EQ(message.law(), value->number());
    ContactModelDef back;
    fields::get_struct(back, fields::Scope<const google::protobuf::Message>(&message));
    EXPECT_EQ(back.law, law.law);
  }
}

TEST(SnapshotConversion, EveryDefinitionAndStateFieldComesBackAsItWent) {
  World world(settling_box());
  world.cycle(20);
  expect_every_field_round_trips(world.snapshot());
  World3 stack(sphere_stack(ContactLaw::kHertzMindlin));
  stack.cycle(20);
  expect_every_field_round_trips(stack.snapshot());
}

TEST(SnapshotConversion, KeepsShapesAndPeriodicBoundaries) {
  WorldDef def = settling_box();
  def.particles.resize(12);
  for (std::size_t i = 0; i < def.particles.size(); ++i) {
    // Superquadrics of two exponents and orientations (Miyata et al. 2002, eq. 34).
    def.particles[i].shape = ShapeDefT<2>{0.012, 0.008, i % 2 == 0 ? 2.5 : 4.0, 0.1 * static_cast<double>(i)};
  }
  def.periodic.axes = {true, false};
  def.periodic.min = {0.0, 0.0};
  def.periodic.max = {0.3, 0.0};
  World world(def);
  world.cycle(50);
  SnapshotInfo info;
  const WorldSnapshot back = snapshot_from_proto<2>(snapshot_to_proto(world.snapshot(), SnapshotInfo{}), &info);
  const WorldSnapshot original = world.snapshot();
  for (std::size_t i = 0; i < back.def.particles.size(); ++i) {
    const ShapeDefT<2>& got = back.def.particles[i].shape;
    const ShapeDefT<2>& want = original.def.particles[i].shape;
    EXPECT_EQ(got.a, want.a);
    EXPECT_EQ(got.b, want.b);
    EXPECT_EQ(got.n, want.n);
    EXPECT_EQ(got.angle, want.angle);
  }
  EXPECT_TRUE(back.def.periodic.axes[0]);
  EXPECT_FALSE(back.def.periodic.axes[1]);
  EXPECT_EQ(back.def.periodic.max.x(), 0.3);

  // 3D: ellipsoids' semi-axes and orientations (Miyata et al. 2002, eq. 43).
  World3 stack(sphere_stack(ContactLaw::kLinear));
  WorldSnapshot3 snapshot3 = stack.snapshot();
  for (std::size_t i = 0; i < snapshot3.def.particles.size(); ++i) {
    snapshot3.def.particles[i].shape.axes = {0.004, 0.003, 0.002 + 1e-4 * static_cast<double>(i)};
    snapshot3.def.particles[i].shape.orientation =
        Quaternion(Eigen::AngleAxisd(0.1 * static_cast<double>(i), Vec3::UnitZ()));
  }
  const WorldSnapshot3 back3 = snapshot_from_proto<3>(snapshot_to_proto(snapshot3, SnapshotInfo{}));
  for (std::size_t i = 0; i < back3.def.particles.size(); ++i) {
    EXPECT_EQ(back3.def.particles[i].shape.axes, snapshot3.def.particles[i].shape.axes);
    EXPECT_EQ(back3.def.particles[i].shape.orientation.coeffs(), snapshot3.def.particles[i].shape.orientation.coeffs());
  }
}

TEST(SnapshotConversion, RefusesAnotherFormatVersionOrDimension) {
  World world(settling_box());
  const proto::Snapshot good = snapshot_to_proto(world.snapshot(), SnapshotInfo{});
  proto::Snapshot m = good;
  m.set_format("dem.case");
  EXPECT_NE(problems_of(m).find("format: is \"dem.case\", not \"dem.snapshot\""), std::string::npos) << problems_of(m);
  m = good;
  m.set_version(7);
  EXPECT_NE(problems_of(m).find("version: 7 is not supported"), std::string::npos) << problems_of(m);
  EXPECT_THROW(snapshot_from_proto<3>(good), SnapshotError);
}

TEST(SnapshotConversion, NamesTheFieldOfEachInconsistency) {
  World world(settling_box());
  world.cycle(500);
  const proto::Snapshot good = snapshot_to_proto(world.snapshot(), SnapshotInfo{});
  ASSERT_GT(good.contacts().first_size(), 0);

  proto::Snapshot m = good;
  m.mutable_particles()->mutable_position()->RemoveLast();
  EXPECT_NE(problems_of(m).find("particles.position: has 199 values, expected 200 (2 for each of 100)"),
            std::string::npos)
      << problems_of(m);

  m = good;
  m.mutable_particles()->set_radius(3, -1.0);
  m.mutable_particles()->set_material(5, 9);
  const std::string both = problems_of(m);
  EXPECT_NE(both.find("particles.radius[3]: must be a finite number > 0"), std::string::npos) << both;
  EXPECT_NE(both.find("particles.material[5]: material 9 out of range for 2 materials"), std::string::npos) << both;

  m = good;
  m.mutable_particles()->set_velocity(8, std::numeric_limits<double>::quiet_NaN());
  EXPECT_NE(problems_of(m).find("particles.velocity[4]: is not a finite number"), std::string::npos) << problems_of(m);

  m = good;
  m.mutable_contacts()->set_first(0, 100000);
  EXPECT_NE(problems_of(m).find("contacts[0].first: particle 100000 out of range"), std::string::npos)
      << problems_of(m);

  m = good;
  m.mutable_contacts()->mutable_sliding()->RemoveLast();
  EXPECT_NE(problems_of(m).find("contacts.sliding: has"), std::string::npos) << problems_of(m);

  m = good;
  m.mutable_walls(2)->mutable_point()->Add(1.0);
  EXPECT_NE(problems_of(m).find("walls[2].point: has 3 values, expected 2"), std::string::npos) << problems_of(m);

  m = good;
  m.set_time_step(0.0);
  EXPECT_NE(problems_of(m).find("time_step: must be a finite number > 0"), std::string::npos) << problems_of(m);
}

TEST(SnapshotConversion, ListsAtMostADozenProblems) {
  World world(settling_box());
  proto::Snapshot m = snapshot_to_proto(world.snapshot(), SnapshotInfo{});
  for (int i = 0; i < m.particles().radius_size(); ++i) m.mutable_particles()->set_radius(i, 0.0);
  const std::string text = problems_of(m);
  EXPECT_NE(text.find("... and 88 more problems"), std::string::npos) << text;
}

}  // namespace
}  // namespace dem::io
