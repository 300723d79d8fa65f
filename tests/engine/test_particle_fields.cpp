// The one field list of a particle (for_each_particle_field,
// engine/src/particle_fields.h): every saved state field restores as
// saved, the state hash changes exactly when a hashed field does, the
// side-by-side copies hold each hot field at its place, and reordering
// moves every array.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

#include "contact_blocks.h"
#include "dem/snapshot.h"
#include "dem/world.h"
#include "distinct_value.h"
#include "particle_fields.h"
#include "particles.h"
#include "snapshot_worlds.h"
#include "world_state.h"

namespace dem {
namespace {

using testing::distinct;
using testing::settling_box;
using testing::sphere_stack;

template <int Dim>
WorldDefT<Dim> rich_world() {
  if constexpr (Dim == 2) {
    return settling_box();
  } else {
    return sphere_stack(ContactLaw::kHertzMindlin);
  }
}

// Each state field of one particle changed in a snapshot: restored as
// changed, and the hash moves exactly when the field is hashed.
template <int Dim>
void expect_state_fields_restore_and_hash(int cycles) {
  BasicWorld<Dim> world(rich_world<Dim>());
  world.cycle(cycles);
  const WorldSnapshotT<Dim> snap = world.snapshot();
  const std::uint64_t hash = BasicWorld<Dim>(snap).state_hash();
  ASSERT_EQ(hash, world.state_hash());
  const std::size_t k = snap.def.particles.size() / 2;
  int fields = 0, hashed = 0, state = 0;
  for_each_particle_field<Dim>([&](const ParticleFieldInfo& info, auto, auto saved, auto) {
    ++fields;
    if (info.hashed) ++hashed;
    if constexpr (kInSnapshot<decltype(saved)>) {
      if (info.role != ParticleFieldRole::kState) return;
      ++state;
      WorldSnapshotT<Dim> changed = snap;
      auto& value = saved.field(changed)[k];
      value = distinct(value, fields);
      const BasicWorld<Dim> rebuilt(changed);
      if (info.hashed) {
        EXPECT_NE(rebuilt.state_hash(), hash) << info.name << " is hashed";
      } else {
        EXPECT_EQ(rebuilt.state_hash(), hash) << info.name << " is not hashed";
      }
      const WorldSnapshotT<Dim> resaved = rebuilt.snapshot();
      EXPECT_TRUE(saved.field(resaved)[k] == saved.field(changed)[k]) << info.name << " restored";
    }
  });
  // A hashed definition field changes the hash too.
  WorldSnapshotT<Dim> moved = snap;
  moved.def.particles[k].velocity = distinct(moved.def.particles[k].velocity, 1);
  EXPECT_NE(BasicWorld<Dim>(moved).state_hash(), hash);
  std::printf("%dD: %d particle fields, %d hashed, %d saved state; hash %016llx\n", Dim, fields, hashed, state,
              static_cast<unsigned long long>(hash));
  EXPECT_EQ(hashed, 5);  // position, velocity, angular velocity, rotation, force
  EXPECT_EQ(state, 3);   // rotation, force, moment
}

TEST(ParticleFields, EveryStateFieldRestoresAndHashedOnesChangeTheHash2D) {
  expect_state_fields_restore_and_hash<2>(2000);
}
TEST(ParticleFields, EveryStateFieldRestoresAndHashedOnesChangeTheHash3D) {
  expect_state_fields_restore_and_hash<3>(10);
}

// The hash adds the hashed fields in list order, so they come first: a
// field hashed after one that is not would be a hash nobody meant.
template <int Dim>
bool hashed_fields_first() {
  bool first = true, seen_unhashed = false;
  for_each_particle_field<Dim>([&](const ParticleFieldInfo& info, auto, auto, auto) {
    if (info.hashed && seen_unhashed) first = false;
    if (!info.hashed) seen_unhashed = true;
  });
  return first;
}
TEST(ParticleFields, HashedFieldsComeFirst) {
  EXPECT_TRUE(hashed_fields_first<2>());
  EXPECT_TRUE(hashed_fields_first<3>());
}

// The copies, plain and streamed, hold each particle's hot fields as its arrays do.
template <int Dim, bool kStream>
void expect_hot_copies_match(const Particles<Dim>& p) {
  const auto n = static_cast<std::int64_t>(p.size());
  Column<HotPlace<Dim>> place(p.size());
  Column<HotMotion<Dim>> motion(p.size());
  copy_hot_particles<kStream>(p, place.data(), motion.data(), 0, n);
  finish_streaming();
  for (std::int64_t i = 0; i < n; ++i) {
    EXPECT_TRUE(place[i].position == p.position[i]) << i;
    EXPECT_EQ(place[i].radius, p.radius[i]) << i;
    EXPECT_TRUE(motion[i].velocity == p.velocity[i]) << i;
    EXPECT_EQ(motion[i].mass, p.mass[i]) << i;
    EXPECT_TRUE(motion[i].angular_velocity == p.angular_velocity[i]) << i;
  }
}

template <int Dim>
Particles<Dim> numbered_particles(std::size_t n) {
  Particles<Dim> p;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i);
    p.position.push_back(Vec<Dim>::Constant(x + 0.25));
    p.velocity.push_back(Vec<Dim>::Constant(x + 0.5));
    if constexpr (Dim == 3) {
      p.angular_velocity.push_back(Vec3(x + 0.75, x + 0.875, x + 0.9375));
      p.rotation.push_back(Quaternion::Identity());
    } else {
      p.angular_velocity.push_back(x + 0.75);
      p.rotation.push_back(x);
    }
    p.radius.push_back(x + 1.0);
    p.mass.push_back(x + 2.0);
    p.material.push_back(static_cast<std::int32_t>(i % 3));
    p.force.push_back(Vec<Dim>::Constant(-x));
    p.moment.push_back(Space<Dim>::zero_spin());
    p.inertia.push_back(x + 3.0);
    p.previous_force.push_back(x + 4.0);
    p.reference_position.push_back(Vec<Dim>::Constant(x));
    p.id.push_back(ParticleId::from_index(i));
  }
  p.index_ids(n);
  return p;
}

TEST(ParticleFields, HotCopiesHoldEachHotField) {
  expect_hot_copies_match<2, false>(numbered_particles<2>(37));
  expect_hot_copies_match<2, true>(numbered_particles<2>(37));
  expect_hot_copies_match<3, false>(numbered_particles<3>(37));
  expect_hot_copies_match<3, true>(numbered_particles<3>(37));
}

// Reordering moves every per-slot array with its particle (the empty
// optional ones stay empty).
TEST(ParticleFields, ReorderingMovesEveryArray) {
  Particles<3> p = numbered_particles<3>(11);
  std::vector<Slot> order(11);
  std::iota(order.rbegin(), order.rend(), 0);
  Particles<3> reversed = p;
  int arrays = 0;
  reversed.for_each_slot_array([&](auto& values) {
    ++arrays;
    gather(values, order);
  });
  EXPECT_EQ(arrays, static_cast<int>(particle_field_count<3>()));
  reversed.index_ids();
  for (std::size_t k = 0; k < 11; ++k) {
    const std::size_t from = 10 - k;
    EXPECT_EQ(reversed.id[k], p.id[from]);
    EXPECT_EQ(reversed.slot_of(p.id[from]), static_cast<Slot>(k));
    EXPECT_TRUE(reversed.position[k] == p.position[from]);
    EXPECT_EQ(reversed.previous_force[k], p.previous_force[from]);
    EXPECT_TRUE(reversed.reference_position[k] == p.reference_position[from]);
  }
  EXPECT_TRUE(reversed.shape.empty());
  EXPECT_TRUE(reversed.principal_inertia.empty());
}

// invalidate marks exactly the caches it is given.
TEST(ParticleFields, InvalidateMarksTheCachesGiven) {
  WorldState<3> s;
  s.contacts_stale = false;
  s.blocks.near_stale = false;
  s.blocks.hot_fresh = true;
  invalidate(s, Cache::kNearRows);
  EXPECT_FALSE(s.contacts_stale);
  EXPECT_TRUE(s.blocks.near_stale);
  EXPECT_TRUE(s.blocks.hot_fresh);
  invalidate(s, Cache::kHotCopies);
  EXPECT_FALSE(s.contacts_stale);
  EXPECT_FALSE(s.blocks.hot_fresh);
  s.blocks.near_stale = false;
  s.blocks.hot_fresh = true;
  invalidate(s, Cache::kAll);
  EXPECT_TRUE(s.contacts_stale);
  EXPECT_TRUE(s.blocks.near_stale);
  EXPECT_FALSE(s.blocks.hot_fresh);
}

}  // namespace
}  // namespace dem
