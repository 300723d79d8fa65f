// What a case's numbers must be, one rule per entry of the engine's field
// list of each struct (SnapshotFields: dem/snapshot_fields.h, and for the
// structs no snapshot holds dem/programme_fields.h, dem/packing_fields.h
// and dem/analysis/compression_fields.h): the one place their ranges are
// declared, and what each entry's field is called in idl/dem/case.proto,
// where it sits, and whether it is converted elsewhere. The case's
// validation (case_fields.h, check_fields) and the snapshot's
// (snapshot_rules.cpp) apply them; a static_assert below wants a rule for
// every list entry, so a new member of these structs cannot be left
// unchecked. Checks across fields or messages (a name's uniqueness, a
// particle material's density > 0, E > 0 under a Hertz law) stay with the
// references they need (case_validation.cpp, contact_model_checks.cpp,
// compression_output_checks.cpp, shape_checks.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "dem/analysis/compression_fields.h"
#include "dem/definitions.h"
#include "dem/packing_fields.h"
#include "dem/programme_fields.h"
#include "dem/snapshot_fields.h"
#include "problem_list.h"

namespace dem::io {

// What a case's number must be: ProblemList's check of that name.
enum class Check { kNone, kFinite, kNonNegative, kPositive, kWithin };

// The unit a case gives a number in, where it is not the engine's.
enum class Unit { kEngine, kDegrees };

struct FieldRule {
  std::string_view name;  // the list entry's
  Check check = Check::kNone;
  Interval interval{};  // for kWithin
  // proto3 cannot tell an unset number from 0, so 0 keeps the struct's default.
  bool zero_keeps_default = false;
  // The case.proto field, when a case spells it otherwise than the member.
  std::string_view field{};
  // The message field of the case's that holds it (a law's parameters);
  // none set, the member keeps its default and nothing is checked.
  std::string_view inside{};
  // Converted and checked by hand where the comment says (a name looked
  // up, a oneof's case, a law's parameters in the message the law names).
  bool elsewhere = false;
  Unit unit = Unit::kEngine;  // kDegrees: read as radians, checked as given
};

// The fraction of local damping, [0, 1) (Miyata eq. 33).
inline constexpr Interval kLocalDamping{0.0, 1.0, false, true};

// CaseRules<T>::list: a FieldRule per entry of SnapshotFields<T>::list,
// in the order the fields are checked. A member that is itself a struct
// with rules (ContactModelDef::rolling) is its message, walked by them.
template <class T>
struct CaseRules;

template <class T>
concept HasCaseRules = requires {
  CaseRules<T>::list;
};
// A member whose message may be left out: std::optional of a struct with
// rules. Struct: the struct walked, the optional's or T itself.
template <class T>
struct OptionalRules : std::false_type {
  using Struct = T;
};
template <HasCaseRules T>
struct OptionalRules<std::optional<T>> : std::true_type {
  using Struct = T;
};

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
struct CaseRules<ContactModelDef> {
  static constexpr std::array list = {
      // The first and last of `materials`, by name (case_conversion.cpp; the references, contact_model_checks.cpp).
      FieldRule{.name = "material_a", .elsewhere = true},
      FieldRule{.name = "material_b", .elsewhere = true},
      // The field of the `law` oneof and its message's parameters, by their own lists (case_laws.cpp).
      FieldRule{.name = "law", .elsewhere = true},
      FieldRule{.name = "linear", .elsewhere = true},
      FieldRule{.name = "hertz", .elsewhere = true},
      // e of the linear restitution law (Miyata eq. 17); checked before
      // friction, as the law's other parameters are.
      FieldRule{
          .name = "restitution", .check = Check::kWithin, .interval = kRestitution, .inside = "linear_restitution"},
      // Left out, the materials' (dem/definitions.h).
      FieldRule{.name = "friction", .check = Check::kNonNegative},
      FieldRule{.name = "cohesion", .check = Check::kNonNegative},
      // None (zeros) when the model leaves it out.
      FieldRule{.name = "rolling"},
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

// Element-test control of a box of walls: the walls by name and what
// drives each axis (a oneof) converted by hand (case_conversion.cpp), as
// are the stress path (a oneof) and the gain and maximum speed's checks,
// which hold only when an axis is servo-driven (case_validation.cpp).
template <>
struct CaseRules<BoxAxisDef> {
  static constexpr std::array list = {
      FieldRule{.name = "lower", .field = "lower_wall", .elsewhere = true},
      FieldRule{.name = "upper", .field = "upper_wall", .elsewhere = true},
      FieldRule{.name = "control", .elsewhere = true},
      FieldRule{.name = "strain_rate", .check = Check::kFinite},
      FieldRule{.name = "stress", .check = Check::kPositive},
  };
};
template <int Dim>
struct CaseRules<BoxControlT<Dim>> {
  static constexpr std::array list = {
      FieldRule{.name = "axes", .field = "axis", .elsewhere = true},
      FieldRule{.name = "path", .elsewhere = true},
      FieldRule{.name = "path_value", .elsewhere = true},
      FieldRule{.name = "gain"},
      FieldRule{.name = "max_speed"},
      // The box's extents when the control is set, filled in by the engine.
      FieldRule{.name = "reference_extent", .elsewhere = true},
      FieldRule{.name = "continuum"},
  };
};
// The particle generators (dem/packing.h). A vector is checked by hand,
// finite and, in 2D, of z = 0 (case_validation.cpp), as are a lattice's
// counts and a packing's box and size classes, whose checks depend on
// their shapes.
template <int Dim>
struct CaseRules<LatticeDefT<Dim>> {
  static constexpr std::array list = {
      FieldRule{.name = "material", .elsewhere = true},  // by name
      FieldRule{.name = "radius", .check = Check::kPositive},
      FieldRule{.name = "origin"},
      FieldRule{.name = "columns"},
      FieldRule{.name = "rows"},
      FieldRule{.name = "layers", .zero_keeps_default = true},
      // 0 stands for 2 x radius, touching neighbours (case_conversion.cpp).
      FieldRule{.name = "spacing", .elsewhere = true},
      // LATTICE_HEXAGONAL, else square (case_conversion.cpp).
      FieldRule{.name = "arrangement", .elsewhere = true},
  };
};
template <int Dim>
struct CaseRules<RandomPackingDefT<Dim>> {
  static constexpr std::array list = {
      FieldRule{.name = "material", .elsewhere = true},  // by name
      FieldRule{.name = "min"},
      FieldRule{.name = "max"},
      // Each class's radius or shape (case_conversion.cpp).
      FieldRule{.name = "sizes", .field = "size", .elsewhere = true},
      FieldRule{.name = "seed"},
      // Left out, the engine's default within the server's limit (case_conversion.cpp).
      FieldRule{.name = "max_attempts", .elsewhere = true},
      FieldRule{.name = "next_size_when_full"},
      // The caller's: a server abandoning a load (case_conversion.cpp).
      FieldRule{.name = "stopped", .elsewhere = true},
  };
};
// A particle's shape (shape_checks.cpp adds what holds across fields).
// Miyata et al. (2002) 2.3(1): 1 < n <= 10 keeps a superquadric's surface
// smooth and convex, away from the corners of n = 1 and the difficulties
// above 10.
template <>
struct CaseRules<ShapeDefT<2>> {
  static constexpr std::array list = {
      FieldRule{.name = "a", .check = Check::kPositive},
      FieldRule{.name = "b", .check = Check::kPositive},
      FieldRule{.name = "n", .check = Check::kWithin, .interval = {1.0, 10.0, true, false}},
      FieldRule{.name = "angle", .check = Check::kFinite, .field = "angle_deg", .unit = Unit::kDegrees},
  };
};
template <>
struct CaseRules<ShapeDefT<3>> {
  static constexpr std::array list = {
      // Set, and each semi-axis > 0 (shape_checks.cpp).
      FieldRule{.name = "axes", .field = "semi_axes"},
      // Normalised, the identity when left out (case_conversion.cpp).
      FieldRule{.name = "orientation", .elsewhere = true},
  };
};
// A particle and a wall: their vectors and extents are checked by hand
// (finite, z = 0 in 2D, a radius > 0 unless a shape sets it, an extent's
// high end above its low: case_validation.cpp), their materials are names,
// and a wall's directions are made unit (and orthonormal in 3D) from the
// case's, a 2D wall's perhaps from angle_deg (case_conversion.cpp).
template <int Dim>
struct CaseRules<ParticleDefT<Dim>> {
  static constexpr std::array list = {
      FieldRule{.name = "position"},
      // Left out for a shape, whose bounding radius the engine sets.
      FieldRule{.name = "radius"},
      FieldRule{.name = "material", .elsewhere = true},
      FieldRule{.name = "velocity"},
      // A scalar about z in 2D, angular_velocity_3d in 3D.
      FieldRule{.name = "angular_velocity", .elsewhere = true},
      // A superquadric in 2D, an ellipsoid in 3D.
      FieldRule{.name = "shape", .elsewhere = true},
  };
};
// The entries both dimensions' walls share; a 3D wall adds its second side.
inline constexpr std::array kWallRules = {
    FieldRule{.name = "name"},  // unique, checked with the references
    FieldRule{.name = "point"},
    FieldRule{.name = "direction", .elsewhere = true},
    FieldRule{.name = "h1"},
    FieldRule{.name = "h2"},
    FieldRule{.name = "material", .elsewhere = true},
    // With its angular velocity, as a stage's commands (case_conversion.cpp).
    FieldRule{.name = "motion", .elsewhere = true},
    // The state of a wall a stage removed; a case's walls stand.
    FieldRule{.name = "removed", .elsewhere = true},
};
template <>
struct CaseRules<WallDefT<2>> {
  static constexpr std::array list = kWallRules;
};
template <>
struct CaseRules<WallDefT<3>> {
  static constexpr std::array list = [] {
    std::array<FieldRule, kWallRules.size() + 4> rules{};
    std::size_t i = 0;
    for (const FieldRule& rule : kWallRules) rules[i++] = rule;
    rules[i++] = FieldRule{.name = "direction2", .elsewhere = true};
    rules[i++] = FieldRule{.name = "k1"};
    rules[i++] = FieldRule{.name = "k2"};
    // A wall of triangle faces, their extent replacing the rectangle's (case_conversion.cpp).
    rules[i++] = FieldRule{.name = "triangles", .field = "face", .elsewhere = true};
    return rules;
  }();
};
// A wall's motion: its velocity (a vector, checked by hand), the servo
// that replaces it when set, and an angular velocity that is a scalar
// about z in 2D and angular_velocity_3d in 3D (case_conversion.cpp).
template <int Dim>
struct CaseRules<WallMotionT<Dim>> {
  static constexpr std::array list = {
      FieldRule{.name = "velocity"},
      FieldRule{.name = "angular_velocity", .elsewhere = true},
      FieldRule{.name = "servo"},
  };
};
// Randall's (1989, 6.4.2) centripetal gravity field; its centre a vector
// checked by hand.
template <int Dim>
struct CaseRules<CentripetalGravityT<Dim>> {
  static constexpr std::array list = {
      FieldRule{.name = "centre"},
      FieldRule{.name = "acceleration", .check = Check::kNonNegative},
  };
};
// A periodic cell: the periodic axes are the case's x, y and z
// (case_conversion.cpp); its bounds vectors checked by hand.
template <int Dim>
struct CaseRules<PeriodicDefT<Dim>> {
  static constexpr std::array list = {
      FieldRule{.name = "axes", .elsewhere = true},
      FieldRule{.name = "min"},
      FieldRule{.name = "max"},
  };
};
template <>
struct CaseRules<StopConditions> {
  static constexpr std::array list = {
      // Walls and regions by name (case_conversion.cpp, case_validation.cpp).
      FieldRule{.name = "region_out_of_balance_below", .elsewhere = true},
      FieldRule{.name = "wall_stress_above", .elsewhere = true},
      FieldRule{.name = "wall_settlement_above", .elsewhere = true},
      // Needs a box control in force (case_validation.cpp).
      FieldRule{.name = "deviator_strain_above", .check = Check::kPositive},
      FieldRule{.name = "kinetic_energy_below", .check = Check::kPositive},
      FieldRule{.name = "out_of_balance_below", .check = Check::kPositive},
      FieldRule{.name = "kinetic_to_elastic_below", .check = Check::kPositive},
      FieldRule{.name = "unbalanced_force_below", .check = Check::kPositive},
      // Needs a servo in force (case_validation.cpp).
      FieldRule{.name = "servo_tolerance", .check = Check::kPositive},
      // At most the stage's cycles (case_validation.cpp).
      FieldRule{.name = "min_cycles"},
      FieldRule{.name = "check_interval", .zero_keeps_default = true},
  };
};
// Miyata et al. (2002) eq. 60: a sine of this amplitude and wavelength
// about the height.
template <>
struct CaseRules<TrimDef> {
  static constexpr std::array list = {
      FieldRule{.name = "height", .check = Check::kFinite},
      FieldRule{.name = "amplitude", .check = Check::kNonNegative},
      // > 0 for a rough surface, checked with the amplitude (case_validation.cpp); a smooth cut may leave it out.
      FieldRule{.name = "wavelength", .zero_keeps_default = true},
  };
};

// The plate loading analyses' settings (Miyata et al. 2002, 3.2-3.3):
// proto3 cannot tell an unset number from 0, so 0 keeps a default. The
// plates are walls by name and the analyses start with the stage that
// places the loading plate (case_conversion.cpp); the checks across
// fields (final above transition stress, stress_to above stress_from, at
// least two snapshots, a stress drop below 1) are in
// compression_output_checks.cpp.
template <>
struct CaseRules<analysis::ForceDistributionSettings> {
  static constexpr std::array list = {
      FieldRule{.name = "stress_from", .check = Check::kPositive},
      FieldRule{.name = "stress_to", .check = Check::kFinite},
      FieldRule{.name = "snapshots", .zero_keeps_default = true},
      FieldRule{.name = "bin_width", .check = Check::kNonNegative, .zero_keeps_default = true},
      FieldRule{.name = "tail_from", .check = Check::kNonNegative, .zero_keeps_default = true},
  };
};
template <>
struct CaseRules<analysis::CompressionSettings> {
  static constexpr std::array list = {
      FieldRule{.name = "loading_plate", .elsewhere = true},
      FieldRule{.name = "bottom_plate", .elsewhere = true},
      FieldRule{.name = "loading_stage", .elsewhere = true},
      FieldRule{.name = "transition_stress", .check = Check::kNonNegative, .zero_keeps_default = true},
      FieldRule{.name = "final_stress", .check = Check::kNonNegative, .zero_keeps_default = true},
      FieldRule{.name = "contacts_at_stress", .check = Check::kPositive},  // each
      // None when left out.
      FieldRule{.name = "force_distribution"},
      FieldRule{.name = "stress_drop_fraction", .check = Check::kNonNegative, .zero_keeps_default = true},
  };
};

namespace case_fields {

// The rules name the list's entries, each once: as many as the list has.
template <class T>
constexpr bool rules_match_list() {
  constexpr auto& list = SnapshotFields<T>::list;
  constexpr auto& rules = CaseRules<T>::list;
  if (rules.size() != std::tuple_size_v<std::remove_cvref_t<decltype(list)>>) return false;
  for (std::size_t i = 0; i < rules.size(); ++i) {
    if (field_index(list, rules[i].name) == rules.size()) return false;
    if (rules[i].elsewhere && rules[i].check != Check::kNone) return false;  // checked where it is converted
    for (std::size_t j = 0; j < i; ++j) {
      if (rules[j].name == rules[i].name) return false;
    }
  }
  return true;
}

#define DEM_CASE_RULES_MATCH(T) \
  static_assert(                \
      rules_match_list<T>(),    \
      #T ": give each entry of its field list one rule in CaseRules (case_rules.h), none both elsewhere and checked")
DEM_CASE_RULES_MATCH(MaterialDef);
DEM_CASE_RULES_MATCH(LinearLawDef);
DEM_CASE_RULES_MATCH(HertzDampingDef);
DEM_CASE_RULES_MATCH(RollingResistanceDef);
DEM_CASE_RULES_MATCH(ContactModelDef);
DEM_CASE_RULES_MATCH(DampingDef);
DEM_CASE_RULES_MATCH(ServoDef);
DEM_CASE_RULES_MATCH(BoxAxisDef);
DEM_CASE_RULES_MATCH(BoxControlT<2>);
DEM_CASE_RULES_MATCH(BoxControlT<3>);
DEM_CASE_RULES_MATCH(LatticeDefT<2>);
DEM_CASE_RULES_MATCH(LatticeDefT<3>);
DEM_CASE_RULES_MATCH(RandomPackingDefT<2>);
DEM_CASE_RULES_MATCH(RandomPackingDefT<3>);
DEM_CASE_RULES_MATCH(ShapeDefT<2>);
DEM_CASE_RULES_MATCH(ShapeDefT<3>);
DEM_CASE_RULES_MATCH(ParticleDefT<2>);
DEM_CASE_RULES_MATCH(ParticleDefT<3>);
DEM_CASE_RULES_MATCH(WallDefT<2>);
DEM_CASE_RULES_MATCH(WallDefT<3>);
DEM_CASE_RULES_MATCH(WallMotionT<2>);
DEM_CASE_RULES_MATCH(WallMotionT<3>);
DEM_CASE_RULES_MATCH(CentripetalGravityT<2>);
DEM_CASE_RULES_MATCH(CentripetalGravityT<3>);
DEM_CASE_RULES_MATCH(PeriodicDefT<2>);
DEM_CASE_RULES_MATCH(PeriodicDefT<3>);
DEM_CASE_RULES_MATCH(StopConditions);
DEM_CASE_RULES_MATCH(TrimDef);
DEM_CASE_RULES_MATCH(analysis::ForceDistributionSettings);
DEM_CASE_RULES_MATCH(analysis::CompressionSettings);
#undef DEM_CASE_RULES_MATCH

template <class T>
constexpr const FieldRule& rule_for(std::string_view name) {
  for (const FieldRule& rule : CaseRules<T>::list) {
    if (rule.name == name) return rule;
  }
  throw std::logic_error("no case rule for " + std::string(name));  // rules_match_list rules it out
}

}  // namespace case_fields
}  // namespace dem::io
