// The case's flat structs from one definition: the engine's field list of
// each (SnapshotFields, dem/snapshot_fields.h, the list the snapshot walks)
// and, here, one rule per list entry - what the case's value must be. One
// walker converts a case.proto message by those lists (read_fields) and
// one checks it by those rules (check_fields), each finding its field by
// the entry's name, so a problem names the field as a case spells it:
// "material[1].friction: must be >= 0 (got -1)". The snapshot's settings
// are checked by the same rules (check_snapshot_fields, snapshot_rules.cpp),
// so a snapshot holds exactly what a case may.
//
// A new member of a struct below is its struct member, its list line
// (the build fails until it has one), its rule line here (the build fails
// until it has one, check below), a field of its name in
// idl/dem/case.proto (CaseFields.EveryListedFieldHasItsCaseField names a
// missing one) and one in idl/dem/snapshot.proto. Checks across fields or
// messages (a name's uniqueness, a particle material's density > 0, E > 0
// under a Hertz law) stay with the references they need
// (case_validation.cpp, contact_model_checks.cpp).
#pragma once

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "dem/definitions.h"
#include "dem/snapshot_fields.h"
#include "problem_list.h"
#include "snapshot_conversion_fields.h"

namespace dem::io {

// What a case's number must be: ProblemList's check of that name.
enum class Check { kNone, kFinite, kNonNegative, kPositive, kWithin };

struct FieldRule {
  std::string_view name;  // the list entry's
  Check check = Check::kNone;
  Interval interval{};  // for kWithin
  // proto3 cannot tell an unset number from 0, so 0 keeps the struct's default.
  bool zero_keeps_default = false;
  // The case.proto field, when a case spells it otherwise than the member.
  std::string_view field{};
};

// The fraction of local damping, [0, 1) (Miyata eq. 33).
inline constexpr Interval kLocalDamping{0.0, 1.0, false, true};

// CaseRules<T>::list: a FieldRule per entry of SnapshotFields<T>::list.
template <class T>
struct CaseRules;

template <>
struct CaseRules<MaterialDef> {
  static constexpr std::array list = {
      // Particles, walls and contact models refer to it: checked with the references (case_validation.cpp).
      FieldRule{.name = "name"},
      // Only particles need a density (> 0 for theirs, case_validation.cpp); a wall material may leave it out.
      FieldRule{.name = "density", .check = Check::kNonNegative, .zero_keeps_default = true},
      FieldRule{.name = "friction", .check = Check::kNonNegative},
      FieldRule{.name = "cohesion", .check = Check::kNonNegative},
      // > 0 for a particle material a Hertz law serves (contact_model_checks.cpp); a wall of E = 0 is rigid.
      FieldRule{.name = "youngs_modulus", .check = Check::kNonNegative},
      FieldRule{.name = "poisson_ratio", .check = Check::kWithin, .interval = kPoissonRatio},
  };
};
template <>
struct CaseRules<LinearLawDef> {
  static constexpr std::array list = {
      FieldRule{.name = "normal_stiffness", .check = Check::kPositive},
      FieldRule{.name = "shear_stiffness", .check = Check::kNonNegative},
  };
};
template <>
struct CaseRules<HertzDampingDef> {
  static constexpr std::array list = {
      FieldRule{.name = "damping_ratio", .check = Check::kNonNegative},
      FieldRule{.name = "restitution", .check = Check::kWithin, .interval = kRestitution},
      FieldRule{.name = "tangential", .field = "tangential_damping"},
  };
};
template <>
struct CaseRules<RollingResistanceDef> {
  static constexpr std::array list = {
      FieldRule{.name = "friction", .check = Check::kNonNegative},
      FieldRule{.name = "damping_ratio", .check = Check::kNonNegative},
  };
};
template <>
struct CaseRules<DampingDef> {
  static constexpr std::array list = {
      FieldRule{.name = "contact_beta", .check = Check::kNonNegative},
      FieldRule{.name = "global_alpha", .check = Check::kNonNegative},
      FieldRule{.name = "global_alpha_rotation", .check = Check::kNonNegative},
      FieldRule{.name = "local_alpha", .check = Check::kWithin, .interval = kLocalDamping},
      FieldRule{.name = "local_alpha_rotation", .check = Check::kWithin, .interval = kLocalDamping},
  };
};
template <>
struct CaseRules<ServoDef> {
  static constexpr std::array list = {
      FieldRule{.name = "target_force", .check = Check::kFinite},
      FieldRule{.name = "gain", .check = Check::kPositive},
      FieldRule{.name = "max_speed", .check = Check::kPositive},
  };
};

namespace case_fields {

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;

// The rules name the list's entries, each once: as many as the list has.
template <class T>
constexpr bool rules_match_list() {
  constexpr auto& list = SnapshotFields<T>::list;
  constexpr auto& rules = CaseRules<T>::list;
  if (rules.size() != std::tuple_size_v<std::remove_cvref_t<decltype(list)>>) return false;
  for (std::size_t i = 0; i < rules.size(); ++i) {
    if (field_index(list, rules[i].name) == rules.size()) return false;
    for (std::size_t j = 0; j < i; ++j) {
      if (rules[j].name == rules[i].name) return false;
    }
  }
  return true;
}

#define DEM_CASE_RULES_MATCH(T) \
  static_assert(rules_match_list<T>(), #T ": give each entry of its field list one rule in CaseRules (case_fields.h)")
DEM_CASE_RULES_MATCH(MaterialDef);
DEM_CASE_RULES_MATCH(LinearLawDef);
DEM_CASE_RULES_MATCH(HertzDampingDef);
DEM_CASE_RULES_MATCH(RollingResistanceDef);
DEM_CASE_RULES_MATCH(DampingDef);
DEM_CASE_RULES_MATCH(ServoDef);
#undef DEM_CASE_RULES_MATCH

template <class T>
constexpr const FieldRule& rule_for(std::string_view name) {
  for (const FieldRule& rule : CaseRules<T>::list) {
    if (rule.name == name) return rule;
  }
  throw std::logic_error("no case rule for " + std::string(name));  // rules_match_list rules it out
}

// How a schema spells a list entry's field: case.proto as the rule says
// (the member's name unless the rule gives another), snapshot.proto by the
// member's name behind the prefix of a flattened struct ("hertz_").
struct Naming {
  bool snapshot = false;
  std::string_view prefix{};
};

// The field a list entry meets; a list line whose field the schema lacks
// is a programming error, named.
inline const FieldDescriptor& field_of(const Message& m, const FieldRule& rule, const Naming& naming = {}) {
  const std::string name = naming.snapshot ? std::string(naming.prefix) + std::string(rule.name)
                                           : std::string(rule.field.empty() ? rule.name : rule.field);
  const FieldDescriptor* field = m.GetDescriptor()->FindFieldByName(name);
  if (field == nullptr) {
    throw std::logic_error(m.GetDescriptor()->full_name() + " has no field " + name +
                           ", which a field list names (dem/snapshot_fields.h, io/src/case_fields.h): add it to " +
                           (naming.snapshot ? "idl/dem/snapshot.proto" : "idl/dem/case.proto"));
  }
  return *field;
}

template <class T, class Entry>
void read_member(const Message& m, const Entry& entry, T& def) {
  using Member = fields::MemberOf<Entry>;
  const FieldRule& rule = rule_for<T>(entry.name);
  const FieldDescriptor& field = field_of(m, rule);
  if (const char* problem = fields::type_problem<Member>(field)) {
    throw std::logic_error("field " + field.full_name() + " cannot carry its list entry: " + problem);
  }
  Member value = def.*entry.member;
  fields::get_value(value, m, &field);
  if constexpr (std::is_arithmetic_v<Member>) {
    if (rule.zero_keeps_default && value == Member{}) return;
  }
  def.*entry.member = std::move(value);
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
void check_named(const Message& message, const std::string& path, Checker& checker, const Naming& naming) {
  std::apply(
      [&](const auto&... entry) {
        const auto check = [&](std::string_view name) {
          const FieldRule& rule = rule_for<T>(name);
          if (rule.check == Check::kNone) return;
          const FieldDescriptor& field = field_of(message, rule, naming);
          if (field.cpp_type() != FieldDescriptor::CPPTYPE_DOUBLE || field.is_repeated()) {
            throw std::logic_error("field " + field.full_name() + " has a rule for numbers but is not a double");
          }
          const google::protobuf::Reflection& r = *message.GetReflection();
          if (field.has_presence() && !r.HasField(message, &field)) return;
          apply_rule(checker, path + '.' + field.name(), r.GetDouble(message, &field), rule);
        };
        (check(entry.name), ...);
      },
      SnapshotFields<T>::list);
}

}  // namespace case_fields

// The message's fields into def, entry by entry of T's list; a field with
// presence left out, or a zero where the rule keeps the default, leaves
// the member as it was.
template <class T>
void read_fields(const google::protobuf::Message& message, T& def) {
  std::apply([&](const auto&... entry) { (case_fields::read_member(message, entry, def), ...); },
             SnapshotFields<T>::list);
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
  case_fields::check_named<T>(message, path, checker, {.snapshot = true, .prefix = prefix});
}

}  // namespace dem::io
