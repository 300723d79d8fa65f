// The numerical health of a world's state: whether the step that produced
// it can be trusted, and if not, why and what to change. The engine's
// second error channel (STYLE.md 7): a returned status that names the fix,
// not an exception. dem_run, the one-shot mode and every server command
// that cycles act on it alike: stop with the message, keep the last good
// state (docs/RELIABILITY.md).
#pragma once

#include <cstdint>
#include <string>

#include "dem/world.h"

namespace dem {

enum class HealthProblem {
  kNone,
  kNonFinite,          // a position, velocity or the kinetic energy is NaN or infinite
  kOverlap,            // a contact overlaps beyond the stated fraction of the smaller radius
  kEnergyGrowth,       // energy appeared that no work put in (the energy budget's residual; worlds that keep it)
  kStepAboveCritical,  // the step exceeds the critical step (BasicWorld::critical_time_step)
  kRunaway,            // a particle travels more than the stated fraction of its radius in a step
};

// What counts as unhealthy; the defaults are far beyond what a sound run
// reaches. Over every case in cases/ (the full Miyata cases in their
// reduced versions) the deepest overlap was 0.38 of the smaller radius
// (superquadrics at 900 kPa, by their bounding radius), the largest travel
// in a step 0.017 of a radius and the largest energy growth 0.012, with
// the energy budget kept (docs/RELIABILITY.md).
struct HealthLimits {
  // A contact's overlap over the smaller radius of its bodies (a wall's
  // contact: the particle's).
  double max_overlap_fraction = 0.75;
  // Energy created since the monitor started - held plus dissipated beyond
  // what came in (initial kinetic energy, gravity's and the walls' work) -
  // over the most energy in play at any assessment so far (what had come
  // in, plus what was held at the start): an undamped assembly bouncing on
  // a floor takes gravity's work back and forth, so the energy in play at
  // one moment can be near 0 while the residual is not. A sound run's
  // residual is an integration error of a few percent of it. The excess
  // must also last: seen again at least two cycles later, or doubled. The
  // work of a contact force is booked a cycle after the motion it causes
  // (EnergyBudget), so a contact's first cycle shows energy ahead of its
  // work, which the next cycle settles; an unstable integration's grows.
  // Below a floor - every particle moving a millionth of its radius a
  // step, 1e-12 sum(m) (mean radius / time step)^2 - an excess is round-off
  // (nine discs at rest show 3e-19 J out of nothing). Only a world that
  // keeps the energy budget (WorldDefT::energy_budget) books the work that
  // came in; one that does not is not checked for this, and an unstable
  // integration there shows as an overlap or a non-finite state.
  double max_energy_growth = 1.0;
  // A particle's travel in one step, |v| dt, over its radius (a shaped
  // particle's: the bounding radius). A sound step resolves a collision
  // over many steps, so particles move a small fraction of their radius in
  // one; a blow-up flings them several radii a step. It needs no energy
  // budget: a world without one is caught by this.
  double max_step_travel = 0.5;
  // Randall's particle-wise step ratio (AssemblyMeasures::time_step_ratio)
  // is no criterion: sound runs reach 2.9 where forces barely change.
};

struct StepHealth {
  HealthProblem problem = HealthProblem::kNone;
  std::uint64_t cycle = 0;
  // What is wrong and what to change ("contact 12-40 overlaps 0.83 of the
  // smaller radius ...: reduce the time step or the loading rate").
  std::string message;
  // Healthy so far, but energy beyond the limit was seen and awaits its
  // confirmation (HealthLimits::max_energy_growth): not a state to keep as
  // the last good one.
  bool energy_suspect = false;
  bool ok() const { return problem == HealthProblem::kNone; }
};

// Follows one world's health from when it is made: the energy check counts
// energy created since then, so a world restored from a snapshot starts
// afresh. A world not yet cycled holds no strain energy even where its
// particles overlap (no force pass has run), so for one the reference is
// taken at the first assessment after a cycle: a packing built
// pre-compressed is a start, not energy from nowhere. assess() costs a
// pass over the particles and one over the touching contacts, about a
// cycle's time (bench_cycle's Health: 1.1 cycles of 10,000 discs, 1.3 of
// 100,000): the runners pace it to about 1/100 of a run, with
// motion_suspect() at output rows and chunks between.
template <int Dim>
class HealthMonitorT {
 public:
  explicit HealthMonitorT(const BasicWorld<Dim>& world, HealthLimits limits = {});
  // Not const: it keeps the most energy in play seen.
  StepHealth assess(const BasicWorld<Dim>& world);
  // A pass over the particles alone: a position or velocity not finite, or
  // a particle beyond max_step_travel - what a blow-up shows first. Cheap
  // enough for every output row or chunk of cycles, between the paced
  // assessments; when it says so, assess() says what is wrong.
  bool motion_suspect(const BasicWorld<Dim>& world) const;
  const HealthLimits& limits() const { return limits_; }

 private:
  HealthLimits limits_;
  double created_at_start_ = 0.0;    // J: the budget's excess when the monitor began
  double held_at_start_ = 0.0;       // J: kinetic and strain energy then
  EnergyBudget budget_at_start_;     // and the dissipating terms then (health::injected_energy)
  double most_in_play_ = 0.0;        // J: the largest energy in play at an assessment
  double round_off_ = 0.0;           // J: the floor below which an excess is round-off
  bool referenced_ = false;          // created_at_start_ and held_at_start_ are taken
  double suspect_created_ = 0.0;     // J: the excess when it first passed the limit, 0 while below
  std::uint64_t suspect_cycle_ = 0;  // and the cycle then
};

using HealthMonitor = HealthMonitorT<2>;
using HealthMonitor3 = HealthMonitorT<3>;

extern template class HealthMonitorT<2>;
extern template class HealthMonitorT<3>;

}  // namespace dem
