// Edits to a world between cycles: removing particles (trimming a sample)
// and placing a wall (a loading plate on the sample's top).
#include <algorithm>
#include <string>

#include "dem/error.h"
#include "dem/world.h"
#include "walls.h"
#include "world_state.h"

namespace dem {

namespace {

// Keeps the entries of v whose flag is set, in order.
template <typename T>
void compact(std::vector<T>& v, const std::vector<bool>& keep) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (keep[i]) v[out++] = std::move(v[i]);
  }
  v.resize(out);
}

template <int Dim>
double held_energy(const WorldState<Dim>& s) {
  const EnergyBudget e = measure_assembly(s).energy;
  return e.kinetic + e.strain;
}

}  // namespace

template <int Dim>
void BasicWorld<Dim>::remove_particles(std::span<const ParticleId> ids) {
  WorldState<Dim>& s = *state_;
  const auto n = static_cast<ParticleId>(s.particles.size());
  std::vector<bool> keep(static_cast<std::size_t>(n), true);
  for (ParticleId id : ids) {
    if (id < 0 || id >= n) throw DefinitionError("remove particles: no particle " + std::to_string(id));
    keep[id] = false;
  }
  if (std::all_of(keep.begin(), keep.end(), [](bool k) { return k; })) return;
  const double held_before = held_energy(s);

  // New dense ids, in the old order.
  std::vector<ParticleId> renumbered(static_cast<std::size_t>(n), kInvalidId);
  ParticleId next = 0;
  for (ParticleId i = 0; i < n; ++i) {
    if (keep[i]) renumbered[i] = next++;
  }
  Particles<Dim>& p = s.particles;
  compact(p.position, keep);
  compact(p.velocity, keep);
  compact(p.angular_velocity, keep);
  compact(p.rotation, keep);
  compact(p.force, keep);
  compact(p.moment, keep);
  compact(p.previous_force, keep);
  compact(p.radius, keep);
  compact(p.mass, keep);
  compact(p.inertia, keep);
  compact(p.material, keep);
  compact(p.shape, keep);
  compact(p.principal_inertia, keep);
  compact(s.reference_positions, keep);

  // Contacts between kept particles keep their history; the renumbering
  // keeps the order, so the tables stay sorted.
  ContactTable<Dim>& t = s.contacts;
  std::vector<bool> keep_pair(t.pairs.size()), keep_wall(t.walls.size());
  for (std::size_t k = 0; k < t.pairs.size(); ++k) keep_pair[k] = keep[t.pairs[k].first] && keep[t.pairs[k].second];
  for (std::size_t k = 0; k < t.walls.size(); ++k) keep_wall[k] = keep[t.walls[k].particle];
  compact(t.pairs, keep_pair);
  compact(t.pair_forces, keep_pair);
  compact(t.walls, keep_wall);
  compact(t.wall_forces, keep_wall);
  for (PairContact<Dim>& c : t.pairs) {
    c.first = renumbered[c.first];
    c.second = renumbered[c.second];
  }
  for (WallContact<Dim>& c : t.walls) c.particle = renumbered[c.particle];
  reindex_contacts(t, next);
  s.contacts_stale = true;
  s.energy.removed += held_before - held_energy(s);
}

template <int Dim>
void BasicWorld<Dim>::place_wall(WallId id, const Vec<Dim>& point) {
  if (id < 0 || id >= wall_count()) throw DefinitionError("place wall: no wall " + std::to_string(id));
  if (!point.allFinite()) throw DefinitionError("place wall: the point must be finite");
  WorldState<Dim>& s = *state_;
  translate(s.walls.def[id], point - s.walls.def[id].point);  // faces and all
  s.walls.initial_point[id] = point;
  s.walls.last_velocity[id] = Vec<Dim>::Zero();
  s.walls.last_angular_velocity[id] = Space<Dim>::zero_spin();
  // Its contacts start afresh where it now stands.
  ContactTable<Dim>& t = s.contacts;
  std::vector<bool> keep(t.walls.size());
  for (std::size_t k = 0; k < t.walls.size(); ++k) keep[k] = t.walls[k].wall != id;
  compact(t.walls, keep);
  compact(t.wall_forces, keep);
  reindex_contacts(t, particle_count());
  s.contacts_stale = true;
}

template <int Dim>
double BasicWorld<Dim>::wall_settlement(WallId id) const {
  const Walls<Dim>& w = state_->walls;
  return (w.def[id].point - w.initial_point[id]).dot(wall_normal(w.def[id]));
}

template void BasicWorld<2>::remove_particles(std::span<const ParticleId>);
template void BasicWorld<3>::remove_particles(std::span<const ParticleId>);
template void BasicWorld<2>::place_wall(WallId, const Vec2&);
template void BasicWorld<3>::place_wall(WallId, const Vec3&);
template double BasicWorld<2>::wall_settlement(WallId) const;
template double BasicWorld<3>::wall_settlement(WallId) const;

}  // namespace dem
