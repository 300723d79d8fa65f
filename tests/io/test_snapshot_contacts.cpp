// The contact fields through Protocol Buffers: the engine's field list and
// dem.proto.SnapshotContacts name the same fields, and every field, filled
// with a value of its own, comes back as it went.
#include <google/protobuf/descriptor.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <type_traits>

#include "dem/io/snapshot_conversion.h"
#include "snapshot_worlds.h"

namespace dem::io {
namespace {

using google::protobuf::FieldDescriptor;

TEST(SnapshotContacts, ListAndSchemaNameTheSameFields) {
  const google::protobuf::Descriptor* message = proto::SnapshotContacts::descriptor();
  std::set<std::string> listed;
  for_each_contact_field<3>([&](const ContactFieldInfo& info, auto field, auto) {
    listed.insert(info.name);
    const FieldDescriptor* f = message->FindFieldByName(info.name);
    ASSERT_NE(f, nullptr) << info.name << " is not in idl/dem/snapshot.proto";
    EXPECT_TRUE(f->is_repeated()) << info.name;
    using T = std::remove_cvref_t<decltype(field(std::declval<ContactSnapshotT<3>&>()))>;
    const FieldDescriptor::CppType expected = std::is_same_v<T, bool>            ? FieldDescriptor::CPPTYPE_BOOL
                                              : std::is_same_v<T, std::int32_t>  ? FieldDescriptor::CPPTYPE_INT32
                                              : std::is_same_v<T, std::uint64_t> ? FieldDescriptor::CPPTYPE_UINT64
                                                                                 : FieldDescriptor::CPPTYPE_DOUBLE;
    EXPECT_EQ(f->cpp_type(), expected) << info.name;
  });
  for (int i = 0; i < message->field_count(); ++i) {
    EXPECT_TRUE(listed.count(message->field(i)->name()) == 1)
        << message->field(i)->name() << " is in the schema but not in for_each_contact_field";
  }
  EXPECT_EQ(listed.size(), static_cast<std::size_t>(message->field_count()));
}

// A value unlike v and unlike any other field's (k differs per field).
template <typename T>
T distinct(const T& v, int k) {
  if constexpr (std::is_same_v<T, bool>) {
    return !v;
  } else if constexpr (std::is_integral_v<T>) {
    return v + static_cast<T>(1000 + k);
  } else if constexpr (std::is_floating_point_v<T>) {
    return -3.0 - 0.25 * k;
  } else {
    T out = v;
    for (Eigen::Index i = 0; i < out.size(); ++i) out[i] = -3.0 - 0.25 * k - 0.015625 * static_cast<double>(i + 1);
    return out;
  }
}

// Fills every field but the key of every contact with its own value, then
// engine snapshot -> message -> engine snapshot.
template <int Dim>
void expect_every_field_round_trips(WorldSnapshotT<Dim> snap) {
  ASSERT_FALSE(snap.contacts.empty());
  int k = 0, compared = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo& info, auto field, auto) {
    ++k;
    if (info.role == ContactFieldRole::kKey) return;
    for (ContactSnapshotT<Dim>& c : snap.contacts)
      field(c) = distinct(field(c), k + 40 * static_cast<int>(&c - &snap.contacts[0]));
  });
  // A contact forms no later than the snapshot's cycle (io/src/snapshot_rules.cpp).
  for (const ContactSnapshotT<Dim>& c : snap.contacts) snap.cycle = std::max(snap.cycle, c.formed_cycle);
  const WorldSnapshotT<Dim> back = snapshot_from_proto<Dim>(snapshot_to_proto(snap, SnapshotInfo{"fields", ""}));
  ASSERT_EQ(back.contacts.size(), snap.contacts.size());
  for_each_contact_field<Dim>([&](const ContactFieldInfo& info, auto field, auto) {
    for (std::size_t i = 0; i < snap.contacts.size(); ++i) {
      ++compared;
      EXPECT_TRUE(field(back.contacts[i]) == field(snap.contacts[i])) << info.name << " of contact " << i;
    }
  });
  std::printf("%dD: %d fields of %zu contacts compared after the round trip\n", Dim, k, snap.contacts.size());
  EXPECT_EQ(compared, k * static_cast<int>(snap.contacts.size()));
}

TEST(SnapshotContacts, EveryFieldRoundTrips2D) {
  World world(testing::settling_box());
  world.cycle(500);
  expect_every_field_round_trips<2>(world.snapshot());
}

TEST(SnapshotContacts, EveryFieldRoundTrips3D) {
  World3 world(testing::sphere_stack(ContactLaw::kHertzMindlin));
  world.cycle(100);
  expect_every_field_round_trips<3>(world.snapshot());
}

// A snapshot written before a field was added has none of it: the reader
// takes the default; any other missing field is named.
TEST(SnapshotContacts, FieldsAddedLaterMayBeMissing) {
  World world(testing::settling_box());
  world.cycle(500);
  proto::Snapshot message = snapshot_to_proto(world.snapshot(), SnapshotInfo{});
  message.mutable_contacts()->clear_mindlin_theta();
  message.mutable_contacts()->clear_tangential_spring();
  message.mutable_contacts()->clear_rolling_torque();
  const WorldSnapshot back = snapshot_from_proto<2>(message);
  ASSERT_FALSE(back.contacts.empty());
  EXPECT_EQ(back.contacts[0].mindlin_theta, 1.0);
  EXPECT_EQ(back.contacts[0].tangential_spring, Vec2::Zero());
  message.mutable_contacts()->clear_dashpot_force();
  try {
    snapshot_from_proto<2>(message);
    ADD_FAILURE() << "a snapshot without dashpot_force was read";
  } catch (const SnapshotError& error) {
    EXPECT_NE(std::string(error.what()).find("contacts.dashpot_force: has 0 values"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace dem::io
