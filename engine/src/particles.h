// Particle state as structure-of-arrays. Arrays are indexed by a storage
// slot, not by the particle's id: the engine keeps particles that are close
// in space close in memory (particle_order.h), so a slot changes when the
// particles are re-sorted while an id stays what the user gave. `id` and
// `slot` translate. Hot data (what every contact reads, what the law of
// motion writes) is apart from cold data (shapes, ids). Written once over
// the dimension. The arrays are Columns (large_pages.h): the long ones lie
// on large pages. Each has its line in the field list (particle_fields.h),
// which says whether it is saved, hashed and copied for the force pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/definitions.h"
#include "dem/ids.h"
#include "dem/math.h"
#include "large_pages.h"
#include "particle_fields.h"

namespace dem {

// The particles' shape, one for the whole world so the contact passes
// choose their geometry once, like the law.
enum class ShapeKind { kRound, kSuperquadric, kEllipsoid };

using Slot = std::int32_t;  // index into the particle arrays

template <int Dim>
struct Particles {
  // Read by every contact of the force pass.
  Column<Vec<Dim>> position;           // x_i at cycle N
  Column<Vec<Dim>> velocity;           // x_dot_i at N - 1/2 (time-centred, eq. 22)
  Column<Spin<Dim>> angular_velocity;  // at N - 1/2 (eq. 23)
  Column<double> radius;               // bounding radius for shaped particles
  Column<double> mass;
  // MaterialId values as plain indices: the force pass indexes the pair
  // table with them for every contact (ids.h: the types guard the API).
  Column<std::int32_t> material;
  // Written by the force pass (eqs. 20-21): the sums of the contact forces and moments.
  Column<Vec<Dim>> force;
  Column<Spin<Dim>> moment;
  // Read and written by the law of motion only.
  Column<double> inertia;               // about the centre; an ellipsoid's smallest principal moment
  Column<Orientation<Dim>> rotation;    // accumulated angle (2D) or unit quaternion (3D) (eq. 23a)
  Column<double> previous_force;        // |sum F| of the last cycle (Randall 4.38)
  Column<Vec<Dim>> reference_position;  // where the particle was at the last contact-table rebuild
  // Cold.
  Column<ShapeDefT<Dim>> shape;    // superquadric or ellipsoid worlds only (empty otherwise)
  Column<Vec3> principal_inertia;  // ellipsoid worlds only: about the body's own axes
  std::vector<ParticleId> id;      // the particle in each slot

  // The slot of each particle id (indexed by id, not by slot); -1 for an
  // id whose particle was removed. Ids are given once, in definition order,
  // and never reused or renamed (remove_particles leaves holes), so its
  // size is the number of ids ever given.
  std::vector<Slot> slot;
  // The particles' ids in ascending order: what the API iterates.
  std::vector<ParticleId> ids;

  std::size_t size() const { return position.size(); }

  // Every per-slot array, so that reordering and removing particles touch
  // them all: visit(array) for each (empty optional arrays included), in
  // the order of the field list (particle_fields.h).
  template <typename Visit>
  void for_each_slot_array(Visit&& visit) {
    for_each_particle_field<Dim>([&](const ParticleFieldInfo&, auto column, auto, auto) { visit(column(*this)); });
  }

  // Rebuilds `slot` and `ids` from `id`; `id_count` is the number of ids
  // ever given (0: keep slot's size).
  void index_ids(std::size_t id_count = 0) {
    if (id_count == 0) id_count = slot.size();
    slot.assign(id_count, -1);
    for (std::size_t k = 0; k < id.size(); ++k) slot[id[k].index()] = static_cast<Slot>(k);
    ids.clear();
    ids.reserve(id.size());
    for (std::size_t i = 0; i < slot.size(); ++i) {
      if (slot[i] >= 0) ids.push_back(ParticleId::from_index(i));
    }
  }

  // Whether a particle of that id is in the world (given and not removed).
  bool contains(ParticleId particle) const {
    return particle.valid() && particle.index() < slot.size() && slot[particle.index()] >= 0;
  }
  // The slot of a particle id; only for ids the world contains.
  Slot slot_of(ParticleId particle) const { return slot[particle.index()]; }

  // omega^T I omega: with the scalar inertia for discs, spheres and
  // superquadrics, with the inertia tensor for ellipsoids.
  double spin_energy_product(std::size_t i, const Spin<Dim>& w) const {
    if constexpr (Dim == 3) {
      if (!principal_inertia.empty()) {
        const Vec3 body = rotation[i].conjugate() * w;
        return body.dot(principal_inertia[i].cwiseProduct(body));
      }
      return inertia[i] * w.squaredNorm();
    } else {
      return inertia[i] * w * w;
    }
  }
};

// Every per-slot array has its line in the field list, and every member of
// ParticleDefT a definition field: a new member - a bool that fits in
// padding too - fails the build here until it has its line in
// for_each_particle_field (particle_fields.h). `slot` and `ids` are by id,
// not by slot, and derived from `id` (index_ids).
static_assert(detail::member_count<Particles<2>>() == particle_field_count<2>() + 2,
              "Particles changed: give the new array its line in for_each_particle_field");
static_assert(detail::member_count<Particles<3>>() == particle_field_count<3>() + 2,
              "Particles changed: give the new array its line in for_each_particle_field");
static_assert(detail::member_count<ParticleDefT<2>>() == particle_definition_field_count<2>(),
              "ParticleDefT changed: give the new member its column and its line in for_each_particle_field");
static_assert(detail::member_count<ParticleDefT<3>>() == particle_definition_field_count<3>(),
              "ParticleDefT changed: give the new member its column and its line in for_each_particle_field");

// Reorders every per-slot array: new slot k holds what slot order[k] held.
template <typename T, typename Allocator>
void gather(std::vector<T, Allocator>& values, const std::vector<Slot>& order) {
  if (values.empty()) return;
  std::vector<T, Allocator> moved;
  moved.reserve(order.size());
  for (Slot from : order) moved.push_back(values[static_cast<std::size_t>(from)]);
  values.swap(moved);
}

}  // namespace dem
