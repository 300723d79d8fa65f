#include "dem/world.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>

#include "broad_phase.h"
#include "contact_forces.h"
#include "dem/error.h"
#include "motion.h"
#include "world_state.h"

namespace dem {

namespace {

// Adds the time since the last lap to a profile entry.
class PhaseTimer {
 public:
  explicit PhaseTimer(StepProfile&) : last_(std::chrono::steady_clock::now()) {}
  void lap(double& entry) {
    const auto now = std::chrono::steady_clock::now();
    entry += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_;
};

// ---------------------------------------------------------------------------
// The calculation cycle (Cundall & Strack 1979, The calculation cycle):
// find contacts -> force-displacement law at every contact -> force sums ->
// law of motion -> move walls.
void step(WorldState& s) {
  PhaseTimer timer(s.profile);
  if (s.contacts_stale) {
    find_contacts(s);
    timer.lap(s.profile.find_contacts);
  }
  ContactTable& c = s.contacts;
  compute_pair_forces(s.particles, c.pairs, c.pair_forces, s.params, s.time_step, s.threads);
  compute_wall_forces(s.particles, s.walls, c.walls, c.wall_forces, s.params, s.time_step, s.threads);
  timer.lap(s.profile.contact_forces);
  sum_particle_forces(s.particles, s.contacts, s.threads);
  sum_wall_forces(s.walls, c.walls, c.wall_forces);
  timer.lap(s.profile.force_sums);
  s.particle_travel = integrate_motion(s.particles, s.reference_positions, s.gravity, s.damping.global_alpha,
                                       s.time_step, s.threads);
  timer.lap(s.profile.motion);
  move_walls(s.walls, s.time_step);
  s.wall_travel += max_wall_step(s.walls, s.time_step);
  timer.lap(s.profile.walls);
  // A pair outside the table had a gap of at least TOL when it was built:
  // rebuild before anything could have closed that gap.
  s.contacts_stale = 2.0 * s.particle_travel >= s.contact_tolerance ||
                     s.particle_travel + s.wall_travel >= s.contact_tolerance;
  ++s.cycle;
  ++s.profile.cycles;
  s.time += s.time_step;
}
// ---------------------------------------------------------------------------

}  // namespace

void find_contacts(WorldState& s) {
  const auto n = static_cast<int>(s.particles.size());
  rebuild_contacts(s.contacts, find_pair_candidates(s.particles, s.contact_tolerance, s.threads),
                   find_wall_candidates(s.particles, s.walls, s.contact_tolerance), n);
  s.reference_positions = s.particles.position;
  s.particle_travel = 0.0;
  s.wall_travel = 0.0;
  s.contacts_stale = false;
  ++s.profile.contact_rebuilds;
}

namespace {

int resolve_threads(int threads) { return threads > 0 ? threads : std::max(1, omp_get_num_procs()); }

void check(bool ok, const std::string& message) {
  if (!ok) throw DefinitionError(message);
}

std::string material_name(const WorldState& s, MaterialId id) { return "\"" + s.materials[id].name + "\""; }

void validate(const WorldDef& def) {
  const auto materials = static_cast<MaterialId>(def.materials.size());
  check(materials > 0, "world: no materials defined");
  for (MaterialId m = 0; m < materials; ++m) {
    const MaterialDef& mat = def.materials[m];
    const std::string where = "material " + std::to_string(m) + " (\"" + mat.name + "\")";
    check(mat.friction >= 0.0, where + ": friction must be >= 0");
    check(mat.cohesion >= 0.0, where + ": cohesion must be >= 0");
  }
  for (std::size_t k = 0; k < def.contact_models.size(); ++k) {
    const ContactModelDef& model = def.contact_models[k];
    const std::string where = "contact model " + std::to_string(k);
    const bool both_default = model.material_a == kInvalidId && model.material_b == kInvalidId;
    const bool both_valid = model.material_a >= 0 && model.material_a < materials && model.material_b >= 0 &&
                            model.material_b < materials;
    check(both_default || both_valid, where + ": unknown material id");
    check(model.linear.normal_stiffness > 0.0, where + ": normal stiffness must be > 0");
    check(model.linear.shear_stiffness >= 0.0, where + ": shear stiffness must be >= 0");
    check(model.friction.value_or(0.0) >= 0.0, where + ": friction must be >= 0");
    check(model.cohesion.value_or(0.0) >= 0.0, where + ": cohesion must be >= 0");
  }
  check(!def.particles.empty(), "world: no particles defined");
  for (std::size_t i = 0; i < def.particles.size(); ++i) {
    const ParticleDef& p = def.particles[i];
    const std::string where = "particle " + std::to_string(i);
    check(p.radius > 0.0 && std::isfinite(p.radius), where + ": radius must be > 0");
    check(p.material >= 0 && p.material < materials, where + ": unknown material id");
    check(def.materials[p.material].density > 0.0, "material " + std::to_string(p.material) + " (\"" +
                                                       def.materials[p.material].name + "\"): density must be > 0");
    check(p.position.allFinite() && p.velocity.allFinite(), where + ": position and velocity must be finite");
  }
  for (std::size_t w = 0; w < def.walls.size(); ++w) {
    const WallDef& wall = def.walls[w];
    const std::string where = "wall " + std::to_string(w) + " (\"" + wall.name + "\")";
    check(std::abs(wall.direction.norm() - 1.0) < 1e-9, where + ": direction must be a unit vector");
    check(wall.h2 > wall.h1, where + ": h2 must be greater than h1");
    check(wall.material >= 0 && wall.material < materials, where + ": unknown material id");
    if (wall.motion.servo) {
      check(wall.motion.servo->gain > 0.0, where + ": servo gain must be > 0");
      check(wall.motion.servo->max_speed > 0.0, where + ": servo max_speed must be > 0");
    }
  }
  check(def.time_step_fraction > 0.0 && def.time_step_fraction <= 1.0,
        "world: time_step_fraction must be in (0, 1]");
  check(def.fixed_time_step >= 0.0, "world: fixed_time_step must be >= 0");
  check(def.contact_tolerance >= 0.0, "world: contact_tolerance must be >= 0");
  check(def.damping.contact_beta >= 0.0 && def.damping.global_alpha >= 0.0, "world: damping must be >= 0");
}

// Every pair of materials that can touch needs a contact law.
void check_contact_laws(const WorldState& s) {
  std::vector<bool> particle_material(s.materials.size(), false), wall_material(s.materials.size(), false);
  for (MaterialId m : s.particles.material) particle_material[m] = true;
  for (const WallDef& w : s.walls.def) wall_material[w.material] = true;
  for (MaterialId a = 0; a < static_cast<MaterialId>(s.materials.size()); ++a) {
    if (!particle_material[a]) continue;
    for (MaterialId b = 0; b < static_cast<MaterialId>(s.materials.size()); ++b) {
      if (!particle_material[b] && !wall_material[b]) continue;
      check(s.params(a, b).defined,
            "no contact model for materials " + material_name(s, a) + " and " + material_name(s, b));
    }
  }
}

}  // namespace

World::World(const WorldDef& def) : state_(std::make_unique<WorldState>()) {
  validate(def);
  WorldState& s = *state_;
  s.materials = def.materials;
  s.contact_models = def.contact_models;
  s.damping = def.damping;
  s.gravity = def.gravity;
  s.threads = resolve_threads(def.threads);
  s.params = ContactParamTable(s.materials, s.contact_models, s.damping);

  Particles& p = s.particles;
  const std::size_t n = def.particles.size();
  double radius_sum = 0.0;
  for (const ParticleDef& d : def.particles) {
    // Discs of unit thickness (Cundall & Strack): m = rho pi R^2, I = m R^2 / 2.
    const double mass = s.materials[d.material].density * std::numbers::pi * d.radius * d.radius;
    p.position.push_back(d.position);
    p.velocity.push_back(d.velocity);
    p.angular_velocity.push_back(d.angular_velocity);
    p.rotation.push_back(0.0);
    p.radius.push_back(d.radius);
    p.mass.push_back(mass);
    p.inertia.push_back(0.5 * mass * d.radius * d.radius);
    p.material.push_back(d.material);
    radius_sum += d.radius;
  }
  p.force.assign(n, Vec2::Zero());
  p.moment.assign(n, 0.0);

  Walls& w = s.walls;
  w.def = def.walls;
  for (const WallDef& wall : def.walls) w.initial_point.push_back(wall.point);
  const std::size_t walls = def.walls.size();
  w.last_velocity.assign(walls, Vec2::Zero());
  w.last_angular_velocity.assign(walls, 0.0);
  w.force.assign(walls, Vec2::Zero());
  w.moment.assign(walls, 0.0);
  w.normal_force.assign(walls, 0.0);
  w.contacts.assign(walls, 0);
  w.normal_force_arm.assign(walls, 0.0);

  check_contact_laws(s);
  s.contact_tolerance =
      def.contact_tolerance > 0.0 ? def.contact_tolerance : 0.1 * radius_sum / static_cast<double>(n);
  s.critical_time_step = estimate_critical_time_step(s);
  s.time_step_fraction = def.time_step_fraction;
  s.fixed_time_step = def.fixed_time_step;
  s.time_step = def.fixed_time_step > 0.0 ? def.fixed_time_step : def.time_step_fraction * s.critical_time_step;
  check(std::isfinite(s.time_step) && s.time_step > 0.0, "world: cannot determine a time step");
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::cycle(std::uint64_t n) {
  for (std::uint64_t k = 0; k < n; ++k) step(*state_);
}

std::uint64_t World::cycle_count() const { return state_->cycle; }
double World::time() const { return state_->time; }
double World::time_step() const { return state_->time_step; }
double World::critical_time_step() const { return state_->critical_time_step; }
int World::particle_count() const { return static_cast<int>(state_->particles.size()); }
int World::wall_count() const { return state_->walls.size(); }

ParticleView World::particles() const {
  const Particles& p = state_->particles;
  return {p.position, p.velocity, p.angular_velocity, p.rotation, p.radius, p.mass};
}

WallId World::find_wall(std::string_view name) const {
  const auto& walls = state_->walls.def;
  for (WallId w = 0; w < static_cast<WallId>(walls.size()); ++w) {
    if (walls[w].name == name) return w;
  }
  return kInvalidId;
}

const WallDef& World::wall(WallId id) const {
  assert(id >= 0 && id < wall_count());
  return state_->walls.def[id];
}

void World::set_wall_motion(WallId id, const WallMotion& motion) {
  assert(id >= 0 && id < wall_count());
  if (motion.servo) {
    check(motion.servo->gain > 0.0 && motion.servo->max_speed > 0.0,
          "wall " + std::to_string(id) + ": servo gain and max_speed must be > 0");
  }
  state_->walls.def[id].motion = motion;
}

DampingDef World::damping() const { return state_->damping; }

void World::set_damping(const DampingDef& damping) {
  check(damping.contact_beta >= 0.0 && damping.global_alpha >= 0.0, "damping must be >= 0");
  state_->damping = damping;
  state_->params = ContactParamTable(state_->materials, state_->contact_models, damping);
}

void World::set_time_step_fraction(double fraction) {
  check(fraction > 0.0 && fraction <= 1.0, "time_step_fraction must be in (0, 1]");
  state_->time_step_fraction = fraction;
  state_->fixed_time_step = 0.0;
  state_->time_step = fraction * state_->critical_time_step;
}

void World::set_friction(MaterialId material, double friction) {
  check(material >= 0 && material < static_cast<MaterialId>(state_->materials.size()),
        "unknown material id " + std::to_string(material));
  check(friction >= 0.0 && std::isfinite(friction), "friction must be >= 0");
  state_->materials[material].friction = friction;
  state_->params = ContactParamTable(state_->materials, state_->contact_models, state_->damping);
}

const std::vector<MaterialDef>& World::materials() const { return state_->materials; }

Vec2 World::gravity() const { return state_->gravity; }
void World::set_gravity(const Vec2& gravity) { state_->gravity = gravity; }
int World::threads() const { return state_->threads; }
const StepProfile& World::profile() const { return state_->profile; }
void World::set_threads(int threads) { state_->threads = resolve_threads(threads); }

}  // namespace dem
