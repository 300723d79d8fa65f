// The case's flat structs from one definition: the engine's field list of
// each (SnapshotFields, dem/snapshot_fields.h, the list the snapshot walks)
// and its rules (case_rules.h). One walker converts a case.proto message
// by those lists (read_fields) and one checks it by those rules
// (check_fields), each finding its field by the entry's name, so a problem
// names the field as a case spells it: "material[1].friction: must be >= 0
// (got -1)". The snapshot's settings are checked by the same rules
// (check_snapshot_fields, snapshot_rules.cpp), so a snapshot holds exactly
// what a case may. A rule may place its field in a message of the case's
// (a law's parameters) or leave the member to code that converts it by
// hand (elsewhere: a name looked up, a oneof's case); a member that is a
// struct with rules, or an optional one, is its message walked by them; a
// repeated number is checked item by item, named field[i]; an unsigned
// count (uint32) is the engine's int; a Vector the engine's vector; an
// angle in degrees radians.
//
// A new member of a struct with rules (case_rules.h: materials, contact
// models and laws, damping, particles, walls, their motions and servos,
// body forces, periodic cells, box controls, stop conditions, trims, shapes, lattices and random
// packings, the compression output) is its struct member, its list line
// (the build fails until it has one), its rule line (the build fails
// until it has one), a field of its name in idl/dem/case.proto
// (CaseFields.EveryListedFieldHasItsCaseField names a missing one) and, if
// a snapshot holds the struct, one in idl/dem/snapshot.proto; nothing here.
#pragma once

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>

#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "case_rules.h"
#include "problem_list.h"
#include "snapshot_conversion_fields.h"

namespace dem::io {
namespace case_fields {

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;

// How a schema spells a list entry's field: case.proto as the rule says
// (the member's name unless the rule gives another), snapshot.proto by the
// member's name behind the prefix of a flattened struct ("hertz_").
struct Naming {
  bool snapshot = false;
  std::string prefix{};
};

// The message a list entry's field is in: m, or the message field of m's
// the rule says holds it (a snapshot flattens those, so there m); null
// when that message is not set.
inline const Message* holder_of(const Message& m, const FieldRule& rule, const Naming& naming) {
  if (rule.inside.empty() || naming.snapshot) return &m;
  const FieldDescriptor* inside = m.GetDescriptor()->FindFieldByName(std::string(rule.inside));
  if (inside == nullptr || inside->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE || inside->is_repeated()) {
    throw std::logic_error(m.GetDescriptor()->full_name() + " has no message field " + std::string(rule.inside) +
                           ", which the rule of " + std::string(rule.name) + " names (io/src/case_rules.h)");
  }
  const google::protobuf::Reflection& r = *m.GetReflection();
  return r.HasField(m, inside) ? &r.GetMessage(m, inside) : nullptr;
}

// The field a list entry meets; a list line whose field the schema lacks
// is a programming error, named.
inline const FieldDescriptor& field_of(const Message& m, const FieldRule& rule, const Naming& naming = {}) {
  const std::string name = naming.snapshot ? std::string(naming.prefix) + std::string(rule.name)
                                           : std::string(rule.field.empty() ? rule.name : rule.field);
  const FieldDescriptor* field = m.GetDescriptor()->FindFieldByName(name);
  if (field == nullptr) {
    throw std::logic_error(m.GetDescriptor()->full_name() + " has no field " + name +
                           ", which a field list names (dem/snapshot_fields.h, io/src/case_rules.h): add it to " +
                           (naming.snapshot ? "idl/dem/snapshot.proto" : "idl/dem/case.proto"));
  }
  return *field;
}

// A struct with rules of its own is a message field, walked by them.
inline const Message* nested_message(const Message& m, const FieldDescriptor& field) {
  if (field.cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE || field.is_repeated()) {
    throw std::logic_error("field " + field.full_name() + " cannot carry its list entry: a struct wants a message");
  }
  const google::protobuf::Reflection& r = *m.GetReflection();
  return r.HasField(m, &field) ? &r.GetMessage(m, &field) : nullptr;
}

template <class T>
void read_fields_of(const Message& message, T& def);

// A proto::Vector as the engine's vector of the case's dimension (a 2D
// case's z is 0, validation saw to it); left out, zero.
template <class V>
V vector_of(const Message& m, const FieldDescriptor& field) {
  if (field.message_type() != proto::Vector::descriptor() || field.is_repeated()) {
    throw std::logic_error("field " + field.full_name() + " cannot carry its list entry: a vector wants a Vector");
  }
  const auto& v = static_cast<const proto::Vector&>(m.GetReflection()->GetMessage(m, &field));
  if constexpr (V::RowsAtCompileTime == 2) {
    return {v.x(), v.y()};
  } else {
    return {v.x(), v.y(), v.z()};
  }
}

// The I-th entry of T's list, its member type and its rule, known at
// compile time: a member converted elsewhere is never instantiated here,
// whatever its type.
template <class T, std::size_t I>
constexpr const auto& entry_at() {
  return std::get<I>(SnapshotFields<T>::list);
}
template <class T, std::size_t I>
using MemberAt = fields::MemberOf<decltype(entry_at<T, I>())>;

template <class T, std::size_t I>
void read_member(const Message& m, T& def) {
  using Member = MemberAt<T, I>;
  constexpr FieldRule rule = rule_for<T>(entry_at<T, I>().name);
  if constexpr (!rule.elsewhere) {
    Member& member = def.*entry_at<T, I>().member;
    const Message* holder = holder_of(m, rule, {});
    if (holder == nullptr) return;
    const FieldDescriptor& field = field_of(*holder, rule);
    if constexpr (HasCaseRules<Member>) {
      if (const Message* nested = nested_message(*holder, field)) read_fields_of(*nested, member);
    } else if constexpr (OptionalRules<Member>::value) {
      if (const Message* nested = nested_message(*holder, field)) read_fields_of(*nested, member.emplace());
    } else if constexpr (std::is_same_v<Member, Vec<2>> || std::is_same_v<Member, Vec<3>>) {
      member = vector_of<Member>(*holder, field);
    } else {
      const google::protobuf::Reflection& r = *holder->GetReflection();
      // A oneof's member or a message left out: the member as it was.
      if (!field.is_repeated() && field.has_presence() && !r.HasField(*holder, &field)) return;
      if constexpr (std::is_same_v<Member, int>) {
        // A count the schema keeps unsigned (uint32), as the engine's int.
        if (field.cpp_type() == FieldDescriptor::CPPTYPE_UINT32 && !field.is_repeated()) {
          const int value = static_cast<int>(r.GetUInt32(*holder, &field));
          if (!(rule.zero_keeps_default && value == 0)) member = value;
          return;
        }
      }
      if (const char* problem = fields::type_problem<Member>(field)) {
        throw std::logic_error("field " + field.full_name() + " cannot carry its list entry: " + problem);
      }
      Member value = member;
      fields::get_value(value, *holder, &field);
      if constexpr (std::is_arithmetic_v<Member>) {
        if (rule.zero_keeps_default && value == Member{}) return;
      }
      if constexpr (rule.unit == Unit::kDegrees) value = value * std::numbers::pi / 180.0;
      member = std::move(value);
    }
  }
}

template <class T>
void read_fields_of(const Message& message, T& def) {
  constexpr std::size_t n = std::tuple_size_v<std::remove_cvref_t<decltype(SnapshotFields<T>::list)>>;
  [&]<std::size_t... I>(std::index_sequence<I...>) { (read_member<T, I>(message, def), ...); }
  (std::make_index_sequence<n>{});
}

// The checker's check the rule names: ProblemList's for a case, the
// snapshot's range checks for a snapshot (snapshot_rules.cpp).
template <class Checker>
void apply_rule(Checker& checker, const std::string& path, double value, const FieldRule& rule) {
  switch (rule.check) {
    case Check::kNone:
      break;
    case Check::kFinite:
      checker.finite(path, value);
      break;
    case Check::kNonNegative:
      checker.non_negative(path, value);
      break;
    case Check::kPositive:
      checker.positive(path, value);
      break;
    case Check::kWithin:
      checker.within(path, value, rule.interval);
      break;
  }
}

template <class T, class Checker>
void check_named(const Message& message, const std::string& path, Checker& checker, const Naming& naming);

// The R-th rule of T's, over its list entry's field, named path.field
// (path.inside.field for a field in a law's message).
template <class T, std::size_t R, class Checker>
void check_member(const Message& message, const std::string& path, Checker& checker, const Naming& naming) {
  constexpr FieldRule rule = CaseRules<T>::list[R];
  if constexpr (!rule.elsewhere) {
    using Member = MemberAt<T, field_index(SnapshotFields<T>::list, rule.name)>;
    const Message* holder = holder_of(message, rule, naming);
    if (holder == nullptr) return;
    const std::string where = holder == &message ? path : path + '.' + std::string(rule.inside);
    if constexpr (HasCaseRules<Member> || OptionalRules<Member>::value) {
      using Nested = typename OptionalRules<Member>::Struct;
      if (naming.snapshot) {  // flattened behind "<member>_", as the snapshot converts it
        check_named<Nested>(message, path, checker,
                            {.snapshot = true, .prefix = naming.prefix + std::string(rule.name) + "_"});
        return;
      }
      const FieldDescriptor& field = field_of(*holder, rule, naming);
      if (const Message* nested = nested_message(*holder, field)) {
        check_named<Nested>(*nested, where + '.' + field.name(), checker, naming);
      }
    } else if constexpr (rule.check != Check::kNone) {
      const FieldDescriptor& field = field_of(*holder, rule, naming);
      if (field.cpp_type() != FieldDescriptor::CPPTYPE_DOUBLE) {
        throw std::logic_error("field " + field.full_name() + " has a rule for numbers but is not a double");
      }
      const google::protobuf::Reflection& r = *holder->GetReflection();
      const std::string named = where + '.' + field.name();
      if (field.is_repeated()) {  // each number, named field[i]
        for (int i = 0; i < r.FieldSize(*holder, &field); ++i) {
          apply_rule(checker, named + '[' + std::to_string(i) + ']', r.GetRepeatedDouble(*holder, &field, i), rule);
        }
        return;
      }
      if (field.has_presence() && !r.HasField(*holder, &field)) return;
      apply_rule(checker, named, r.GetDouble(*holder, &field), rule);
    }
  }
}

// The fields in the rules' order, each by the type of its list entry.
template <class T, class Checker>
void check_named(const Message& message, const std::string& path, Checker& checker, const Naming& naming) {
  [&]<std::size_t... R>(std::index_sequence<R...>) { (check_member<T, R>(message, path, checker, naming), ...); }
  (std::make_index_sequence<CaseRules<T>::list.size()>{});
}

}  // namespace case_fields

// The message's fields into def, entry by entry of T's list; a field with
// presence left out, or a zero where the rule keeps the default, leaves
// the member as it was.
template <class T>
void read_fields(const google::protobuf::Message& message, T& def) {
  case_fields::read_fields_of(message, def);
}

// Each of the case message's numbers checked by its rule, a problem named
// path.field; a field with presence left out is not checked.
template <class T>
void check_fields(const google::protobuf::Message& message, const std::string& path, ProblemList& problems) {
  case_fields::check_named<T>(message, path, problems, {});
}

// The same rules over a snapshot's message, whose fields are named as the
// members behind `prefix` (the snapshot holds exactly what a case may).
template <class T, class Checker>
void check_snapshot_fields(const google::protobuf::Message& message, const std::string& path, Checker& checker,
                           std::string_view prefix = {}) {
  case_fields::check_named<T>(message, path, checker, {.snapshot = true, .prefix = std::string(prefix)});
}

}  // namespace dem::io
