// The field lists of the structs a snapshot holds besides the contact table
// (whose list is for_each_contact_field, dem/snapshot.h): every member of
// the definition structs (dem/definitions.h), the energy budget and the
// wall and world state, by name. The conversion to Protocol Buffers walks
// these lists (io/src/snapshot_conversion_fields.h), finding each field of
// idl/dem/snapshot.proto by the name given here. A new member fails the
// build below until it has its line; a line whose name the schema lacks
// fails the io tests by name (SnapshotConversion.EveryListedField...) and
// the conversion itself, loudly. Adding a member is a line here and a
// field of that name in idl/dem/snapshot.proto.
#pragma once

#include <tuple>

#include "dem/definitions.h"
#include "dem/field_list.h"
#include "dem/snapshot.h"

namespace dem {

// SnapshotFields<T>::list: a tuple of Field (dem/field_list.h), one per
// member of T.
template <class T>
struct SnapshotFields;

template <>
struct SnapshotFields<MaterialDef> {
  static constexpr auto list = std::make_tuple(
      DEM_FIELD(MaterialDef, name), DEM_FIELD(MaterialDef, density), DEM_FIELD(MaterialDef, friction),
      DEM_FIELD(MaterialDef, cohesion), DEM_FIELD(MaterialDef, youngs_modulus), DEM_FIELD(MaterialDef, poisson_ratio));
};
template <>
struct SnapshotFields<LinearLawDef> {
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(LinearLawDef, normal_stiffness), DEM_FIELD(LinearLawDef, shear_stiffness));
};
template <>
struct SnapshotFields<HertzDampingDef> {
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(HertzDampingDef, damping_ratio), DEM_FIELD(HertzDampingDef, restitution),
                      DEM_FIELD(HertzDampingDef, tangential));
};
template <>
struct SnapshotFields<RollingResistanceDef> {
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(RollingResistanceDef, friction), DEM_FIELD(RollingResistanceDef, damping_ratio));
};
template <>
struct SnapshotFields<ContactModelDef> {
  static constexpr auto list = std::make_tuple(
      DEM_FIELD(ContactModelDef, material_a), DEM_FIELD(ContactModelDef, material_b),
      DEM_FIELD(ContactModelDef, linear), DEM_FIELD(ContactModelDef, friction), DEM_FIELD(ContactModelDef, cohesion),
      DEM_FIELD(ContactModelDef, law), DEM_FIELD(ContactModelDef, restitution), DEM_FIELD(ContactModelDef, hertz),
      DEM_FIELD(ContactModelDef, rolling));
};
template <>
struct SnapshotFields<DampingDef> {
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(DampingDef, contact_beta), DEM_FIELD(DampingDef, global_alpha),
                      DEM_FIELD(DampingDef, global_alpha_rotation), DEM_FIELD(DampingDef, local_alpha),
                      DEM_FIELD(DampingDef, local_alpha_rotation));
};
template <>
struct SnapshotFields<EnergyBudget> {
  static constexpr auto list = std::make_tuple(
      DEM_FIELD(EnergyBudget, initial_kinetic), DEM_FIELD(EnergyBudget, gravity_work),
      DEM_FIELD(EnergyBudget, wall_work), DEM_FIELD(EnergyBudget, kinetic), DEM_FIELD(EnergyBudget, strain),
      DEM_FIELD(EnergyBudget, contact_damping), DEM_FIELD(EnergyBudget, friction),
      DEM_FIELD(EnergyBudget, global_damping), DEM_FIELD(EnergyBudget, local_damping), DEM_FIELD(EnergyBudget, removed),
      DEM_FIELD(EnergyBudget, continuum_work));
};
template <>
struct SnapshotFields<ServoDef> {
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(ServoDef, target_force), DEM_FIELD(ServoDef, gain), DEM_FIELD(ServoDef, max_speed));
};
template <>
struct SnapshotFields<ShapeDefT<2>> {
  using Shape = ShapeDefT<2>;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Shape, a), DEM_FIELD(Shape, b), DEM_FIELD(Shape, n), DEM_FIELD(Shape, angle));
};
template <>
struct SnapshotFields<ShapeDefT<3>> {
  using Shape = ShapeDefT<3>;
  static constexpr auto list = std::make_tuple(DEM_FIELD(Shape, axes), DEM_FIELD(Shape, orientation));
};
template <>
struct SnapshotFields<WallDefT<2>> {
  using Wall = WallDefT<2>;
  static constexpr auto list = std::make_tuple(
      DEM_FIELD(Wall, name), DEM_FIELD(Wall, point), DEM_FIELD(Wall, direction), DEM_FIELD(Wall, h1),
      DEM_FIELD(Wall, h2), DEM_FIELD(Wall, material), DEM_FIELD(Wall, motion), DEM_FIELD(Wall, removed));
};
template <>
struct SnapshotFields<WallDefT<3>> {
  using Wall = WallDefT<3>;
  static constexpr auto list = std::make_tuple(
      DEM_FIELD(Wall, name), DEM_FIELD(Wall, point), DEM_FIELD(Wall, direction), DEM_FIELD(Wall, h1),
      DEM_FIELD(Wall, h2), DEM_FIELD(Wall, direction2), DEM_FIELD(Wall, k1), DEM_FIELD(Wall, k2),
      DEM_FIELD(Wall, material), DEM_FIELD(Wall, motion), DEM_FIELD(Wall, triangles), DEM_FIELD(Wall, removed));
};
template <>
struct SnapshotFields<BoxAxisDef> {
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(BoxAxisDef, lower), DEM_FIELD(BoxAxisDef, upper), DEM_FIELD(BoxAxisDef, control),
                      DEM_FIELD(BoxAxisDef, strain_rate), DEM_FIELD(BoxAxisDef, stress));
};
template <int Dim>
struct SnapshotFields<ParticleDefT<Dim>> {
  using Particle = ParticleDefT<Dim>;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Particle, position), DEM_FIELD(Particle, radius), DEM_FIELD(Particle, material),
                      DEM_FIELD(Particle, velocity), DEM_FIELD(Particle, angular_velocity), DEM_FIELD(Particle, shape));
};
template <int Dim>
struct SnapshotFields<WallMotionT<Dim>> {
  using Motion = WallMotionT<Dim>;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Motion, velocity), DEM_FIELD(Motion, angular_velocity), DEM_FIELD(Motion, servo));
};
template <int Dim>
struct SnapshotFields<PeriodicDefT<Dim>> {
  using Periodic = PeriodicDefT<Dim>;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Periodic, axes), DEM_FIELD(Periodic, min), DEM_FIELD(Periodic, max));
};
template <int Dim>
struct SnapshotFields<BoxControlT<Dim>> {
  using Box = BoxControlT<Dim>;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Box, axes), DEM_FIELD(Box, path), DEM_FIELD(Box, path_value), DEM_FIELD(Box, gain),
                      DEM_FIELD(Box, max_speed), DEM_FIELD(Box, reference_extent), DEM_FIELD(Box, continuum));
};
template <int Dim>
struct SnapshotFields<ContinuumFieldT<Dim>> {
  using Continuum = ContinuumFieldT<Dim>;
  static constexpr auto list = std::make_tuple(DEM_FIELD(Continuum, rate), DEM_FIELD(Continuum, centre));
};
template <int Dim>
struct SnapshotFields<CentripetalGravityT<Dim>> {
  using Centripetal = CentripetalGravityT<Dim>;
  static constexpr auto list = std::make_tuple(DEM_FIELD(Centripetal, centre), DEM_FIELD(Centripetal, acceleration));
};
template <int Dim>
struct SnapshotFields<WorldDefT<Dim>> {
  using Def = WorldDefT<Dim>;
  static constexpr auto list = std::make_tuple(
      DEM_FIELD(Def, materials), DEM_FIELD(Def, contact_models), DEM_FIELD(Def, particles), DEM_FIELD(Def, walls),
      DEM_FIELD(Def, periodic), DEM_FIELD(Def, box_control), DEM_FIELD(Def, damping), DEM_FIELD(Def, gravity),
      DEM_FIELD(Def, centripetal_gravity), DEM_FIELD(Def, planar_particle), DEM_FIELD(Def, time_step_fraction),
      DEM_FIELD(Def, fixed_time_step), DEM_FIELD(Def, contact_tolerance), DEM_FIELD(Def, threads),
      DEM_FIELD(Def, energy_budget));
};
template <int Dim>
struct SnapshotFields<WallSnapshotT<Dim>> {
  using Wall = WallSnapshotT<Dim>;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Wall, initial_point), DEM_FIELD(Wall, last_velocity),
                      DEM_FIELD(Wall, last_angular_velocity), DEM_FIELD(Wall, force), DEM_FIELD(Wall, moment),
                      DEM_FIELD(Wall, normal_force), DEM_FIELD(Wall, contacts), DEM_FIELD(Wall, normal_force_arm));
};
template <int Dim>
struct SnapshotFields<WorldSnapshotT<Dim>> {
  using State = WorldSnapshotT<Dim>;
  static constexpr auto list = std::make_tuple(
      DEM_FIELD(State, def), DEM_FIELD(State, rotation), DEM_FIELD(State, force), DEM_FIELD(State, moment),
      DEM_FIELD(State, walls), DEM_FIELD(State, contacts), DEM_FIELD(State, reference_positions),
      DEM_FIELD(State, particle_travel), DEM_FIELD(State, wall_travel), DEM_FIELD(State, contacts_stale),
      DEM_FIELD(State, particle_order), DEM_FIELD(State, particle_ids), DEM_FIELD(State, particle_id_count),
      DEM_FIELD(State, sorted_cycle), DEM_FIELD(State, energy), DEM_FIELD(State, tangential_work),
      DEM_FIELD(State, cycle), DEM_FIELD(State, time), DEM_FIELD(State, time_step),
      DEM_FIELD(State, critical_time_step), DEM_FIELD(State, continuum));
};

// A struct with a list above.
template <class T>
concept HasSnapshotFields = requires {
  SnapshotFields<T>::list;
};

namespace detail {
template <class T>
constexpr bool snapshot_fields_complete() {
  return lists_every_member<T>(SnapshotFields<T>::list);
}
}  // namespace detail

// Every member of every struct is listed once: a new member - a bool that
// fits in padding too - fails the build here until it has its line above
// (and the snapshot carries it: a field of its name in idl/dem/snapshot.proto).
#define DEM_SNAPSHOT_FIELDS_COMPLETE(...)                        \
  static_assert(detail::snapshot_fields_complete<__VA_ARGS__>(), \
                #__VA_ARGS__ " changed: give the new member its line in SnapshotFields (dem/snapshot_fields.h)")
DEM_SNAPSHOT_FIELDS_COMPLETE(MaterialDef);
DEM_SNAPSHOT_FIELDS_COMPLETE(LinearLawDef);
DEM_SNAPSHOT_FIELDS_COMPLETE(HertzDampingDef);
DEM_SNAPSHOT_FIELDS_COMPLETE(RollingResistanceDef);
DEM_SNAPSHOT_FIELDS_COMPLETE(ContactModelDef);
DEM_SNAPSHOT_FIELDS_COMPLETE(DampingDef);
DEM_SNAPSHOT_FIELDS_COMPLETE(EnergyBudget);
DEM_SNAPSHOT_FIELDS_COMPLETE(ServoDef);
DEM_SNAPSHOT_FIELDS_COMPLETE(BoxAxisDef);
DEM_SNAPSHOT_FIELDS_COMPLETE(ShapeDefT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(ShapeDefT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WallDefT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WallDefT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(ParticleDefT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(ParticleDefT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WallMotionT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WallMotionT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(PeriodicDefT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(PeriodicDefT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(BoxControlT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(BoxControlT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(ContinuumFieldT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(ContinuumFieldT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(CentripetalGravityT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(CentripetalGravityT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WorldDefT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WorldDefT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WallSnapshotT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WallSnapshotT<3>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WorldSnapshotT<2>);
DEM_SNAPSHOT_FIELDS_COMPLETE(WorldSnapshotT<3>);
#undef DEM_SNAPSHOT_FIELDS_COMPLETE

}  // namespace dem
