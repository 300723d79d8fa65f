// The complete state of a World as plain data, for exact restart: a World
// rebuilt from a snapshot continues bit for bit as the original would have,
// and reports the same measures and contacts at once.
// The conversion layer (io/) turns it into a Protocol Buffers message.
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "dem/definitions.h"
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
  ParticleId first = kInvalidId;
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
  std::uint64_t sorted_cycle = 0;
  EnergyBudget energy;           // the accumulated terms since the world was first built
  double tangential_work = 0.0;  // J, done on the tangential springs since then
  std::uint64_t cycle = 0;
  double time = 0.0;
  double time_step = 0.0;           // s, as in use (not re-estimated on restore)
  double critical_time_step = 0.0;  // s
};

using ContactSnapshot = ContactSnapshotT<2>;
using WallSnapshot = WallSnapshotT<2>;
using WorldSnapshot = WorldSnapshotT<2>;
using WorldSnapshot3 = WorldSnapshotT<3>;

}  // namespace dem
