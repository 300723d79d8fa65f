// The complete state of a World as plain data, for exact restart: a World
// rebuilt from a snapshot continues bit for bit as the original would have,
// and reports the same measures and contacts at once.
// The conversion layer (io/) turns it into a Protocol Buffers message.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

#include "dem/definitions.h"
#include "dem/field_list.h"
#include "dem/measures.h"

namespace dem {

// The shear history of a contact: BALL's signed scalar F_s in 2D (along
// t_i, Fig. 3), a vector in the tangent plane in 3D.
template <int Dim>
using ShearForce = std::conditional_t<Dim == 2, double, Vec3>;

template <int Dim>
ShearForce<Dim> zero_shear() {
  if constexpr (Dim == 2) {
    return 0.0;
  } else {
    return Vec3::Zero();
  }
}

// The loading history of a Mindlin-Deresiewicz tangential law (Randall
// 1989, 4.3: BALL's CDF, T*, T** and DD).
struct MindlinHistory {
  double direction = 0.0;  // CDF: +1 or -1 along the axis; 0 before any tangential loading
  bool unloading = false;  // T* holds the force where unloading began
  bool reloading = false;  // T** holds the force where reloading began
  double t_star = 0.0;     // T*
  double t_star2 = 0.0;    // T**
  double lag = 0.0;        // DD (4.17-4.18)
};

// One row of the contact table: its history (Cundall & Strack eq. 18) and
// what the last force pass made of it. A pair row's `first` is the particle
// with the lower id. Rows that do not touch carry no force history; they
// are stored for the contact search of non-round particles, which starts
// where the last cycle's ended. The history restores the row; overlap,
// normal, point, dashpots, force and moments are what the pass made of it
// (for readers of the snapshot) and are not read back: the restored world
// computes the same from the same state.
template <int Dim>
struct ContactSnapshotT {
  // The ids' values (ParticleId::value, WallId::value): the row names a
  // particle and either kind of body.
  std::int32_t first = kInvalidId;
  std::int32_t second = kInvalidId;  // a particle, or a wall when with_wall
  bool with_wall = false;
  double normal_force = 0.0;
  ShearForce<Dim> shear_force = zero_shear<Dim>();
  bool sliding = false;
  double overlap = 0.0;
  double normal_damping = 0.0;
  ShearForce<Dim> shear_damping = zero_shear<Dim>();
  Vec<Dim> normal = Vec<Dim>::Zero();
  Vec<Dim> point = Vec<Dim>::Zero();
  Vec<Dim> force = Vec<Dim>::Zero();  // on the first particle
  Spin<Dim> moment_first = Space<Dim>::zero_spin();
  Spin<Dim> moment_second = Space<Dim>::zero_spin();
  std::uint64_t formed_cycle = 0;
  bool touching = true;
  MindlinHistory mindlin;                    // Hertz-Mindlin law only
  Vec<Dim> mindlin_axis = Vec<Dim>::Zero();  // its loading axis in the tangent plane
  double mindlin_theta = 1.0;                // the stiffness factor of the last step (sizes the tangential dashpot)
  // The dashpot force and the tangential spring force of the last cycle and
  // the relative velocity they came from: their work is booked in the next
  // cycle (energy budget).
  Vec<Dim> dashpot_force = Vec<Dim>::Zero();
  Vec<Dim> tangential_spring = Vec<Dim>::Zero();
  Vec<Dim> relative_velocity = Vec<Dim>::Zero();
  // The rolling spring's torque on the first body (rolling resistance only).
  Spin<Dim> rolling_torque = Space<Dim>::zero_spin();
  // Where the last contact search ended (superquadric parametric angles,
  // ellipsoid Lagrange multipliers), if there was one.
  double search_first = 0.0;
  double search_second = 0.0;
  bool has_search = false;
};

// ---------------------------------------------------------------------------
// The one list of a contact's fields. Save and restore (engine/src/snapshot.cpp),
// the state hash (engine/src/state_hash.cpp) and the Protocol Buffers
// conversion (io/src/snapshot_contacts.cpp) all walk it; adding a field is a
// member above, a line below and a field of dem.proto.SnapshotContacts of the
// same name (idl/dem/snapshot.proto).

// What a field is to the engine.
enum class ContactFieldRole {
  kKey,      // names the row (first, second, with_wall); saved and checked by snapshot.cpp itself
  kFlag,     // a bit of the row's flags (touching, sliding)
  kHistory,  // a column of the contact table, restored as saved
  kReport,   // what the last force pass made of the row, for readers; not read back
};

// The table column that holds a history field: a world keeps only the
// columns its law, shapes and energy budget need (ContactColumns in
// engine/src/contact_table.h); a field of a column the world lacks is saved
// at its default and not restored.
enum class ContactColumn { kNone, kAlways, kNormalForce, kMindlin, kSearch, kDashpot, kRolling };

struct ContactFieldInfo {
  const char* name;  // the field of dem.proto.SnapshotContacts
  ContactFieldRole role;
  ContactColumn column = ContactColumn::kNone;
  // Part of the state hash (a touching row's key by particle id, then these
  // in list order: the order is part of the hash, so hashed fields come first).
  bool hashed = false;
  // Added after snapshot version 1 was first written: older snapshots have
  // none of it, and a reader takes the default.
  bool may_be_empty = false;
};

// A field that no table column holds.
struct NoRow {};

// Calls visit(info, field, row) for every field of ContactSnapshotT<Dim>, in
// list order: field(c) is the field of a contact snapshot c (const or not),
// row(rows, r) the same quantity in row r of the engine's contact table
// (history fields only; NoRow otherwise). Both are generic lambdas, so the
// table's layout is named here but only compiled where the engine uses it.
template <int Dim, typename Visit>
constexpr void for_each_contact_field(Visit&& visit) {
  using enum ContactFieldRole;
  using enum ContactColumn;
  visit(
      ContactFieldInfo{"first", kKey}, [](auto& c) -> auto& { return c.first; }, NoRow{});
  visit(
      ContactFieldInfo{"second", kKey}, [](auto& c) -> auto& { return c.second; }, NoRow{});
  visit(
      ContactFieldInfo{"with_wall", kKey}, [](auto& c) -> auto& { return c.with_wall; }, NoRow{});
  // Hashed, in the hash's order.
  visit(
      ContactFieldInfo{"shear_force", kHistory, kAlways, true}, [](auto& c) -> auto& { return c.shear_force; },
      [](auto& rows, std::size_t r) -> auto& { return rows.shear[r]; });
  visit(
      ContactFieldInfo{"normal_force", kHistory, kNormalForce, true}, [](auto& c) -> auto& { return c.normal_force; },
      [](auto& rows, std::size_t r) -> auto& { return rows.normal_force[r]; });
  visit(
      ContactFieldInfo{"rolling_torque", kHistory, kRolling, true, true},
      [](auto& c) -> auto& { return c.rolling_torque; },
      [](auto& rows, std::size_t r) -> auto& { return rows.rolling[r]; });
  visit(
      ContactFieldInfo{"mindlin_t_star", kHistory, kMindlin, true}, [](auto& c) -> auto& { return c.mindlin.t_star; },
      [](auto& rows, std::size_t r) -> auto& { return rows.mindlin[r].history.t_star; });
  visit(
      ContactFieldInfo{"mindlin_t_star2", kHistory, kMindlin, true}, [](auto& c) -> auto& { return c.mindlin.t_star2; },
      [](auto& rows, std::size_t r) -> auto& { return rows.mindlin[r].history.t_star2; });
  visit(
      ContactFieldInfo{"mindlin_lag", kHistory, kMindlin, true}, [](auto& c) -> auto& { return c.mindlin.lag; },
      [](auto& rows, std::size_t r) -> auto& { return rows.mindlin[r].history.lag; });
  // Restored, not hashed.
  visit(
      ContactFieldInfo{"mindlin_direction", kHistory, kMindlin}, [](auto& c) -> auto& { return c.mindlin.direction; },
      [](auto& rows, std::size_t r) -> auto& { return rows.mindlin[r].history.direction; });
  visit(
      ContactFieldInfo{"mindlin_unloading", kHistory, kMindlin}, [](auto& c) -> auto& { return c.mindlin.unloading; },
      [](auto& rows, std::size_t r) -> auto& { return rows.mindlin[r].history.unloading; });
  visit(
      ContactFieldInfo{"mindlin_reloading", kHistory, kMindlin}, [](auto& c) -> auto& { return c.mindlin.reloading; },
      [](auto& rows, std::size_t r) -> auto& { return rows.mindlin[r].history.reloading; });
  visit(
      ContactFieldInfo{"mindlin_axis", kHistory, kMindlin}, [](auto& c) -> auto& { return c.mindlin_axis; },
      [](auto& rows, std::size_t r) -> auto& { return rows.mindlin[r].axis; });
  visit(
      ContactFieldInfo{"mindlin_theta", kHistory, kMindlin, false, true},
      [](auto& c) -> auto& { return c.mindlin_theta; },
      [](auto& rows, std::size_t r) -> auto& { return rows.mindlin[r].theta; });
  visit(
      ContactFieldInfo{"dashpot_force", kHistory, kDashpot}, [](auto& c) -> auto& { return c.dashpot_force; },
      [](auto& rows, std::size_t r) -> auto& { return rows.dashpot[r].force; });
  visit(
      ContactFieldInfo{"tangential_spring", kHistory, kDashpot, false, true},
      [](auto& c) -> auto& { return c.tangential_spring; },
      [](auto& rows, std::size_t r) -> auto& { return rows.dashpot[r].tangential; });
  visit(
      ContactFieldInfo{"relative_velocity", kHistory, kDashpot}, [](auto& c) -> auto& { return c.relative_velocity; },
      [](auto& rows, std::size_t r) -> auto& { return rows.dashpot[r].relative_velocity; });
  visit(
      ContactFieldInfo{"search_first", kHistory, kSearch}, [](auto& c) -> auto& { return c.search_first; },
      [](auto& rows, std::size_t r) -> auto& { return rows.search[r].first; });
  visit(
      ContactFieldInfo{"search_second", kHistory, kSearch}, [](auto& c) -> auto& { return c.search_second; },
      [](auto& rows, std::size_t r) -> auto& { return rows.search[r].second; });
  visit(
      ContactFieldInfo{"has_search", kHistory, kSearch}, [](auto& c) -> auto& { return c.has_search; },
      [](auto& rows, std::size_t r) -> auto& { return rows.search[r].valid; });
  visit(
      ContactFieldInfo{"formed_cycle", kHistory, kAlways}, [](auto& c) -> auto& { return c.formed_cycle; },
      [](auto& rows, std::size_t r) -> auto& { return rows.formed_cycle[r]; });
  visit(
      ContactFieldInfo{"touching", kFlag}, [](auto& c) -> auto& { return c.touching; }, NoRow{});
  visit(
      ContactFieldInfo{"sliding", kFlag}, [](auto& c) -> auto& { return c.sliding; }, NoRow{});
  visit(
      ContactFieldInfo{"overlap", kReport}, [](auto& c) -> auto& { return c.overlap; }, NoRow{});
  visit(
      ContactFieldInfo{"normal_damping", kReport}, [](auto& c) -> auto& { return c.normal_damping; }, NoRow{});
  visit(
      ContactFieldInfo{"shear_damping", kReport}, [](auto& c) -> auto& { return c.shear_damping; }, NoRow{});
  visit(
      ContactFieldInfo{"normal", kReport}, [](auto& c) -> auto& { return c.normal; }, NoRow{});
  visit(
      ContactFieldInfo{"point", kReport}, [](auto& c) -> auto& { return c.point; }, NoRow{});
  visit(
      ContactFieldInfo{"force", kReport}, [](auto& c) -> auto& { return c.force; }, NoRow{});
  visit(
      ContactFieldInfo{"moment_first", kReport}, [](auto& c) -> auto& { return c.moment_first; }, NoRow{});
  visit(
      ContactFieldInfo{"moment_second", kReport}, [](auto& c) -> auto& { return c.moment_second; }, NoRow{});
}

template <int Dim>
constexpr std::size_t contact_field_count() {
  std::size_t n = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo&, auto, auto) { ++n; });
  return n;
}

// Every member is in the list (MindlinHistory's six as six fields): a new
// member - a bool that fits in padding too - fails the build here until it
// has its line above.
static_assert(detail::member_count<ContactSnapshotT<2>>() - 1 + detail::member_count<MindlinHistory>() ==
                  contact_field_count<2>(),
              "ContactSnapshotT changed: give the new member its line in for_each_contact_field");
static_assert(detail::member_count<ContactSnapshotT<3>>() - 1 + detail::member_count<MindlinHistory>() ==
                  contact_field_count<3>(),
              "ContactSnapshotT changed: give the new member its line in for_each_contact_field");
// ---------------------------------------------------------------------------

template <int Dim>
struct WallSnapshotT {
  Vec<Dim> initial_point = Vec<Dim>::Zero();  // for settlement
  Vec<Dim> last_velocity = Vec<Dim>::Zero();  // the motion over the last cycle
  Spin<Dim> last_angular_velocity = Space<Dim>::zero_spin();
  Vec<Dim> force = Vec<Dim>::Zero();  // resultants of the last force pass
  Spin<Dim> moment = Space<Dim>::zero_spin();
  double normal_force = 0.0;
  int contacts = 0;
  Eccentricity<Dim> normal_force_arm = zero_eccentricity<Dim>();
};

template <int Dim>
struct WorldSnapshotT {
  // The definition as it stands now: materials, contact models, damping,
  // gravity, threads, time-step settings; walls at their current position,
  // direction and commanded motion; particles at their current position,
  // (half-step) velocity and angular velocity.
  WorldDefT<Dim> def;
  std::vector<Orientation<Dim>> rotation;       // per particle
  std::vector<Vec<Dim>> force;                  // per particle, last force sums
  std::vector<Spin<Dim>> moment;                // per particle
  std::vector<WallSnapshotT<Dim>> walls;        // per wall
  std::vector<ContactSnapshotT<Dim>> contacts;  // every row of the contact table
  // Neighbour-list bookkeeping, so the table is rebuilt on the same cycle
  // as it would have been: positions at the last rebuild (empty: rebuild
  // at once from the current positions) and the travel since.
  std::vector<Vec<Dim>> reference_positions;
  double particle_travel = 0.0;
  double wall_travel = 0.0;
  bool contacts_stale = false;
  // The order the engine stores the particles in (ids, closest in space
  // closest together) and the cycle it was last sorted; empty: id order,
  // sorted at the next rebuild. Float sums follow this order, so an exact
  // restart needs it.
  std::vector<ParticleId> particle_order;
  // The id of each particle of def.particles, ascending; empty: 0 .. n-1
  // (a world nothing was removed from, and every snapshot written before
  // ids were saved). Ids stay with their particles (world.h), so after a
  // trim they have gaps; particle_id_count is one past the highest id
  // ever given (0: one past the last of particle_ids), so a removed id
  // stays "removed" rather than "unknown".
  std::vector<ParticleId> particle_ids;
  std::int32_t particle_id_count = 0;
  std::uint64_t sorted_cycle = 0;
  EnergyBudget energy;           // the accumulated terms since the world was first built
  double tangential_work = 0.0;  // J, done on the tangential springs since then
  std::uint64_t cycle = 0;
  double time = 0.0;
  double time_step = 0.0;           // s, as in use (not re-estimated on restore)
  double critical_time_step = 0.0;  // s
  // The continuum field a box laid over the particles in the last step
  // (BoxControlT::continuum): the particles' velocities carry it, and the
  // next step takes it out again before it integrates their own.
  std::optional<ContinuumFieldT<Dim>> continuum;
};

// The id of the k-th particle of def.particles.
template <int Dim>
ParticleId snapshot_particle_id(const WorldSnapshotT<Dim>& s, std::size_t k) {
  return s.particle_ids.empty() ? ParticleId::from_index(k) : s.particle_ids[k];
}

// For readers of the contacts, which name particles by id: each id's
// entry in def.particles, -1 for removed ids. Assumes a consistent
// snapshot (ids ascending, contacts naming them), as the engine and the
// snapshot loader check it.
template <int Dim>
std::vector<std::int32_t> snapshot_entries_by_id(const WorldSnapshotT<Dim>& s) {
  const std::size_t n = s.def.particles.size();
  std::size_t count = s.particle_ids.empty() ? n : s.particle_ids.back().index() + 1;
  if (s.particle_id_count > 0) count = std::max(count, static_cast<std::size_t>(s.particle_id_count));
  std::vector<std::int32_t> entry(count, -1);
  for (std::size_t k = 0; k < n; ++k) entry[snapshot_particle_id(s, k).index()] = static_cast<std::int32_t>(k);
  return entry;
}

using ContactSnapshot = ContactSnapshotT<2>;
using WallSnapshot = WallSnapshotT<2>;
using WorldSnapshot = WorldSnapshotT<2>;
using WorldSnapshot3 = WorldSnapshotT<3>;

}  // namespace dem
