// Edits to a world between cycles: removing particles (trimming a sample),
// placing a wall (a loading plate on the sample's top), removing a wall (a
// hopper's orifice opened) and the box control of an element test. Both change
// which contacts act, so the force sums are evaluated again from the
// contacts' histories: between cycles the sums always belong to the
// contacts as they stand.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "box_control.h"
#include "contact_forces.h"
#include "dem/error.h"
#include "dem/world.h"
#include "ellipsoid.h"
#include "rolling_resistance.h"
#include "superquadric.h"
#include "walls.h"
#include "world_state.h"

namespace dem {

namespace {

template <int Dim>
double held_energy(const WorldState<Dim>& s) {
  const EnergyBudget e = measure_assembly(s).energy;
  return e.kinetic + e.strain;
}

// Keeps the rows for which keep(row) holds, in order.
template <int Dim, typename Keep>
void keep_rows(ContactRows<Dim>& rows, Keep keep) {
  std::vector<std::int32_t> from;
  std::vector<ContactKey> keys;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (!keep(r)) continue;
    from.push_back(static_cast<std::int32_t>(r));
    keys.push_back({rows.first[r], rows.second[r]});
  }
  gather_rows(rows, from, keys);
}

// Forgets the wall's contacts, then evaluates the force sums of the
// contacts left.
template <int Dim>
void drop_wall_contacts(WorldState<Dim>& s, WallId id) {
  ContactRows<Dim>& rows = s.contacts.walls;
  keep_rows(rows, [&](std::size_t r) { return rows.second[r] != id.value(); });
  plan_blocks(s.blocks, s.contacts, s.particles.size(), block_size(s));
  evaluate_contacts(s);
  if (s.rolling) add_rolling_moments(s);
}

}  // namespace

template <int Dim>
void BasicWorld<Dim>::remove_particles(std::span<const ParticleId> ids) {
  WorldState<Dim>& s = *state_;
  Particles<Dim>& p = s.particles;
  // Every id is checked before anything changes: a stale id is an error,
  // never half of a removal.
  for (ParticleId id : ids) {
    if (const auto missing = missing_particle(id)) throw DefinitionError("remove particles: " + *missing);
  }
  std::vector<bool> removed(p.slot.size(), false);
  for (ParticleId id : ids) removed[id.index()] = true;
  const auto kept = static_cast<std::size_t>(
      std::count_if(p.id.begin(), p.id.end(), [&](ParticleId id) { return !removed[id.index()]; }));
  if (kept == p.size()) return;
  if (kept == 0) throw DefinitionError("remove particles: cannot remove every particle");
  const double held_before = s.energy_budget ? held_energy(s) : 0.0;

  // The kept particles keep their ids (LIGGGHTS' atom ids, PFC's ball ids:
  // a client's id names the same particle for the whole run) and their
  // storage order; the removed ones' ids name nothing from now on.
  std::vector<Slot> kept_slots, renamed(p.size(), -1);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (removed[p.id[i].index()]) continue;
    renamed[i] = static_cast<Slot>(kept_slots.size());
    kept_slots.push_back(static_cast<Slot>(i));
  }
  p.for_each_slot_array([&](auto& values) { gather(values, kept_slots); });
  p.index_ids();

  // Contacts between kept particles keep their history; a pair row's first
  // particle still has the lower id (ids did not change).
  rename_slots(s.contacts.pairs, renamed, true);
  rename_slots(s.contacts.walls, renamed, false);
  plan_blocks(s.blocks, s.contacts, p.size(), block_size(s));
  evaluate_contacts(s);
  if (s.rolling) add_rolling_moments(s);
  invalidate(s, Cache::kAll);  // the particles moved slots, and the table lost rows
  if (s.energy_budget) s.energy.removed += held_before - held_energy(s);
}

template <int Dim>
void BasicWorld<Dim>::place_wall(WallId id, const Vec<Dim>& point) {
  if (const auto missing = missing_wall(id)) throw DefinitionError("place wall: " + *missing);
  if (!point.allFinite()) throw DefinitionError("place wall: the point must be finite");
  WorldState<Dim>& s = *state_;
  const std::size_t w = id.index();
  translate(s.walls.def[w], point - s.walls.def[w].point);  // faces and all
  s.walls.initial_point[w] = point;
  s.walls.last_velocity[w] = Vec<Dim>::Zero();
  s.walls.last_angular_velocity[w] = Space<Dim>::zero_spin();
  // Its contacts start afresh where it now stands.
  drop_wall_contacts(s, id);
  invalidate(s, Cache::kAll);  // the wall jumped, not moved: the travel does not call the rebuild
}

template <int Dim>
void BasicWorld<Dim>::remove_wall(WallId id) {
  if (const auto missing = missing_wall(id)) throw DefinitionError("remove wall: " + *missing);
  WorldState<Dim>& s = *state_;
  const std::size_t w = id.index();
  if (s.walls.box) {
    for (const BoxAxisDef& a : s.walls.box->axes) {
      if (a.lower == id || a.upper == id) {
        throw DefinitionError("remove wall: wall " + to_string(id) + " (\"" + s.walls.def[w].name +
                              "\") bounds the controlled box; release the box control first");
      }
    }
  }
  if (s.walls.def[w].removed) return;
  const double held_before = s.energy_budget ? held_energy(s) : 0.0;
  s.walls.def[w].removed = true;
  s.walls.last_velocity[w] = Vec<Dim>::Zero();
  s.walls.last_angular_velocity[w] = Space<Dim>::zero_spin();
  drop_wall_contacts(s, id);
  // The strain energy its contacts held is gone with them.
  if (s.energy_budget) s.energy.removed += held_before - held_energy(s);
}

template <int Dim>
void BasicWorld<Dim>::set_box_control(const std::optional<BoxControlT<Dim>>& control) {
  WorldState<Dim>& s = *state_;
  if (!control) {
    s.walls.box.reset();
    return;
  }
  check_box_control(*control, s.walls.def);
  check_box_continuum(*control, s.periodic_def);
  BoxControlT<Dim> box = *control;
  if (!(box.reference_extent.array() > 0.0).all()) box.reference_extent = box_extent(s.walls, box);
  s.walls.box = box;
}

template <int Dim>
const std::optional<BoxControlT<Dim>>& BasicWorld<Dim>::box_control() const {
  return state_->walls.box;
}

template <int Dim>
BoxMeasureT<Dim> BasicWorld<Dim>::box_measure() const {
  const Walls<Dim>& walls = state_->walls;
  if (!walls.box) throw DefinitionError("box measure: no box control is set");
  return measure_box(walls, *walls.box);
}

template <int Dim>
double BasicWorld<Dim>::furthest_reach(const Vec<Dim>& u) const {
  const WorldState<Dim>& s = *state_;
  const Particles<Dim>& p = s.particles;
  double reach = -std::numeric_limits<double>::infinity();
  for (Slot i = 0; i < static_cast<Slot>(p.size()); ++i) {
    double extent = p.radius[i];
    if constexpr (Dim == 3) {
      // sqrt(u^T M^-1 u): the support of an ellipsoid along u (eq. 54).
      if (s.shape == ShapeKind::kEllipsoid)
        extent = std::sqrt(u.dot(ellipsoid_frame(p.shape[i].axes, p.rotation[i]).reach * u));
    } else {
      if (s.shape == ShapeKind::kSuperquadric) {
        const ShapeDefT<2>& shape = p.shape[i];
        const PlacedSuperquadric body{{shape.a, shape.b, shape.n}, p.position[i], p.rotation[i]};
        extent = superquadric_line_contact(body, p.position[i], u).overlap;
      }
    }
    reach = std::max(reach, p.position[i].dot(u) + extent);
  }
  return reach;
}

template <int Dim>
double BasicWorld<Dim>::wall_settlement(WallId id) const {
  assert(!missing_wall(id));
  const Walls<Dim>& w = state_->walls;
  return (w.def[id.index()].point - w.initial_point[id.index()]).dot(wall_normal(w.def[id.index()]));
}

template void BasicWorld<2>::remove_particles(std::span<const ParticleId>);
template void BasicWorld<3>::remove_particles(std::span<const ParticleId>);
template void BasicWorld<2>::remove_wall(WallId);
template void BasicWorld<3>::remove_wall(WallId);
template void BasicWorld<2>::set_box_control(const std::optional<BoxControlT<2>>&);
template void BasicWorld<3>::set_box_control(const std::optional<BoxControlT<3>>&);
template const std::optional<BoxControlT<2>>& BasicWorld<2>::box_control() const;
template const std::optional<BoxControlT<3>>& BasicWorld<3>::box_control() const;
template BoxMeasureT<2> BasicWorld<2>::box_measure() const;
template BoxMeasureT<3> BasicWorld<3>::box_measure() const;
template void BasicWorld<2>::place_wall(WallId, const Vec2&);
template void BasicWorld<3>::place_wall(WallId, const Vec3&);
template double BasicWorld<2>::furthest_reach(const Vec2&) const;
template double BasicWorld<3>::furthest_reach(const Vec3&) const;
template double BasicWorld<2>::wall_settlement(WallId) const;
template double BasicWorld<3>::wall_settlement(WallId) const;

}  // namespace dem
