// Everything a World owns, and the engine-internal functions over it.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "contact_blocks.h"
#include "contact_params.h"
#include "contact_table.h"
#include "dem/definitions.h"
#include "dem/measures.h"
#include "dem/profile.h"
#include "dem/snapshot.h"
#include "ellipsoid.h"
#include "particles.h"
#include "periodic.h"
#include "step_context.h"
#include "walls.h"

namespace dem {

inline constexpr std::uint64_t kNeverSorted = std::numeric_limits<std::uint64_t>::max();

template <int Dim>
struct WorldState {
  std::vector<MaterialDef> materials;
  std::vector<ContactModelDef> contact_models;
  Particles<Dim> particles;
  Walls<Dim> walls;
  PeriodicDefT<Dim> periodic_def;
  Periodic<Dim> periodic;
  ContactTable<Dim> contacts;
  ContactBlocks<Dim> blocks;
  ContactParamTable params;
  ShapeKind shape = ShapeKind::kRound;
  ContactLaw pair_law = ContactLaw::kLinear;  // the law of every particle-particle contact
  ContactLaw wall_law = ContactLaw::kLinear;  // the law of every particle-wall contact
  DampingDef damping;
  Vec<Dim> gravity = Vec<Dim>::Zero();
  std::optional<CentripetalGravityT<Dim>> centripetal_gravity;  // Randall 6.4.2
  // The continuum field a box laid over the particles in the last step
  // (BoxControlT::continuum), which their velocities carry.
  std::optional<ContinuumFieldT<Dim>> continuum;
  PlanarParticle planar_particle = PlanarParticle::kDisc;
  double depth = 1.0;  // out-of-plane depth that turns 2D wall forces into stresses (3D: unused)
  double time_step = 0.0;
  double critical_time_step = 0.0;  // with the damping in force (estimate_critical_time_step)
  // 2 sqrt(m/k) without it (Rayleigh's step for Hertz laws): what a
  // time_step fraction is a fraction of.
  double undamped_critical_time_step = 0.0;
  double time_step_fraction = 0.1;  // the user's settings the step came from
  double fixed_time_step = 0.0;
  double contact_tolerance = 0.0;  // BALL's TOL
  bool energy_budget = false;
  bool rolling = false;  // some pair of materials has rolling resistance (rolling_resistance.h)
  int threads = 1;
  std::uint64_t cycle = 0;
  double time = 0.0;
  // Neighbour-list bookkeeping: how far particles and walls have moved since
  // the last rebuild (the positions then are Particles::reference_position),
  // and the cycle the particles were last put in spatial order.
  double particle_travel = 0.0;
  double wall_travel = 0.0;
  bool contacts_stale = true;
  std::uint64_t sorted_cycle = kNeverSorted;
  // How much closer any two particles may still come before the near rows
  // must be sorted out again (contact_blocks.h): the margin, less twice
  // the largest particle speed times each step since.
  double near_slack = 0.0;
  StepProfile profile;
  // Scratch of the force pass, derived from the particles' shapes and
  // rotations at its start (contact_forces.cpp): each ellipsoid's matrices.
  std::vector<EllipsoidFrame> ellipsoid_frames;
  // Accumulated energy terms (the held terms, kinetic and strain, are
  // measured when asked) and the last cycle's particle-wise step check.
  EnergyBudget energy;
  double tangential_work = 0.0;  // done on the tangential springs; friction = this - what they hold
  double time_step_ratio = 0.0;
};

// What the engine keeps worked out from the particles and the contact
// table between cycles, each redone when next needed once invalidated.
// Every edit that makes one out of date says so through invalidate(); the
// builders mark their own work done (find_contacts, the force pass,
// plan_blocks, the law of motion that writes the copies).
enum class Cache : unsigned {
  // The contact table's rows: rebuilt before the next force pass
  // (contacts_stale; find_contacts), as when the particles or walls moved
  // the tolerance.
  kContactTable = 1U << 0U,
  // The batched pass's near rows: sorted out again by the next pass
  // (ContactBlocks::near_stale, contact_blocks.h).
  kNearRows = 1U << 1U,
  // The batched pass's side-by-side copies: written again by the next pass
  // (ContactBlocks::hot_fresh, contact_blocks.h).
  kHotCopies = 1U << 2U,
  kAll = kContactTable | kNearRows | kHotCopies,
};
constexpr Cache operator|(Cache a, Cache b) {
  return static_cast<Cache>(static_cast<unsigned>(a) | static_cast<unsigned>(b));
}
constexpr bool contains(Cache set, Cache cache) {
  return (static_cast<unsigned>(set) & static_cast<unsigned>(cache)) != 0;
}

// Marks the caches out of date; the next step (or pass) redoes them. Only
// for what an edit changed: a table rebuilt earlier than the travel calls
// moves the next re-sort (sorted_cycle) and so the order of the float sums,
// so a needless invalidation changes the trajectory's bits.
template <int Dim>
void invalidate(WorldState<Dim>& state, Cache caches) {
  if (contains(caches, Cache::kContactTable)) state.contacts_stale = true;
  if (contains(caches, Cache::kNearRows)) state.blocks.near_stale = true;
  if (contains(caches, Cache::kHotCopies)) state.blocks.hot_fresh = false;
}

// The body force per unit mass on a particle at x: gravity and Randall's
// centripetal field (the law of motion adds the same, motion.cpp).
template <int Dim>
Vec<Dim> body_acceleration(const WorldState<Dim>& state, const Vec<Dim>& x) {
  if (!state.centripetal_gravity) return state.gravity;
  return state.gravity + state.centripetal_gravity->at(x);
}

// Particles per force-pass block, about (plan_blocks rounds the number of
// blocks to a power of two; contact_blocks.h): large for round
// particles, whose rows are cheap, so few rows cross blocks; small for
// shaped ones, whose rows are dear, so even small worlds spread over threads.
// A crossing row costs a round sphere's pass about as much as two rows that
// stay inside (its share set aside and added after all blocks, its slot
// found by a walk of the block's crossing rows, its second particle's data
// away from the block's): on the dense benchmark, blocks of 4096 spheres
// instead of 1024 cut the crossing rows from 17 % to 7 % (10k) and ran
// 1.055 (10k) and 1.09 (100k) on one thread (docs/PERFORMANCE.md, item 16).
// Discs keep 1024: a 2D case has a few thousand.
template <int Dim>
int block_size(const WorldState<Dim>& state) {
  if (state.shape != ShapeKind::kRound) return 32;
  return Dim == 3 ? 4096 : 1024;
}

// The gap below which a pair row counts as near (contact_blocks.h): an
// eighth of the tolerance (measured on the dense benchmark: two thirds of
// the rows near, sorted out every 60 cycles, against three quarters and
// every 100 at a quarter, and fewer rows read in all).
template <int Dim>
double near_margin(const WorldState<Dim>& state) {
  return 0.125 * state.contact_tolerance;
}

// The context of the step from the state's cycle N to N + 1.
template <int Dim>
StepContext begin_step(const WorldState<Dim>& state, bool keep_force, bool check_step) {
  return {state.time_step, state.cycle + 1, state.threads, state.energy_budget, keep_force, check_step};
}

// The context of work on the state as it stands, outside a step: a world's
// first contact search and force pass, the sums after an edit, reports.
template <int Dim>
StepContext current_context(const WorldState<Dim>& state) {
  return {state.time_step, state.cycle, state.threads, state.energy_budget, false, false};
}

// Rebuilds the contact table from the broad phase (keeping history),
// putting the particles back in spatial order first when that is due.
template <int Dim>
void find_contacts(WorldState<Dim>& state, const StepContext& step);

// The critical time step of central differences (time_step.cpp): over the
// particles and the contacts they can make, with the damping given (a
// stage's, a parameter's) or the state's own. Undamped, 2 sqrt(m/k) for the
// linear laws and Rayleigh's step for the Hertz laws.
template <int Dim>
double estimate_critical_time_step(const WorldState<Dim>& state, const ContactParamTable& params,
                                   const DampingDef& damping);
template <int Dim>
double estimate_critical_time_step(const WorldState<Dim>& state);
template <int Dim>
double estimate_undamped_critical_time_step(const WorldState<Dim>& state);

template <int Dim>
AssemblyMeasures measure_assembly(const WorldState<Dim>& state);

template <int Dim>
WorldSnapshotT<Dim> save_snapshot(const WorldState<Dim>& state);
// Overwrites a freshly built state (from the snapshot's def) with the saved dynamic state.
template <int Dim>
void restore_snapshot(WorldState<Dim>& state, const WorldSnapshotT<Dim>& snapshot);

template <int Dim>
std::uint64_t hash_state(const WorldState<Dim>& state);

}  // namespace dem
