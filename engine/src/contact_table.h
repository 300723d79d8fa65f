// The contact table: every pair closer than the tolerance (BALL's TOL), with
// its history (the accumulated forces of eq. 18) kept from cycle to cycle
// while the pair stays close. Structure of arrays, one row per pair: the
// force pass reads and writes only the key, the flags and the shear history
// of a row, plus the columns its contact law needs; columns a world does not
// need stay empty (ContactColumns). Particle-particle rows and particle-wall
// rows are separate tables with the same columns.
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "dem/ids.h"
#include "dem/snapshot.h"
#include "large_pages.h"
#include "particles.h"

namespace dem {

// Bits of a row's flags.
inline constexpr std::uint8_t kTouching = 1;  // the bodies overlapped at the last force pass
inline constexpr std::uint8_t kSliding = 2;   // the shear force stood at the Coulomb limit (eq. 19)

// Mindlin-Deresiewicz history of a row (Hertz-Mindlin law only): Randall's
// CDF, T*, T** and DD; in 3D the law works along a loading axis in the
// tangent plane. theta, the stiffness factor of the last step, sizes the
// optional tangential dashpot.
template <int Dim>
struct MindlinRow {
  MindlinHistory history;
  Vec<Dim> axis = Vec<Dim>::Zero();
  double theta = 1.0;
};

// Energy bookkeeping (energy budget only): the dashpot force and the
// tangential spring force applied last cycle (on the first body) and the
// relative velocity they were computed from. Their work is known once the
// next relative velocity is (contact_forces.cpp).
template <int Dim>
struct DashpotWork {
  Vec<Dim> force = Vec<Dim>::Zero();
  Vec<Dim> tangential = Vec<Dim>::Zero();
  Vec<Dim> relative_velocity = Vec<Dim>::Zero();
};

// Superquadrics and ellipsoids: where last cycle's two contact searches
// ended (parametric angles, Miyata 2.3; Lagrange multipliers, 2.4), to
// start this cycle's near them.
struct ContactSearch {
  double first = 0.0, second = 0.0;
  bool valid = false;
};

// The optional columns a world keeps.
struct ContactColumns {
  bool normal_force = false;  // laws whose normal force is history (BALL's eq. 18) or whose dN matters (Mindlin)
  bool mindlin = false;
  bool search = false;   // shaped particles
  bool dashpot = false;  // energy budget
  bool rolling = false;  // rolling resistance (rolling_resistance.h)
};

template <int Dim>
struct ContactRows {
  // The key. A pair row's `first` is the slot of the particle with the lower
  // id and `second` the other's slot, so a row keeps its orientation (e_i
  // from first to second) when particles are re-sorted; a wall row's
  // `second` is the wall id. Rows are sorted by (first, second).
  Column<Slot> first;
  Column<std::int32_t> second;
  // Hot: read and written at every force pass.
  Column<std::uint8_t> flags;
  Column<ShearForce<Dim>> shear;  // F_s: signed along t_i (2D) or a tangent-plane vector (3D)
  // Optional, by law, shape and energy budget.
  Column<double> normal_force;  // F_n as history, compressive positive
  Column<MindlinRow<Dim>> mindlin;
  Column<ContactSearch> search;
  Column<DashpotWork<Dim>> dashpot;
  Column<Spin<Dim>> rolling;  // the rolling spring's torque on the first body
  // Cold: written when a contact forms.
  Column<std::uint64_t> formed_cycle;

  ContactColumns columns;

  std::size_t size() const { return first.size(); }
  bool touching(std::size_t r) const { return (flags[r] & kTouching) != 0; }
  bool sliding(std::size_t r) const { return (flags[r] & kSliding) != 0; }

  // Every column the table keeps, key included: visit(column).
  template <typename Visit>
  void for_each_column(Visit&& visit) {
    visit(first);
    visit(second);
    visit(flags);
    visit(shear);
    if (columns.normal_force) visit(normal_force);
    if (columns.mindlin) visit(mindlin);
    if (columns.search) visit(search);
    if (columns.dashpot) visit(dashpot);
    if (columns.rolling) visit(rolling);
    visit(formed_cycle);
  }
};

// A value with every member zero: what a row that just entered the table holds.
template <typename T>
T fresh() {
  if constexpr (std::is_base_of_v<Eigen::MatrixBase<T>, T>) {
    return T::Zero();
  } else {
    return T{};
  }
}

// The row a pair that stopped touching leaves behind: no force, no
// history; a shaped pair keeps where its contact search ended.
template <int Dim>
void separate(ContactRows<Dim>& rows, std::size_t r) {
  rows.flags[r] = 0;
  rows.shear[r] = fresh<ShearForce<Dim>>();
  if (rows.columns.normal_force) rows.normal_force[r] = 0.0;
  if (rows.columns.mindlin) rows.mindlin[r] = MindlinRow<Dim>{};
  if (rows.columns.dashpot) rows.dashpot[r] = DashpotWork<Dim>{};
  if (rows.columns.rolling) rows.rolling[r] = Space<Dim>::zero_spin();
}

// A row's key, for building and merging tables.
struct ContactKey {
  Slot first;
  std::int32_t second;  // a slot (pairs) or a wall id
  friend bool operator<(const ContactKey& a, const ContactKey& b) {
    return a.first < b.first || (a.first == b.first && a.second < b.second);
  }
  friend bool operator==(const ContactKey& a, const ContactKey& b) = default;
};

// Rearranges the rows: new row k is old row from[k], or a fresh row with
// key keys[k] where from[k] < 0.
template <int Dim>
void gather_rows(ContactRows<Dim>& rows, const std::vector<std::int32_t>& from, const std::vector<ContactKey>& keys);

// Replaces the rows with the given keys (sorted), carrying over the history
// of every key present in both: linear in the table size and deterministic.
template <int Dim>
void merge_rows(ContactRows<Dim>& rows, const std::vector<ContactKey>& keys);

// Renames the particle slots of every key (new slot = renamed[old]; pair
// rows swap nothing: their first is still the lower id) and sorts the rows
// by their new keys. Rows naming a slot renamed to -1 are dropped.
template <int Dim>
void rename_slots(ContactRows<Dim>& rows, const std::vector<Slot>& renamed, bool pairs);

template <int Dim>
struct ContactTable {
  ContactRows<Dim> pairs;
  ContactRows<Dim> walls;
};

}  // namespace dem
