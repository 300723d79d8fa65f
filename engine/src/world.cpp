#include "dem/world.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <string>

#include "box_control.h"
#include "broad_phase.h"
#include "contact_forces.h"
#include "dem/error.h"
#include "motion.h"
#include "particle_order.h"
#include "rolling_resistance.h"
#include "world_build.h"
#include "world_state.h"
#include "world_validation.h"

namespace dem {

namespace {

// Adds the time since the last lap to a profile entry.
class PhaseTimer {
 public:
  PhaseTimer() : last_(std::chrono::steady_clock::now()) {}
  void lap(double& entry) {
    const auto now = std::chrono::steady_clock::now();
    entry += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_;
};

template <int Dim>
void book(WorldState<Dim>& s, const ContactEnergy& e) {
  s.energy.contact_damping += e.damping;
  s.tangential_work += e.tangential_work;
  s.energy.wall_work += e.wall_work;
}

// The law of motion (motion.cpp) under the last pass's force sums, and
// what it reports booked: how far the particles went (for the contact
// search and the near rows), the energy flows, the time-step check.
template <int Dim>
void particle_motion(WorldState<Dim>& s, const StepContext& step) {
  // The pass's copies, when it keeps them (large beds) at this size.
  const bool hot = s.blocks.hot_place.size() == s.particles.size() && !s.particles.position.empty();
  // The continuum field of a box (Randall 4.5.2) this step, from the
  // speeds its walls are given next: the particles move with it too.
  std::optional<ContinuumFieldT<Dim>> continuum;
  if (s.walls.box && s.walls.box->continuum) continuum = box_continuum(s.walls, *s.walls.box);
  const MotionStep motion = integrate_motion(
      s.particles, MotionInputs<Dim>{s.periodic, s.gravity, s.damping, step.dt, step.threads, step.energy_budget,
                                     step.keep_force, step.check_step, hot ? s.blocks.hot_place.data() : nullptr,
                                     hot ? s.blocks.hot_motion.data() : nullptr,
                                     s.centripetal_gravity ? &*s.centripetal_gravity : nullptr,
                                     s.continuum ? &*s.continuum : nullptr, continuum ? &*continuum : nullptr});
  s.continuum = continuum;
  s.blocks.hot_fresh = hot;
  s.particle_travel = motion.max_travel;
  s.near_slack -= 2.0 * motion.max_speed * step.dt;
  if (s.near_slack < 0.0) invalidate(s, Cache::kNearRows);
  s.energy.gravity_work += motion.gravity_work;
  s.energy.global_damping += motion.global_damping;
  s.energy.local_damping += motion.local_damping;
  s.energy.continuum_work += motion.continuum_work;
  if (step.check_step) s.time_step_ratio = motion.time_step_ratio;
}

// The walls' motion over the step (walls.cpp), and how far they went.
template <int Dim>
void wall_motion(WorldState<Dim>& s, const StepContext& step) {
  move_walls(s.walls, step.dt);
  s.wall_travel += max_wall_step(s.walls, step.dt);
}

// A pair outside the table had a gap of at least TOL when it was built:
// rebuild before anything could have closed that gap.
template <int Dim>
bool contacts_due(const WorldState<Dim>& s) {
  return s.contacts_stale || 2.0 * s.particle_travel >= s.contact_tolerance ||
         s.particle_travel + s.wall_travel >= s.contact_tolerance;
}

// The force-displacement law at every contact (contact_forces.cpp), its
// energy flows booked, then rolling resistance (its own pass: nothing when
// off).
template <int Dim>
void contact_forces(WorldState<Dim>& s, const StepContext& step) {
  book(s, advance_contacts(s, step));
  if (s.rolling) apply_rolling_resistance(s);
}

// ---------------------------------------------------------------------------
// The calculation cycle (Cundall & Strack 1979, The calculation cycle). The
// force sums of the last pass move the particles (law of motion) and the
// walls; then the contacts are found where they now stand and the
// force-displacement law runs at every contact, leaving the force sums for
// the next cycle. So between cycles, positions, contact forces and wall
// forces all belong to the same instant.
//
// Randall's particle-wise time-step check compares each particle's force
// sum with the last cycle's, so the step's context asks for it on the
// cycles whose result is read (the last of each cycle(n)), and for keeping
// the sums on the cycles before them.
template <int Dim>
void step(WorldState<Dim>& s, const StepContext& context) {
  PhaseTimer timer;
  particle_motion(s, context);
  timer.lap(s.profile.motion);
  wall_motion(s, context);
  s.cycle = context.cycle;  // from here on the world is at the step's end
  s.time += context.dt;
  timer.lap(s.profile.walls);
  if (contacts_due(s)) {
    find_contacts(s, context);
    timer.lap(s.profile.find_contacts);
  }
  contact_forces(s, context);
  timer.lap(s.profile.contact_forces);
  ++s.profile.cycles;
}
// ---------------------------------------------------------------------------

// Cycles between putting the particles back in spatial order (at the next
// contact-table rebuild): they drift apart in memory as the assembly flows.
constexpr std::uint64_t kResortCycles = 1000;

}  // namespace

template <int Dim>
void find_contacts(WorldState<Dim>& s, const StepContext& step) {
  Particles<Dim>& p = s.particles;
  if (s.sorted_cycle == kNeverSorted || step.cycle - s.sorted_cycle >= kResortCycles) {
    double max_radius = 0.0;
    for (double r : p.radius) max_radius = std::max(max_radius, r);
    reorder_particles(p, s.contacts, spatial_order(p, s.periodic, 2.0 * max_radius + s.contact_tolerance));
    invalidate(s, Cache::kHotCopies);  // the copies are in the old order
    s.sorted_cycle = step.cycle;
  }
  merge_rows(s.contacts.pairs, find_pair_keys(p, s.periodic, s.contact_tolerance, step.threads));
  merge_rows(s.contacts.walls, find_wall_keys(p, s.walls, s.contact_tolerance));
  plan_blocks(s.blocks, s.contacts, p.size(), block_size(s));
  s.profile.pair_rows = s.contacts.pairs.size();
  s.profile.wall_rows = s.contacts.walls.size();
  s.profile.crossing_rows = s.blocks.cross_row.size();
  p.reference_position = p.position;
  s.particle_travel = 0.0;
  s.wall_travel = 0.0;
  s.contacts_stale = false;
  ++s.profile.contact_rebuilds;
}

template <int Dim>
BasicWorld<Dim>::BasicWorld(const Def& def) : state_(std::make_unique<WorldState<Dim>>()) {
  WorldState<Dim>& s = *state_;
  build_world(s, def);
  // The contacts and forces of cycle 0, for the first step's motion.
  const StepContext now = current_context(s);
  find_contacts(s, now);
  contact_forces(s, now);
  s.energy.initial_kinetic = measure_assembly(s).kinetic_energy;
}

template <int Dim>
BasicWorld<Dim>::BasicWorld(const Snapshot& snapshot) : state_(std::make_unique<WorldState<Dim>>()) {
  build_world(*state_, snapshot.def);
  restore_snapshot(*state_, snapshot);
}

template <int Dim>
BasicWorld<Dim>::~BasicWorld() = default;
template <int Dim>
BasicWorld<Dim>::BasicWorld(BasicWorld&&) noexcept = default;
template <int Dim>
BasicWorld<Dim>& BasicWorld<Dim>::operator=(BasicWorld&&) noexcept = default;

template <int Dim>
void BasicWorld<Dim>::cycle(std::uint64_t n) {
  for (std::uint64_t k = 0; k < n; ++k) step(*state_, begin_step(*state_, k + 2 >= n, k + 1 == n));
}

template <int Dim>
std::uint64_t BasicWorld<Dim>::cycle_count() const {
  return state_->cycle;
}
template <int Dim>
double BasicWorld<Dim>::time() const {
  return state_->time;
}
template <int Dim>
double BasicWorld<Dim>::time_step() const {
  return state_->time_step;
}
template <int Dim>
double BasicWorld<Dim>::critical_time_step() const {
  return state_->critical_time_step;
}
template <int Dim>
int BasicWorld<Dim>::particle_count() const {
  return static_cast<int>(state_->particles.size());
}
template <int Dim>
int BasicWorld<Dim>::wall_count() const {
  return state_->walls.size();
}
template <int Dim>
std::span<const ParticleId> BasicWorld<Dim>::particle_ids() const {
  return state_->particles.ids;
}
template <int Dim>
int BasicWorld<Dim>::particle_id_count() const {
  return static_cast<int>(state_->particles.slot.size());
}
template <int Dim>
bool BasicWorld<Dim>::has_particle(ParticleId id) const {
  return state_->particles.contains(id);
}
template <int Dim>
std::optional<std::string> BasicWorld<Dim>::missing_particle(ParticleId id) const {
  const Particles<Dim>& p = state_->particles;
  if (p.contains(id)) return std::nullopt;
  if (id.valid() && id.index() < p.slot.size()) return "particle " + to_string(id) + " was removed";
  return "no particle " + to_string(id);
}

template <int Dim>
ParticleViewT<Dim> BasicWorld<Dim>::particles() const {
  const Particles<Dim>& p = state_->particles;
  const std::span<const Slot> slots = p.slot;
  const std::span<const ParticleId> ids = p.ids;
  return {{p.position, slots, ids}, {p.velocity, slots, ids}, {p.angular_velocity, slots, ids},
          {p.rotation, slots, ids}, {p.radius, slots, ids},   {p.mass, slots, ids}};
}

template <int Dim>
WallId BasicWorld<Dim>::find_wall(std::string_view name) const {
  const auto& walls = state_->walls.def;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (walls[w].name == name) return WallId::from_index(w);
  }
  return kInvalidId;
}

template <int Dim>
std::optional<std::string> BasicWorld<Dim>::missing_wall(WallId id) const {
  return dem::missing_wall(state_->walls.def, id);
}

template <int Dim>
const WallDefT<Dim>& BasicWorld<Dim>::wall(WallId id) const {
  assert(!missing_wall(id));
  return state_->walls.def[id.index()];
}

template <int Dim>
void BasicWorld<Dim>::set_wall_motion(WallId id, const Motion& motion) {
  assert(!missing_wall(id));
  check_wall_motion(motion, id);
  state_->walls.def[id.index()].motion = motion;
}

template <int Dim>
double BasicWorld<Dim>::wall_area(WallId id) const {
  assert(!missing_wall(id));
  return wall_extent(state_->walls.def[id.index()], state_->periodic) * (Dim == 2 ? state_->depth : 1.0);
}

template <int Dim>
double BasicWorld<Dim>::wall_stress(WallId id) const {
  const double area = wall_area(id);
  return area > 0.0 ? measure_wall(state_->walls, id).normal_force / area : 0.0;
}

template <int Dim>
std::vector<WallMeasureT<Dim>> BasicWorld<Dim>::wall_measures() const {
  std::vector<WallMeasureT<Dim>> measures;
  for (int w = 0; w < wall_count(); ++w) measures.push_back(measure_wall(state_->walls, WallId{w}));
  return measures;
}

template <int Dim>
AssemblyMeasures BasicWorld<Dim>::assembly_measures() const {
  return measure_assembly(*state_);
}
template <int Dim>
std::vector<ContactRecordT<Dim>> BasicWorld<Dim>::contacts() const {
  return report_contacts(*state_);
}
template <int Dim>
std::vector<ContactRecordT<Dim>> BasicWorld<Dim>::wall_contacts(WallId wall) const {
  return report_wall_contacts(*state_, wall);
}
template <int Dim>
std::optional<ContactRecordT<Dim>> BasicWorld<Dim>::contact_between(ParticleId a, ParticleId b) const {
  return report_pair_contact(*state_, a, b);
}

template <int Dim>
double BasicWorld<Dim>::depth() const {
  return state_->depth;
}
template <int Dim>
const PeriodicDefT<Dim>& BasicWorld<Dim>::periodic() const {
  return state_->periodic_def;
}

template <int Dim>
DampingDef BasicWorld<Dim>::damping() const {
  return state_->damping;
}

template <int Dim>
double BasicWorld<Dim>::undamped_critical_time_step() const {
  return state_->undamped_critical_time_step;
}

template <int Dim>
double BasicWorld<Dim>::critical_time_step_with(const DampingDef& damping) const {
  check_damping(damping);
  return estimate_critical_time_step(*state_, ContactParamTable(state_->materials, state_->contact_models, damping),
                                     damping);
}

// The dashpots set the critical step; the step stays (a fraction is of the
// undamped critical step), and the health check judges it.
template <int Dim>
void BasicWorld<Dim>::set_damping(const DampingDef& damping) {
  check_damping(damping);
  ContactParamTable params(state_->materials, state_->contact_models, damping);
  state_->critical_time_step = estimate_critical_time_step(*state_, params, damping);
  state_->damping = damping;
  state_->params = std::move(params);
}

template <int Dim>
void BasicWorld<Dim>::set_time_step_fraction(double fraction) {
  check_time_step_fraction(fraction);
  state_->time_step_fraction = fraction;
  state_->fixed_time_step = 0.0;
  state_->time_step = fraction * state_->undamped_critical_time_step;
}

template <int Dim>
void BasicWorld<Dim>::set_fixed_time_step(double seconds) {
  check_fixed_time_step(seconds);
  state_->fixed_time_step = seconds;
  state_->time_step = seconds;
}

template <int Dim>
double BasicWorld<Dim>::fixed_time_step() const {
  return state_->fixed_time_step;
}

template <int Dim>
void BasicWorld<Dim>::set_friction(MaterialId material, double friction) {
  check_friction(material, state_->materials.size(), friction);
  state_->materials[material.index()].friction = friction;
  state_->params = ContactParamTable(state_->materials, state_->contact_models, state_->damping);
}

template <int Dim>
const std::vector<MaterialDef>& BasicWorld<Dim>::materials() const {
  return state_->materials;
}
template <int Dim>
Vec<Dim> BasicWorld<Dim>::gravity() const {
  return state_->gravity;
}
template <int Dim>
void BasicWorld<Dim>::set_gravity(const Vec<Dim>& gravity) {
  state_->gravity = gravity;
}
template <int Dim>
const std::optional<CentripetalGravityT<Dim>>& BasicWorld<Dim>::centripetal_gravity() const {
  return state_->centripetal_gravity;
}
template <int Dim>
void BasicWorld<Dim>::set_body_force(const BodyForceT<Dim>& body_force) {
  check_body_force(body_force.gravity, body_force.centripetal);
  state_->gravity = body_force.gravity;
  state_->centripetal_gravity = body_force.centripetal;
}
template <int Dim>
int BasicWorld<Dim>::threads() const {
  return state_->threads;
}
template <int Dim>
const StepProfile& BasicWorld<Dim>::profile() const {
  return state_->profile;
}
template <int Dim>
void BasicWorld<Dim>::set_threads(int threads) {
  state_->threads = resolve_threads(threads);
}
template <int Dim>
WorldSnapshotT<Dim> BasicWorld<Dim>::snapshot() const {
  return save_snapshot(*state_);
}
template <int Dim>
std::uint64_t BasicWorld<Dim>::state_hash() const {
  return hash_state(*state_);
}
template <int Dim>
bool BasicWorld<Dim>::energy_budget() const {
  return state_->energy_budget;
}

template void find_contacts(WorldState<2>&, const StepContext&);
template void find_contacts(WorldState<3>&, const StepContext&);
template class BasicWorld<2>;
template class BasicWorld<3>;

}  // namespace dem
