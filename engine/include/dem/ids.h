// Ids, passed by value and validated at the API (STYLE.md 3). The same ids
// appear in output files and on the wire.
//
// ParticleId, WallId and MaterialId are distinct types: each is built from
// its integer only explicitly (ParticleId{7}), none converts into another or
// back into an int, so a wall id cannot be handed to a call that wants a
// particle (tests/engine/test_ids.cpp proves it at compile time). Inside the
// engine the hot loops keep plain 32-bit index arrays (the contact table's
// columns, the pair table); the types guard the public API.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>

namespace dem {

// The one invalid value, which every id type accepts and compares with
// (`WallId wall = kInvalidId;`, `if (id == kInvalidId)`). It also reads as
// the raw value -1 where a plain index array stores "none".
struct InvalidId {
  constexpr operator std::int32_t() const { return -1; }  // NOLINT(google-explicit-constructor)
};
inline constexpr InvalidId kInvalidId{};

template <typename Tag>
class Id {
 public:
  using Value = std::int32_t;

  constexpr Id() = default;   // invalid
  constexpr Id(InvalidId) {}  // NOLINT(google-explicit-constructor)
  constexpr explicit Id(Value value) : value_(value) {}
  // An array position (std::size_t and friends) as an id, without a
  // narrowing warning at every call site.
  static constexpr Id from_index(std::size_t index) { return Id(static_cast<Value>(index)); }

  constexpr Value value() const { return value_; }
  // The value as an index into an array; only meaningful when valid().
  constexpr std::size_t index() const { return static_cast<std::size_t>(value_); }
  constexpr bool valid() const { return value_ >= 0; }

  friend constexpr auto operator<=>(Id, Id) = default;
  friend constexpr bool operator==(Id, Id) = default;

 private:
  Value value_ = -1;
};

struct ParticleTag;
struct WallTag;
struct MaterialTag;

// A particle, as named when it was created (definition order).
using ParticleId = Id<ParticleTag>;
// A wall, in definition order (removing a wall keeps its id).
using WallId = Id<WallTag>;
// An entry of WorldDef::materials.
using MaterialId = Id<MaterialTag>;

template <typename Tag>
std::string to_string(Id<Tag> id) {
  return std::to_string(id.value());
}

template <typename Char, typename Traits, typename Tag>
std::basic_ostream<Char, Traits>& operator<<(std::basic_ostream<Char, Traits>& out, Id<Tag> id) {
  return out << id.value();
}

}  // namespace dem

template <typename Tag>
struct std::hash<dem::Id<Tag>> {
  std::size_t operator()(dem::Id<Tag> id) const noexcept { return std::hash<std::int32_t>{}(id.value()); }
};
