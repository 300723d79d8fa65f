// The public face of the engine: build a World from a WorldDef, cycle it,
// steer its walls, and read what it measures. No files, no networking.
// Written once over the dimension: World is the 2D world, World3 the 3D one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dem/definitions.h"
#include "dem/measures.h"
#include "dem/profile.h"
#include "dem/region.h"
#include "dem/snapshot.h"

namespace dem {

template <int Dim>
struct WorldState;  // engine/src: particles, walls, contacts

// One particle quantity read by ParticleId. The engine stores particles in
// its own order (close in space, close in memory), so this looks each id up
// (slots: indexed by id); iterating goes through the particles' ids in
// ascending order (ids).
template <typename T>
class ById {
 public:
  ById(std::span<const T> values, std::span<const std::int32_t> slots, std::span<const ParticleId> ids)
      : values_(values), slots_(slots), ids_(ids) {}
  // Only for ids the world holds (BasicWorld::has_particle).
  const T& operator[](ParticleId id) const { return values_[static_cast<std::size_t>(slots_[id.index()])]; }
  std::size_t size() const { return ids_.size(); }
  bool empty() const { return ids_.empty(); }

  class iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = const T*;
    using reference = const T&;
    iterator(const ById* view, std::span<const ParticleId>::iterator at) : view_(view), at_(at) {}
    const T& operator*() const { return (*view_)[*at_]; }
    iterator& operator++() {
      ++at_;
      return *this;
    }
    iterator operator++(int) {
      iterator old = *this;
      ++at_;
      return old;
    }
    bool operator==(const iterator& o) const { return at_ == o.at_; }

   private:
    const ById* view_;
    std::span<const ParticleId>::iterator at_;
  };
  iterator begin() const { return {this, ids_.begin()}; }
  iterator end() const { return {this, ids_.end()}; }

 private:
  std::span<const T> values_;
  std::span<const std::int32_t> slots_;
  std::span<const ParticleId> ids_;
};

// Read-only views of the particles' state, by ParticleId. Valid until the
// next call that changes the World.
template <int Dim>
struct ParticleViewT {
  ById<Vec<Dim>> position;
  ById<Vec<Dim>> velocity;  // at the last half step, m/s
  ById<Spin<Dim>> angular_velocity;
  ById<Orientation<Dim>> rotation;  // 2D: accumulated angle, rad; 3D: unit quaternion
  ById<double> radius;
  ById<double> mass;
};

template <int Dim>
class BasicWorld {
 public:
  using Def = WorldDefT<Dim>;
  using WallDefinition = WallDefT<Dim>;
  using Motion = WallMotionT<Dim>;
  using Measure = WallMeasureT<Dim>;
  using Record = ContactRecordT<Dim>;
  using Snapshot = WorldSnapshotT<Dim>;

  // Throws DefinitionError naming the offending item if the definition is invalid.
  explicit BasicWorld(const Def& def);
  // Restores a saved state; throws DefinitionError if the snapshot is
  // inconsistent (ids out of range, sizes that do not match).
  explicit BasicWorld(const Snapshot& snapshot);
  ~BasicWorld();
  BasicWorld(BasicWorld&&) noexcept;
  BasicWorld& operator=(BasicWorld&&) noexcept;
  BasicWorld(const BasicWorld&) = delete;
  BasicWorld& operator=(const BasicWorld&) = delete;

  // Runs n calculation cycles (Cundall & Strack, The calculation cycle).
  // Between cycles the contact forces, wall forces and force sums belong to
  // the particles' current positions.
  void cycle(std::uint64_t n = 1);

  std::uint64_t cycle_count() const;
  double time() const;       // s
  double time_step() const;  // s
  // s, the largest step central differences keep stable for one contact:
  // 2 sqrt(m/k) undamped (Rayleigh's for Hertz laws), less with the
  // contact dashpots and local damping (time_step.cpp).
  double critical_time_step() const;
  // The same were the damping `damping` (a stage's, a parameter's).
  double critical_time_step_with(const DampingDef& damping) const;
  // s, 2 sqrt(m/k) (Rayleigh's step for Hertz laws) without the damping:
  // what a time step fraction is a fraction of; the fraction covers the
  // damping and a particle's several contacts, and validation refuses one
  // whose step is above the critical step.
  double undamped_critical_time_step() const;

  // Particle ids are given once, in definition order (ParticleId{k} is
  // WorldDef::particles[k]), and stay with their particle for the whole
  // run: removing particles leaves the others' ids as they were, and a
  // removed particle's id names nothing from then on.
  int particle_count() const;  // particles in the world now
  int wall_count() const;
  // The ids of the particles in the world, ascending; after a removal
  // they have gaps.
  std::span<const ParticleId> particle_ids() const;
  // One past the highest id ever given (WorldDef::particles' size).
  int particle_id_count() const;
  bool has_particle(ParticleId id) const;
  // Why an id names no particle ("no particle 12", "particle 12 was
  // removed"), or nothing if it names one: the message a command that
  // names a stale id fails with.
  std::optional<std::string> missing_particle(ParticleId id) const;
  ParticleViewT<Dim> particles() const;

  // Walls, by dense id (definition order; ids out of range are a
  // programmer error); find_wall returns kInvalidId for an unknown name.
  WallId find_wall(std::string_view name) const;
  // Why an id names no wall ("no wall 7"), or nothing if it names one: the
  // message an edit that names a wrong id fails with. A removed wall keeps
  // its id (remove_wall), so its id still names it.
  std::optional<std::string> missing_wall(WallId id) const;
  const WallDefinition& wall(WallId id) const;  // current geometry and motion
  void set_wall_motion(WallId id, const Motion& motion);
  // Length (2D, times the out-of-plane depth) or area (3D) that turns a
  // wall's normal force into a normal stress.
  double wall_area(WallId id) const;
  // A wall's normal stress: the compressive normal force of the last force
  // pass over wall_area (0 for a wall of no extent). Telemetry, the tables,
  // the analyses and the stop conditions all take a plate's stress here.
  double wall_stress(WallId id) const;
  // Moves a wall's reference point there at once (placing a loading plate
  // on a sample); its contacts start afresh and its displacement
  // (settlement) counts from here.
  void place_wall(WallId id, const Vec<Dim>& point);
  // The furthest any particle's surface reaches along the unit vector u:
  // the largest x.u plus the body's own extent along u (its radius, or the
  // support of an ellipse or superquadric as it is turned now; a bounding
  // radius would leave an elongated body's plate a tenth of a metre short).
  double furthest_reach(const Vec<Dim>& u) const;
  // How far a wall has moved along its normal, towards the particles, since
  // it was built or placed: a loading plate's settlement.
  double wall_settlement(WallId id) const;
  // Takes a wall out of the world (opening a hopper's orifice, Randall
  // 1989, 6.2): it keeps its id and definition but touches nothing from
  // now on, and its contacts end at once.
  void remove_wall(WallId id);

  // Element-test control of a box of walls (BoxControlT): set, replaced or,
  // with std::nullopt, released (the walls then keep the motion they were
  // given last). Throws DefinitionError naming the field when the control
  // makes no sense for the walls. Strains count from the box as it stands
  // when a control is set, unless its reference_extent is given.
  void set_box_control(const std::optional<BoxControlT<Dim>>& control);
  const std::optional<BoxControlT<Dim>>& box_control() const;
  // The box as the last force pass left it; requires a box control.
  BoxMeasureT<Dim> box_measure() const;

  // Removes particles (trimming a sample's surface). The others keep
  // their ids; contacts between them keep their history. The energy they
  // held is booked as removed. Throws DefinitionError naming the first id
  // that names no particle (missing_particle), before removing any.
  void remove_particles(std::span<const ParticleId> ids);

  std::vector<Measure> wall_measures() const;
  AssemblyMeasures assembly_measures() const;
  // Cundall & Strack's out-of-balance ratio Delta F / F (Table 1, note 2)
  // over the particles whose centres lie in the region: the largest
  // resultant on one of them (body forces included) over the largest force
  // of their contacts; 0 without contacts. Randall's quasi-equilibrium
  // (6.4.2-6.5.2) is judged in his measurement circles, away from the
  // boundary.
  double out_of_balance(const RegionT<Dim>& region) const;
  std::vector<Record> contacts() const;  // touching contacts only
  // The touching contacts of one wall, as contacts() reports them: a pass
  // over that wall's rows alone.
  std::vector<Record> wall_contacts(WallId wall) const;
  // The touching contact between two particles, if any (none when either
  // id names no particle: see missing_particle).
  std::optional<Record> contact_between(ParticleId a, ParticleId b) const;

  // 2D: the out-of-plane depth that turns forces per unit depth into
  // stresses (1 for discs; the mean diameter for spheres in the plane,
  // Randall 1989, 4.4). 3D: 1.
  double depth() const;
  const PeriodicDefT<Dim>& periodic() const;

  DampingDef damping() const;
  void set_damping(const DampingDef& damping);
  Vec<Dim> gravity() const;
  void set_gravity(const Vec<Dim>& gravity);
  // Randall's centripetal gravity field (6.4.2), or none.
  const std::optional<CentripetalGravityT<Dim>>& centripetal_gravity() const;
  // The body forces from now on: gravity and the centripetal field (none
  // when the optional is empty). Throws DefinitionError for a field that
  // is not finite or pulls outwards, changing nothing.
  void set_body_force(const BodyForceT<Dim>& body_force);

  // Time spent in each phase of the cycle since the world was built.
  const StepProfile& profile() const;

  int threads() const;
  void set_threads(int threads);  // 0 = all cores; results do not depend on it

  // Whether the world keeps the energy budget (WorldDefT::energy_budget);
  // without it AssemblyMeasures::energy holds only the kinetic energy.
  bool energy_budget() const;

  // Everything needed to continue this run exactly (see snapshot.h).
  Snapshot snapshot() const;

  // The time step as a fraction (0, 1] of the undamped critical step; recomputes the step.
  void set_time_step_fraction(double fraction);
  // A fixed time step, s (> 0).
  void set_fixed_time_step(double seconds);
  double fixed_time_step() const;  // s; 0 when the step is a fraction of the critical step
  // Friction coefficient tan(phi) of a material; recomputes the pair table
  // (contact models that set their own friction keep it).
  void set_friction(MaterialId material, double friction);
  const std::vector<MaterialDef>& materials() const;

  // 64-bit hash of the complete dynamic state (positions, velocities,
  // rotations, contact history, walls), bit for bit.
  std::uint64_t state_hash() const;

 private:
  std::unique_ptr<WorldState<Dim>> state_;
};

using World = BasicWorld<2>;
using World3 = BasicWorld<3>;
using ParticleView = ParticleViewT<2>;

extern template class BasicWorld<2>;
extern template class BasicWorld<3>;

}  // namespace dem
