// The id types of dem/ids.h: distinct, explicit, and ordered like their
// values. The static_asserts are the test that matters: a wall id handed to
// a call that wants a particle id does not compile.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <unordered_set>

#include "dem/ids.h"

namespace dem {
namespace {

static_assert(!std::is_convertible_v<WallId, ParticleId>);
static_assert(!std::is_convertible_v<ParticleId, WallId>);
static_assert(!std::is_convertible_v<MaterialId, ParticleId>);
static_assert(!std::is_convertible_v<ParticleId, MaterialId>);
static_assert(!std::is_convertible_v<WallId, MaterialId>);
static_assert(!std::is_convertible_v<MaterialId, WallId>);
static_assert(!std::is_constructible_v<ParticleId, WallId>);
static_assert(!std::is_constructible_v<WallId, MaterialId>);
// No silent way in from an integer, nor back out to one.
static_assert(!std::is_convertible_v<int, ParticleId>);
static_assert(!std::is_convertible_v<std::int32_t, WallId>);
static_assert(!std::is_convertible_v<std::size_t, MaterialId>);
static_assert(!std::is_convertible_v<ParticleId, int>);
static_assert(!std::is_convertible_v<WallId, std::size_t>);
static_assert(!std::is_convertible_v<MaterialId, std::int32_t>);
// Explicitly, from its own integer, it is built; kInvalidId fits every kind.
static_assert(std::is_constructible_v<ParticleId, std::int32_t>);
static_assert(std::is_convertible_v<InvalidId, ParticleId> && std::is_convertible_v<InvalidId, WallId>);
// As small and as cheap to pass as the integer it wraps.
static_assert(sizeof(ParticleId) == sizeof(std::int32_t) && std::is_trivially_copyable_v<ParticleId>);

TEST(Ids, CompareHashAndConvertExplicitly) {
  const ParticleId a{3}, b{7};
  EXPECT_TRUE(a < b);
  EXPECT_EQ(a, ParticleId{3});
  EXPECT_EQ(a.value(), 3);
  EXPECT_EQ(b.index(), 7u);
  EXPECT_EQ(ParticleId::from_index(7), b);
  EXPECT_EQ(to_string(b), "7");
  const std::unordered_set<ParticleId> set{a, b, ParticleId{3}};
  EXPECT_EQ(set.size(), 2u);
}

TEST(Ids, DefaultIsInvalid) {
  const WallId none;
  EXPECT_FALSE(none.valid());
  EXPECT_EQ(none, kInvalidId);
  EXPECT_TRUE(WallId{0}.valid());
  EXPECT_NE(WallId{0}, kInvalidId);
  const std::int32_t raw = kInvalidId;  // what plain index arrays store for "none"
  EXPECT_EQ(raw, -1);
}

}  // namespace
}  // namespace dem
