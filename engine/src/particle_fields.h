// The one list of a particle's fields, as for_each_contact_field
// (dem/snapshot.h) is the contacts'. Every per-slot array of Particles
// (particles.h) has a line, and what each part of the engine does with the
// array follows from it: reordering and removing particles move every
// array (Particles::for_each_slot_array), the world's build sizes the state
// arrays (world_build.cpp), the snapshot saves and restores the saved
// fields (snapshot.cpp), the state hash adds the hashed ones
// (state_hash.cpp), and the batched pass's side-by-side copies are written
// from the fields with a place in them (copy_hot_particles,
// contact_blocks.h). The Protocol Buffers conversion walks the snapshot's
// own lists (dem/snapshot_fields.h), which name the same members.
//
// Adding a per-particle field is a member of Particles and its line below;
// a saved one also needs its member in ParticleDefT or WorldSnapshotT, that
// struct's line in dem/snapshot_fields.h and the field of that name in
// idl/dem/snapshot.proto. The build fails (below, and in
// dem/snapshot_fields.h) until each list has its line.
#pragma once

#include <cstddef>
#include <type_traits>

#include "dem/field_list.h"
#include "inline.h"

namespace dem {

// What a field is to the engine.
enum class ParticleFieldRole {
  kKey,          // the particle's id; snapshot.cpp saves the ids and the storage order itself
  kDefinition,   // a member of the definition's ParticleDefT: saved there, and the world is built from it
  kState,        // a per-particle vector of the snapshot (WorldSnapshotT), restored as saved
  kBookkeeping,  // a per-particle vector of the snapshot restored with the contact table's rows (snapshot.cpp)
  kDerived,      // worked out from the definition and the materials when the world is built; not saved
  kScratch,      // carried from one cycle to the next for a report only; not saved
};

struct ParticleFieldInfo {
  const char* name;  // the member of Particles (and of ParticleDefT for a definition field)
  ParticleFieldRole role;
  // Part of the state hash: every particle by id, its hashed fields in list
  // order. The order is part of the hash, so hashed fields come first.
  bool hashed = false;
  // Empty unless the world's shapes need it (superquadric or ellipsoid
  // worlds): a definition field of an empty column saves its default.
  bool optional = false;
};

// Where a field lies in the batched pass's side-by-side copies
// (HotPlace, HotMotion in contact_blocks.h): the record and its first
// double. contact_blocks.h checks each lane against the record's member.
enum class HotRecord { kNone, kPlace, kMotion };
template <HotRecord kRecord = HotRecord::kNone, int kLane = 0>
struct HotLane {
  static constexpr HotRecord record = kRecord;
  static constexpr int lane = kLane;
};
using NotHot = HotLane<>;

// Where a saved field goes: field(d) the member of a ParticleDefT (a
// definition field), field(s) the per-particle vector of a WorldSnapshotT
// (state and bookkeeping). Types, not roles, so that each is compiled only
// against its own struct.
template <typename Field>
struct InDefinition {
  Field field;
};
template <typename Field>
struct InSnapshot {
  Field field;
};
template <typename Field>
InDefinition(Field) -> InDefinition<Field>;
template <typename Field>
InSnapshot(Field) -> InSnapshot<Field>;
struct NotSaved {};

template <typename T>
inline constexpr bool kInDefinition = false;
template <typename Field>
inline constexpr bool kInDefinition<InDefinition<Field>> = true;
template <typename T>
inline constexpr bool kInSnapshot = false;
template <typename Field>
inline constexpr bool kInSnapshot<InSnapshot<Field>> = true;

// Calls visit(info, column, saved, hot) for every per-slot array of
// Particles<Dim>, in list order: column(p) is the array of a Particles p
// (const or not), saved an InDefinition, InSnapshot or NotSaved, hot a
// HotLane. The accessors are generic lambdas, so the structs are named here
// but only compiled where they are used. Inlined, so that a visit in a hot
// loop (copy_hot_particles) compiles to the fields' own loads and stores.
template <int Dim, typename Visit>
DEM_INLINE constexpr void for_each_particle_field(Visit&& visit) {
  using enum ParticleFieldRole;
  using enum HotRecord;
  // Hashed, in the hash's order.
  visit(
      ParticleFieldInfo{"position", kDefinition, true}, [](auto& p) -> auto& {
    return p.position; },
      InDefinition{[](auto& d) -> auto& { return d.position;
}
}  // namespace dem
, HotLane<kPlace, 0>{});
  visit(
      ParticleFieldInfo{"velocity", kDefinition, true}, [](auto& p) -> auto& {
  return p.velocity; },
      InDefinition{[](auto& d) -> auto& { return d.velocity;
  }
  }, HotLane<kMotion, 0>{});
  visit(
      ParticleFieldInfo{"angular_velocity", kDefinition, true}, [](auto& p) -> auto& {
  return p.angular_velocity; },
      InDefinition{[](auto& d) -> auto& { return d.angular_velocity;
  }
  }, HotLane<kMotion, Dim + 1>{});
  visit(
      ParticleFieldInfo{"rotation", kState, true}, [](auto& p) -> auto& {
  return p.rotation; },
      InSnapshot{[](auto& s) -> auto& { return s.rotation;
  }
  }, NotHot{});
  visit(
      ParticleFieldInfo{"force", kState, true}, [](auto& p) -> auto& {
  return p.force; },
      InSnapshot{[](auto& s) -> auto& { return s.force;
  }
  }, NotHot{});
  // Saved, not hashed.
  visit(
      ParticleFieldInfo{"moment", kState}, [](auto& p) -> auto& {
  return p.moment; },
      InSnapshot{[](auto& s) -> auto& { return s.moment;
  }
  }, NotHot{});
  // A shaped particle's is its bounding radius, which the build works out
  // again from the shape.
  visit(
      ParticleFieldInfo{"radius", kDefinition}, [](auto& p) -> auto& {
  return p.radius; },
      InDefinition{[](auto& d) -> auto& { return d.radius;
  }
  }, HotLane<kPlace, Dim>{});
  visit(
      ParticleFieldInfo{"material", kDefinition}, [](auto& p) -> auto& {
  return p.material; },
      InDefinition{[](auto& d) -> auto& { return d.material;
  }
  }, NotHot{});
  visit(
      ParticleFieldInfo{"shape", kDefinition, false, true}, [](auto& p) -> auto& {
  return p.shape; },
      InDefinition{[](auto& d) -> auto& { return d.shape;
  }
  }, NotHot{});
  visit(
      ParticleFieldInfo{"reference_position", kBookkeeping}, [](auto& p) -> auto& {
  return p.reference_position; },
      InSnapshot{[](auto& s) -> auto& { return s.reference_positions;
  }
  }, NotHot{});
  // Not saved.
  visit(
      ParticleFieldInfo{"mass", kDerived}, [](auto& p) -> auto& { return p.mass; }, NotSaved{},
      HotLane<kMotion, Dim>{});
  visit(
      ParticleFieldInfo{"inertia", kDerived}, [](auto& p) -> auto& { return p.inertia; }, NotSaved{}, NotHot{});
  visit(
      ParticleFieldInfo{"principal_inertia", kDerived, false, true},
      [](auto& p) -> auto& { return p.principal_inertia; }, NotSaved{}, NotHot{});
  // Randall's particle-wise time-step check (4.38) compares a force sum
  // with the last cycle's; a restored world's first check has none.
  visit(
      ParticleFieldInfo{"previous_force", kScratch}, [](auto& p) -> auto& { return p.previous_force; }, NotSaved{},
      NotHot{});
  visit(
      ParticleFieldInfo{"id", kKey}, [](auto& p) -> auto& { return p.id; }, NotSaved{}, NotHot{});
  }

  template <int Dim>
  constexpr std::size_t particle_field_count() {
    std::size_t n = 0;
    for_each_particle_field<Dim>([&](const ParticleFieldInfo&, auto, auto, auto) { ++n; });
    return n;
  }

  template <int Dim>
  constexpr std::size_t particle_definition_field_count() {
    std::size_t n = 0;
    for_each_particle_field<Dim>([&](const ParticleFieldInfo&, auto, auto saved, auto) {
      if constexpr (kInDefinition<decltype(saved)>) ++n;
    });
    return n;
  }

  }  // namespace dem
