// A contact record as the wire's ContactEntry, field by field from the
// engine's one list of a record's fields (ContactRecordFields,
// dem/measures.h) to the wire field of the same name (idl/dem/command.idl,
// generated into protocol::Fields<ContactEntry>). The build fails while a
// wire field has no record field of its name, while a record field has
// neither a wire field nor a line in kNotOnTheWire, and while a pair has
// types wire_value does not convert between.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "dem/measures.h"
#include "dem/protocol/messages.h"

namespace dem::service {

// Record fields that do not travel: naming one here is the decision that
// clients do without it. None today: users querying contacts draw force
// chains and fabric tensors from the whole record.
inline constexpr std::array<std::string_view, 0> kNotOnTheWire{};

namespace contact_entry {

// Engine values as wire values: ids as their int32 values, 2D vectors with
// z = 0; numbers and flags as they are.
inline std::int32_t wire_value(ParticleId id) { return id.value(); }
inline std::int32_t wire_value(WallId id) { return id.value(); }
inline protocol::Vector3 wire_value(const Vec2& v) { return {v.x(), v.y(), 0.0}; }
inline protocol::Vector3 wire_value(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
template <class T>
requires std::is_arithmetic_v<T> T wire_value(T value) { return value; }

inline constexpr auto kWire = protocol::Fields<protocol::ContactEntry>::list;
inline constexpr std::size_t kWireCount = std::tuple_size_v<decltype(kWire)>;
template <int Dim>
inline constexpr auto kRecord = ContactRecordFields<Dim>::list;
template <int Dim>
inline constexpr std::size_t kRecordCount = std::tuple_size_v<decltype(kRecord<Dim>)>;

constexpr bool not_on_the_wire(std::string_view name) {
  for (std::string_view kept : kNotOnTheWire) {
    if (kept == name) return true;
  }
  return false;
}

// Every record field goes to the wire field of its name, or is named in
// kNotOnTheWire (not both).
template <int Dim>
constexpr bool every_record_field_placed() {
  return std::apply(
      [](const auto&... f) { return (((field_index(kWire, f.name) < kWireCount) != not_on_the_wire(f.name)) && ...); },
      kRecord<Dim>);
}
// Every name in kNotOnTheWire is a record field.
template <int Dim>
constexpr bool not_on_the_wire_are_fields() {
  for (std::string_view name : kNotOnTheWire) {
    if (field_index(kRecord<Dim>, name) == kRecordCount<Dim>) return false;
  }
  return true;
}

static_assert(every_record_field_placed<2>() && every_record_field_placed<3>(),
              "a ContactRecordT field has no ContactEntry field of its name: add one to idl/dem/command.idl, or name "
              "the field in kNotOnTheWire");
static_assert(not_on_the_wire_are_fields<2>() && not_on_the_wire_are_fields<3>(),
              "kNotOnTheWire names a field ContactRecordT does not have");

// The wire field I, from the record field of its name.
template <std::size_t I, int Dim>
void fill(protocol::ContactEntry& entry, const ContactRecordT<Dim>& record) {
  constexpr auto wire = std::get<I>(kWire);
  constexpr std::size_t source = field_index(kRecord<Dim>, wire.name);
  static_assert(source < kRecordCount<Dim>,
                "a ContactEntry field has no ContactRecordT field of its name (ContactRecordFields, dem/measures.h)");
  constexpr auto from = std::get<source>(kRecord<Dim>);
  using Wire = std::remove_cvref_t<decltype(entry.*wire.member)>;
  static_assert(std::is_same_v<decltype(wire_value(record.*from.member)), Wire>,
                "a record field and its wire field differ in type: give wire_value the conversion");
  entry.*wire.member = wire_value(record.*from.member);
}

}  // namespace contact_entry

template <int Dim>
protocol::ContactEntry to_entry(const ContactRecordT<Dim>& record) {
  protocol::ContactEntry entry;
  [&]<std::size_t... I>(std::index_sequence<I...>) { (contact_entry::fill<I>(entry, record), ...); }
  (std::make_index_sequence<contact_entry::kWireCount>{});
  return entry;
}

}  // namespace dem::service
