#include "dem/world.h"

#include <omp.h>

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

#include "broad_phase.h"
#include "contact_forces.h"
#include "dem/error.h"
#include "motion.h"
#include "ellipsoid.h"
#include "superquadric.h"
#include "world_state.h"

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

// ---------------------------------------------------------------------------
// The calculation cycle (Cundall & Strack 1979, The calculation cycle):
// find contacts -> force-displacement law at every contact -> force sums ->
// law of motion -> move walls.
template <int Dim>
void step(WorldState<Dim>& s) {
  PhaseTimer timer;
  if (s.contacts_stale) {
    find_contacts(s);
    timer.lap(s.profile.find_contacts);
  }
  ContactTable<Dim>& c = s.contacts;
  ContactEnergy contact_energy = compute_pair_forces(s.pair_law, s.shape, s.cycle, s.particles, s.periodic,
                                                     c.pairs, c.pair_forces, s.params, s.time_step, s.threads);
  contact_energy += compute_wall_forces(s.wall_law, s.shape, s.cycle, s.particles, s.walls, c.walls, c.wall_forces,
                                        s.params, s.time_step, s.threads);
  s.energy.contact_damping += contact_energy.damping;
  s.tangential_work += contact_energy.tangential_work;
  s.energy.wall_work += contact_energy.wall_work;
  timer.lap(s.profile.contact_forces);
  sum_particle_forces(s.particles, c, s.threads);
  sum_wall_forces(s.walls, c.walls, c.wall_forces);
  timer.lap(s.profile.force_sums);
  const MotionStep motion = integrate_motion(s.particles, s.reference_positions, s.periodic, s.gravity, s.damping,
                                            s.shape == ShapeKind::kEllipsoid, s.time_step, s.threads);
  s.particle_travel = motion.max_travel;
  s.energy.gravity_work += motion.gravity_work;
  s.energy.global_damping += motion.global_damping;
  s.energy.local_damping += motion.local_damping;
  s.time_step_ratio = motion.time_step_ratio;
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

// 0 means what OpenMP would use: OMP_NUM_THREADS if set, else every core.
int resolve_threads(int threads) { return threads > 0 ? threads : std::max(1, omp_get_max_threads()); }

void check(bool ok, const std::string& message) {
  if (!ok) throw DefinitionError(message);
}

std::string quoted(const MaterialDef& m) { return "\"" + m.name + "\""; }

void validate_wall(const WallDefT<2>& wall, const std::string& where) {
  check(std::abs(wall.direction.norm() - 1.0) < 1e-9, where + ": direction must be a unit vector");
  check(wall.h2 > wall.h1, where + ": h2 must be greater than h1");
}

void validate_wall(const WallDefT<3>& wall, const std::string& where) {
  check(std::abs(wall.direction.norm() - 1.0) < 1e-9 && std::abs(wall.direction2.norm() - 1.0) < 1e-9,
        where + ": direction and direction2 must be unit vectors");
  check(std::abs(wall.direction.dot(wall.direction2)) < 1e-9, where + ": direction2 must be perpendicular to direction");
  check(wall.h2 > wall.h1, where + ": h2 must be greater than h1");
  check(wall.k2 > wall.k1, where + ": k2 must be greater than k1");
  for (std::size_t k = 0; k < wall.triangles.size(); ++k) {
    const auto& t = wall.triangles[k];
    const double scale = std::max({(t[1] - t[0]).squaredNorm(), (t[2] - t[0]).squaredNorm(), 1e-300});
    check((t[1] - t[0]).cross(t[2] - t[0]).norm() > 1e-9 * scale && t[0].allFinite() && t[1].allFinite() &&
              t[2].allFinite(),
          where + ": triangle " + std::to_string(k) + " is degenerate (its corners are on one line)");
  }
}

void check_damping(const DampingDef& d) {
  check(d.contact_beta >= 0.0 && d.global_alpha >= 0.0 && d.global_alpha_rotation.value_or(0.0) >= 0.0,
        "damping: contact_beta and global_alpha must be >= 0");
  check(d.local_alpha >= 0.0 && d.local_alpha < 1.0 && d.local_alpha_rotation.value_or(0.0) >= 0.0 &&
            d.local_alpha_rotation.value_or(0.0) < 1.0,
        "damping: local_alpha must be in [0, 1)");
}

template <int Dim>
void validate(const WorldDefT<Dim>& def) {
  const auto materials = static_cast<MaterialId>(def.materials.size());
  check(materials > 0, "world: no materials defined");
  for (MaterialId m = 0; m < materials; ++m) {
    const MaterialDef& mat = def.materials[m];
    const std::string where = "material " + std::to_string(m) + " (" + quoted(mat) + ")";
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
    const bool linear = model.law == ContactLaw::kLinear || model.law == ContactLaw::kLinearRestitution;
    if (linear) {
      check(model.linear.normal_stiffness > 0.0, where + ": normal stiffness must be > 0");
      check(model.linear.shear_stiffness >= 0.0, where + ": shear stiffness must be >= 0");
    }
    if (model.law == ContactLaw::kLinearRestitution) {
      check(model.restitution > 0.0 && model.restitution <= 1.0, where + ": restitution must be in (0, 1]");
    }
    if (!linear) {
      check(model.hertz.damping_ratio >= 0.0, where + ": damping ratio must be >= 0");
      check(!model.hertz.restitution || (*model.hertz.restitution > 0.0 && *model.hertz.restitution <= 1.0),
            where + ": restitution must be in (0, 1]");
    }
    check(model.friction.value_or(0.0) >= 0.0, where + ": friction must be >= 0");
    check(model.cohesion.value_or(0.0) >= 0.0, where + ": cohesion must be >= 0");
  }
  check(!def.particles.empty(), "world: no particles defined");
  for (std::size_t i = 0; i < def.particles.size(); ++i) {
    const ParticleDefT<Dim>& p = def.particles[i];
    const std::string where = "particle " + std::to_string(i);
    if constexpr (Dim == 3) {
      const ShapeDefT<3>& shape = p.shape;
      check(shape.ellipsoid() == def.particles[0].shape.ellipsoid(),
            where + ": the particles must be all spheres or all ellipsoids");
      if (shape.ellipsoid()) {
        check((shape.axes.array() > 0.0).all() && shape.axes.allFinite(), where + ": ellipsoid axes must be > 0");
        check(shape.orientation.norm() > 0.0, where + ": ellipsoid orientation must be a rotation");
        continue;  // an ellipsoid's radius comes from its axes
      }
    }
    if constexpr (Dim == 2) {
      const ShapeDefT<2>& shape = p.shape;
      check(shape.superquadric() == def.particles[0].shape.superquadric(),
            where + ": the particles must be all discs or all superquadrics");
      if (shape.superquadric()) {
        check(shape.b > 0.0, where + ": superquadric semi-axis b must be > 0");
        check(shape.n > 1.0 && shape.n <= 10.0, where + ": superquadric exponent n must be in (1, 10]");
        check(def.planar_particle == PlanarParticle::kDisc, where + ": superquadrics have unit thickness, not spheres");
        continue;  // a superquadric's radius comes from its axes
      }
    }
    check(p.radius > 0.0 && std::isfinite(p.radius), where + ": radius must be > 0");
    check(p.material >= 0 && p.material < materials, where + ": unknown material id");
    const MaterialDef& mat = def.materials[p.material];
    check(mat.density > 0.0, "material " + std::to_string(p.material) + " (" + quoted(mat) + "): density must be > 0");
    check(p.position.allFinite() && p.velocity.allFinite(), where + ": position and velocity must be finite");
  }
  for (std::size_t w = 0; w < def.walls.size(); ++w) {
    const WallDefT<Dim>& wall = def.walls[w];
    const std::string where = "wall " + std::to_string(w) + " (\"" + wall.name + "\")";
    validate_wall(wall, where);
    check(wall.material >= 0 && wall.material < materials, where + ": unknown material id");
    if (wall.motion.servo) {
      check(wall.motion.servo->gain > 0.0, where + ": servo gain must be > 0");
      check(wall.motion.servo->max_speed > 0.0, where + ": servo max_speed must be > 0");
    }
  }
  for (int d = 0; d < Dim; ++d) {
    if (!def.periodic.axes[d]) continue;
    check(def.periodic.max[d] > def.periodic.min[d],
          "periodic: max must exceed min along axis " + std::to_string(d));
  }
  check(def.time_step_fraction > 0.0 && def.time_step_fraction <= 1.0,
        "world: time_step_fraction must be in (0, 1]");
  check(def.fixed_time_step >= 0.0, "world: fixed_time_step must be >= 0");
  check(def.contact_tolerance >= 0.0, "world: contact_tolerance must be >= 0");
  check_damping(def.damping);
}

const char* law_name(ContactLaw law) {
  switch (law) {
    case ContactLaw::kLinear:
      return "linear";
    case ContactLaw::kLinearRestitution:
      return "linear_restitution";
    case ContactLaw::kHertzMindlin:
      return "hertz_mindlin";
    case ContactLaw::kHertzLinearTangential:
      return "hertz_linear_tangential";
  }
  return "?";
}

bool is_hertz(ContactLaw law) { return law == ContactLaw::kHertzMindlin || law == ContactLaw::kHertzLinearTangential; }

// Every pair of materials that can touch needs a contact law, and one law
// serves all particle-particle contacts and one all particle-wall contacts
// (so the force passes choose it once, not per contact). Hertz laws need
// the elastic constants of the particles' materials.
template <int Dim>
void resolve_contact_laws(WorldState<Dim>& s) {
  const auto count = static_cast<MaterialId>(s.materials.size());
  std::vector<bool> particle_material(count, false), wall_material(count, false);
  for (MaterialId m : s.particles.material) particle_material[m] = true;
  for (const WallDefT<Dim>& w : s.walls.def) wall_material[w.material] = true;
  struct Seen {
    bool any = false;
    ContactLaw law = ContactLaw::kLinear;
    MaterialId a = 0, b = 0;
  };
  Seen pairs, walls;
  auto note = [&](Seen& seen, MaterialId a, MaterialId b, const char* kind) {
    const ContactParams& p = s.params(a, b);
    check(p.defined, "no contact model for materials " + quoted(s.materials[a]) + " and " + quoted(s.materials[b]));
    if (!seen.any) {
      seen = {true, p.law, a, b};
      return;
    }
    check(p.law == seen.law, std::string(kind) + " contacts must all use one contact law: materials " +
                                 quoted(s.materials[seen.a]) + " and " + quoted(s.materials[seen.b]) + " use " +
                                 law_name(seen.law) + ", " + quoted(s.materials[a]) + " and " +
                                 quoted(s.materials[b]) + " use " + law_name(p.law));
  };
  for (MaterialId a = 0; a < count; ++a) {
    if (!particle_material[a]) continue;
    for (MaterialId b = 0; b < count; ++b) {
      if (particle_material[b]) note(pairs, a, b, "particle-particle");
      if (wall_material[b]) note(walls, a, b, "particle-wall");
    }
  }
  s.pair_law = pairs.law;
  s.wall_law = walls.law;
  const bool hertz = (pairs.any && is_hertz(pairs.law)) || (walls.any && is_hertz(walls.law));
  if (!hertz) return;
  for (MaterialId m = 0; m < count; ++m) {
    if (!particle_material[m]) continue;
    const MaterialDef& mat = s.materials[m];
    check(mat.youngs_modulus > 0.0, "material " + quoted(mat) + ": a Hertz law needs youngs_modulus > 0");
    check(mat.poisson_ratio > -1.0 && mat.poisson_ratio < 0.5,
          "material " + quoted(mat) + ": poisson_ratio must be in (-1, 0.5)");
  }
}

// Mass and moment of inertia: discs of unit thickness (Cundall & Strack)
// or spheres, in the plane (Randall 1989, 4.4) or in space.
struct MassProperties {
  double mass, inertia;
};
MassProperties mass_properties(double density, double radius, bool disc) {
  if (disc) {
    const double m = density * std::numbers::pi * radius * radius;
    return {m, 0.5 * m * radius * radius};
  }
  const double m = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  return {m, 0.4 * m * radius * radius};
}

}  // namespace

template <int Dim>
void find_contacts(WorldState<Dim>& s) {
  const auto n = static_cast<int>(s.particles.size());
  rebuild_contacts(s.contacts, find_pair_candidates(s.particles, s.periodic, s.contact_tolerance, s.threads),
                   find_wall_candidates(s.particles, s.walls, s.contact_tolerance), n);
  s.reference_positions = s.particles.position;
  s.particle_travel = 0.0;
  s.wall_travel = 0.0;
  s.contacts_stale = false;
  ++s.profile.contact_rebuilds;
}

template <int Dim>
BasicWorld<Dim>::BasicWorld(const Def& def) : state_(std::make_unique<WorldState<Dim>>()) {
  validate(def);
  WorldState<Dim>& s = *state_;
  s.materials = def.materials;
  s.contact_models = def.contact_models;
  s.damping = def.damping;
  s.gravity = def.gravity;
  s.planar_particle = def.planar_particle;
  s.threads = resolve_threads(def.threads);
  s.params = ContactParamTable(s.materials, s.contact_models, s.damping);

  Particles<Dim>& p = s.particles;
  const std::size_t n = def.particles.size();
  const bool discs = Dim == 2 && def.planar_particle == PlanarParticle::kDisc;
  double radius_sum = 0.0;
  for (const ParticleDefT<Dim>& d : def.particles) {
    const double density = s.materials[d.material].density;
    MassProperties mp = mass_properties(density, d.radius, discs);
    double radius = d.radius;
    Orientation<Dim> rotation = Space<Dim>::identity();
    if constexpr (Dim == 2) {
      if (d.shape.superquadric()) {
        // Unit thickness; the bounding circle serves the broad phase.
        const SuperquadricMass m = superquadric_mass({d.shape.a, d.shape.b, d.shape.n});
        mp = {density * m.area, density * m.polar_moment};
        radius = superquadric_bounding_radius({d.shape.a, d.shape.b, d.shape.n});
        rotation = d.shape.angle;
        s.shape = ShapeKind::kSuperquadric;
      }
    } else {
      Vec3 principal = Vec3::Constant(mp.inertia);
      if (d.shape.ellipsoid()) {
        // The bounding sphere serves the broad phase; the smallest principal
        // moment the time-step estimate.
        const EllipsoidMass m = ellipsoid_mass(d.shape.axes);
        principal = density * m.principal_moments;
        mp = {density * m.volume, principal.minCoeff()};
        radius = d.shape.axes.maxCoeff();
        rotation = d.shape.orientation.normalized();
        s.shape = ShapeKind::kEllipsoid;
      }
      p.principal_inertia.push_back(principal);
    }
    p.position.push_back(d.position);
    p.velocity.push_back(d.velocity);
    p.angular_velocity.push_back(d.angular_velocity);
    p.rotation.push_back(rotation);
    p.radius.push_back(radius);
    p.mass.push_back(mp.mass);
    p.inertia.push_back(mp.inertia);
    p.material.push_back(d.material);
    p.shape.push_back(d.shape);
    radius_sum += radius;
  }
  p.force.assign(n, Vec<Dim>::Zero());
  p.moment.assign(n, Space<Dim>::zero_spin());
  p.previous_force.assign(n, 0.0);
  s.periodic_def = def.periodic;
  s.periodic = Periodic<Dim>::from(def.periodic);
  for (Vec<Dim>& x : p.position) s.periodic.wrap(x);
  // Stresses on 2D walls: discs have unit thickness; spheres in the plane
  // are taken as a layer one mean diameter deep (Randall 1989, 4.4).
  s.depth = discs || Dim == 3 ? 1.0 : 2.0 * radius_sum / static_cast<double>(n);

  Walls<Dim>& w = s.walls;
  w.def = def.walls;
  for (const WallDefT<Dim>& wall : def.walls) w.initial_point.push_back(wall.point);
  const std::size_t walls = def.walls.size();
  w.last_velocity.assign(walls, Vec<Dim>::Zero());
  w.last_angular_velocity.assign(walls, Space<Dim>::zero_spin());
  w.force.assign(walls, Vec<Dim>::Zero());
  w.moment.assign(walls, Space<Dim>::zero_spin());
  w.normal_force.assign(walls, 0.0);
  w.contacts.assign(walls, 0);
  w.normal_force_arm.assign(walls, zero_eccentricity<Dim>());

  resolve_contact_laws(s);
  s.contact_tolerance =
      def.contact_tolerance > 0.0 ? def.contact_tolerance : 0.1 * radius_sum / static_cast<double>(n);
  // Nearest images are unique only while a period holds two interaction ranges.
  const double reach = 2.0 * *std::max_element(p.radius.begin(), p.radius.end()) + s.contact_tolerance;
  for (int d = 0; d < Dim; ++d) {
    check(!s.periodic.repeats(d) || s.periodic.length[d] > 2.0 * reach,
          "periodic: the period along axis " + std::to_string(d) + " must exceed twice the largest diameter plus "
          "the contact tolerance (" + std::to_string(2.0 * reach) + ")");
  }
  s.critical_time_step = estimate_critical_time_step(s);
  s.time_step_fraction = def.time_step_fraction;
  s.fixed_time_step = def.fixed_time_step;
  s.time_step = def.fixed_time_step > 0.0 ? def.fixed_time_step : def.time_step_fraction * s.critical_time_step;
  check(std::isfinite(s.time_step) && s.time_step > 0.0, "world: cannot determine a time step");
  s.energy.initial_kinetic = measure_assembly(s).kinetic_energy;
}

template <int Dim>
BasicWorld<Dim>::BasicWorld(const Snapshot& snapshot) : BasicWorld(snapshot.def) {
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
  for (std::uint64_t k = 0; k < n; ++k) step(*state_);
}

template <int Dim>
std::uint64_t BasicWorld<Dim>::cycle_count() const { return state_->cycle; }
template <int Dim>
double BasicWorld<Dim>::time() const { return state_->time; }
template <int Dim>
double BasicWorld<Dim>::time_step() const { return state_->time_step; }
template <int Dim>
double BasicWorld<Dim>::critical_time_step() const { return state_->critical_time_step; }
template <int Dim>
int BasicWorld<Dim>::particle_count() const { return static_cast<int>(state_->particles.size()); }
template <int Dim>
int BasicWorld<Dim>::wall_count() const { return state_->walls.size(); }

template <int Dim>
ParticleViewT<Dim> BasicWorld<Dim>::particles() const {
  const Particles<Dim>& p = state_->particles;
  return {p.position, p.velocity, p.angular_velocity, p.rotation, p.radius, p.mass};
}

template <int Dim>
WallId BasicWorld<Dim>::find_wall(std::string_view name) const {
  const auto& walls = state_->walls.def;
  for (WallId w = 0; w < static_cast<WallId>(walls.size()); ++w) {
    if (walls[w].name == name) return w;
  }
  return kInvalidId;
}

template <int Dim>
const WallDefT<Dim>& BasicWorld<Dim>::wall(WallId id) const {
  assert(id >= 0 && id < wall_count());
  return state_->walls.def[id];
}

template <int Dim>
void BasicWorld<Dim>::set_wall_motion(WallId id, const Motion& motion) {
  assert(id >= 0 && id < wall_count());
  if (motion.servo) {
    check(motion.servo->gain > 0.0 && motion.servo->max_speed > 0.0,
          "wall " + std::to_string(id) + ": servo gain and max_speed must be > 0");
  }
  state_->walls.def[id].motion = motion;
}

template <int Dim>
double BasicWorld<Dim>::wall_area(WallId id) const {
  assert(id >= 0 && id < wall_count());
  return wall_extent(state_->walls.def[id], state_->periodic) * (Dim == 2 ? state_->depth : 1.0);
}

template <int Dim>
std::vector<WallMeasureT<Dim>> BasicWorld<Dim>::wall_measures() const {
  std::vector<WallMeasureT<Dim>> measures;
  for (WallId w = 0; w < wall_count(); ++w) measures.push_back(measure_wall(state_->walls, w));
  return measures;
}

template <int Dim>
AssemblyMeasures BasicWorld<Dim>::assembly_measures() const { return measure_assembly(*state_); }
template <int Dim>
std::vector<ContactRecordT<Dim>> BasicWorld<Dim>::contacts() const { return list_contacts(*state_); }
template <int Dim>
std::optional<ContactRecordT<Dim>> BasicWorld<Dim>::contact_between(ParticleId a, ParticleId b) const {
  return find_pair_contact(*state_, a, b);
}

template <int Dim>
DampingDef BasicWorld<Dim>::damping() const { return state_->damping; }

template <int Dim>
void BasicWorld<Dim>::set_damping(const DampingDef& damping) {
  check_damping(damping);
  state_->damping = damping;
  state_->params = ContactParamTable(state_->materials, state_->contact_models, damping);
}

template <int Dim>
void BasicWorld<Dim>::set_time_step_fraction(double fraction) {
  check(fraction > 0.0 && fraction <= 1.0, "time_step_fraction must be in (0, 1]");
  state_->time_step_fraction = fraction;
  state_->fixed_time_step = 0.0;
  state_->time_step = fraction * state_->critical_time_step;
}

template <int Dim>
void BasicWorld<Dim>::set_friction(MaterialId material, double friction) {
  check(material >= 0 && material < static_cast<MaterialId>(state_->materials.size()),
        "unknown material id " + std::to_string(material));
  check(friction >= 0.0 && std::isfinite(friction), "friction must be >= 0");
  state_->materials[material].friction = friction;
  state_->params = ContactParamTable(state_->materials, state_->contact_models, state_->damping);
}

template <int Dim>
const std::vector<MaterialDef>& BasicWorld<Dim>::materials() const { return state_->materials; }
template <int Dim>
Vec<Dim> BasicWorld<Dim>::gravity() const { return state_->gravity; }
template <int Dim>
void BasicWorld<Dim>::set_gravity(const Vec<Dim>& gravity) { state_->gravity = gravity; }
template <int Dim>
int BasicWorld<Dim>::threads() const { return state_->threads; }
template <int Dim>
const StepProfile& BasicWorld<Dim>::profile() const { return state_->profile; }
template <int Dim>
void BasicWorld<Dim>::set_threads(int threads) { state_->threads = resolve_threads(threads); }
template <int Dim>
WorldSnapshotT<Dim> BasicWorld<Dim>::snapshot() const { return save_snapshot(*state_); }
template <int Dim>
std::uint64_t BasicWorld<Dim>::state_hash() const { return hash_state(*state_); }

template void find_contacts(WorldState<2>&);
template void find_contacts(WorldState<3>&);
template class BasicWorld<2>;
template class BasicWorld<3>;

}  // namespace dem
