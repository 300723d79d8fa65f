// The one field list of a contact (for_each_contact_field, dem/snapshot.h):
// every history field the world keeps is restored as saved, and the state
// hash changes exactly when a hashed field does.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <type_traits>

#include "dem/snapshot.h"
#include "dem/world.h"
#include "distinct_value.h"
#include "snapshot_worlds.h"

namespace dem {
namespace {

using testing::distinct;
using testing::settling_box;
using testing::sphere_stack;

// Hertz-Mindlin with rolling resistance and the energy budget: every
// column but the contact search's.
template <int Dim>
WorldDefT<Dim> every_column_but_search() {
  if constexpr (Dim == 2) {
    WorldDef def = settling_box();
    for (MaterialDef& m : def.materials) {
      m.youngs_modulus = 1e8;
      m.poisson_ratio = 0.25;
    }
    def.contact_models[0].law = ContactLaw::kHertzMindlin;
    def.contact_models[0].hertz.restitution = 0.4;
    def.contact_models[0].rolling = RollingResistanceDef{0.1, 0.3};
    return def;
  } else {
    WorldDef3 def = sphere_stack(ContactLaw::kHertzMindlin);
    def.contact_models[0].rolling = RollingResistanceDef{0.05, 0.2};
    return def;
  }
}

template <int Dim>
void expect_fields_restore_and_hash(int cycles) {
  BasicWorld<Dim> world(every_column_but_search<Dim>());
  world.cycle(cycles);
  const WorldSnapshotT<Dim> snap = world.snapshot();
  std::size_t row = snap.contacts.size();
  for (std::size_t r = 0; r < snap.contacts.size(); ++r) {
    if (snap.contacts[r].touching) {
      row = r;
      break;
    }
  }
  ASSERT_LT(row, snap.contacts.size()) << "no touching contact";
  const std::uint64_t hash = BasicWorld<Dim>(snap).state_hash();
  EXPECT_EQ(hash, world.state_hash());
  int k = 0, hashed = 0, restored = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo& info, auto field, auto row_of) {
    ++k;
    if constexpr (!std::is_same_v<decltype(row_of), NoRow>) {
      WorldSnapshotT<Dim> changed = snap;
      field(changed.contacts[row]) = distinct(field(snap.contacts[row]), k);
      const BasicWorld<Dim> rebuilt(changed);
      const bool kept = info.column != ContactColumn::kSearch;
      if (info.hashed) {
        ++hashed;
        EXPECT_NE(rebuilt.state_hash(), hash) << info.name << " is hashed";
      } else {
        EXPECT_EQ(rebuilt.state_hash(), hash) << info.name << " is not hashed";
        // Read back as restored (a hashed field may be rewritten by the
        // force report, so the hash is its evidence).
        const WorldSnapshotT<Dim> resaved = rebuilt.snapshot();
        const auto& saved = field(resaved.contacts[row]);
        if (kept) {
          ++restored;
          EXPECT_TRUE(saved == field(changed.contacts[row])) << info.name << " restored";
        } else {
          EXPECT_TRUE(saved == field(snap.contacts[row])) << info.name << " has no column here";
        }
      }
    }
  });
  std::printf("%dD: %d fields, %d hashed, %d more restored as changed; hash %016llx\n", Dim, k, hashed, restored,
              static_cast<unsigned long long>(hash));
  EXPECT_EQ(hashed, 6);    // shear, normal force, rolling torque, T*, T**, DD
  EXPECT_EQ(restored, 9);  // Mindlin CDF, unloading, reloading, axis, theta; dashpot work (3); formed cycle
}

TEST(SnapshotFields, EveryHistoryFieldRestoresAndHashedOnesChangeTheHash2D) { expect_fields_restore_and_hash<2>(2000); }
TEST(SnapshotFields, EveryHistoryFieldRestoresAndHashedOnesChangeTheHash3D) { expect_fields_restore_and_hash<3>(10); }

}  // namespace
}  // namespace dem
