// A world's state built from its definition: particles with their mass
// properties, walls, the contact laws and table columns, the tolerance and
// the time step - everything up to the first contact search.
#include "world_build.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "box_control.h"
#include "ellipsoid.h"
#include "superquadric.h"
#include "world_laws.h"
#include "world_validation.h"

namespace dem {

// 0 means what OpenMP would use: OMP_NUM_THREADS if set, else every core.
int resolve_threads(int threads) { return threads > 0 ? threads : std::max(1, omp_get_max_threads()); }

namespace {

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

// Zero of a column's values (a rotation's is the identity).
template <typename T>
T zero_value() {
  if constexpr (requires { T::Zero(); }) {
    return T::Zero();
  } else if constexpr (requires { T::Identity(); }) {
    return T::Identity();
  } else {
    return T{};
  }
}

template <int Dim>
void add_particles(WorldState<Dim>& s, const WorldDefT<Dim>& def) {
  Particles<Dim>& p = s.particles;
  const bool discs = Dim == 2 && def.planar_particle == PlanarParticle::kDisc;
  const std::size_t n = def.particles.size();
  const bool shaped = [&] {
    if constexpr (Dim == 2) {
      return def.particles[0].shape.superquadric();
    } else {
      return def.particles[0].shape.ellipsoid();
    }
  }();
  p.position.reserve(n);
  // A superquadric's bounding radius samples its boundary 4,096 times
  // (superquadric_bounding_radius); the particles of a packing's size class
  // share one shape, so the last shape's radius is kept for the next.
  std::array<double, 3> bounded_shape{0.0, 0.0, 0.0};
  double bounding_radius = 0.0;
  for (const ParticleDefT<Dim>& d : def.particles) {
    const double density = s.materials[d.material.index()].density;
    MassProperties mp = mass_properties(density, d.radius, discs);
    double radius = d.radius;
    Orientation<Dim> rotation = Space<Dim>::identity();
    if constexpr (Dim == 2) {
      if (d.shape.superquadric()) {
        // Unit thickness; the bounding circle serves the broad phase.
        const SuperquadricMass m = superquadric_mass({d.shape.a, d.shape.b, d.shape.n});
        mp = {density * m.area, density * m.polar_moment};
        const std::array<double, 3> shape{d.shape.a, d.shape.b, d.shape.n};
        if (shape != bounded_shape || bounding_radius == 0.0) {
          bounded_shape = shape;
          bounding_radius = superquadric_bounding_radius({d.shape.a, d.shape.b, d.shape.n});
        }
        radius = bounding_radius;
        rotation = d.shape.angle;
        s.shape = ShapeKind::kSuperquadric;
      }
    } else {
      if (d.shape.ellipsoid()) {
        // The bounding sphere serves the broad phase; the smallest principal
        // moment the time-step estimate.
        const EllipsoidMass m = ellipsoid_mass(d.shape.axes);
        const Vec3 principal = density * m.principal_moments;
        mp = {density * m.volume, principal.minCoeff()};
        radius = d.shape.axes.maxCoeff();
        rotation = d.shape.orientation.normalized();
        s.shape = ShapeKind::kEllipsoid;
        p.principal_inertia.push_back(principal);
      }
    }
    p.position.push_back(d.position);
    p.velocity.push_back(d.velocity);
    p.angular_velocity.push_back(d.angular_velocity);
    p.rotation.push_back(rotation);
    p.radius.push_back(radius);
    p.mass.push_back(mp.mass);
    p.inertia.push_back(mp.inertia);
    p.material.push_back(d.material.value());
    if (shaped) p.shape.push_back(d.shape);
  }
  // The state and scratch arrays the definitions do not give start at
  // zero: the force sums before the first pass (particle_fields.h).
  for_each_particle_field<Dim>([&](const ParticleFieldInfo& info, auto column, auto, auto) {
    auto& values = column(p);
    using Value = typename std::remove_cvref_t<decltype(values)>::value_type;
    const bool zeroed = info.role == ParticleFieldRole::kState || info.role == ParticleFieldRole::kScratch;
    if (zeroed && values.size() != n) values.assign(n, zero_value<Value>());
  });
  p.reference_position = p.position;
  p.id.resize(n);
  for (std::size_t i = 0; i < n; ++i) p.id[i] = ParticleId::from_index(i);
  p.index_ids(n);
  for (Vec<Dim>& x : p.position) s.periodic.wrap(x);
}

template <int Dim>
void add_walls(WorldState<Dim>& s, const WorldDefT<Dim>& def) {
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
}

}  // namespace

template <int Dim>
void build_world(WorldState<Dim>& s, const WorldDefT<Dim>& def) {
  validate_world(def);
  s.materials = def.materials;
  s.contact_models = def.contact_models;
  s.damping = def.damping;
  s.gravity = def.gravity;
  s.centripetal_gravity = def.centripetal_gravity;
  s.planar_particle = def.planar_particle;
  s.energy_budget = def.energy_budget;
  s.threads = resolve_threads(def.threads);
  s.params = ContactParamTable(s.materials, s.contact_models, s.damping);
  s.periodic_def = def.periodic;
  s.periodic = Periodic<Dim>::from(def.periodic);
  add_particles(s, def);
  add_walls(s, def);
  const Particles<Dim>& p = s.particles;
  const auto n = static_cast<double>(p.size());
  double radius_sum = 0.0;
  for (double r : p.radius) radius_sum += r;
  // Stresses on 2D walls: discs have unit thickness; spheres in the plane
  // are taken as a layer one mean diameter deep (Randall 1989, 4.4).
  const bool discs = Dim == 2 && def.planar_particle == PlanarParticle::kDisc;
  s.depth = discs || Dim == 3 ? 1.0 : 2.0 * radius_sum / n;
  s.walls.depth = s.depth;
  if (def.box_control) {
    check_box_control(*def.box_control, def.walls);
    check_box_continuum(*def.box_control, def.periodic);
    s.walls.box = def.box_control;
    if (!(s.walls.box->reference_extent.array() > 0.0).all()) {
      s.walls.box->reference_extent = box_extent(s.walls, *s.walls.box);
    }
  }

  resolve_laws(s, def);

  s.contact_tolerance = def.contact_tolerance > 0.0 ? def.contact_tolerance : 0.1 * radius_sum / n;
  check_periodic_reach(s.periodic, *std::max_element(p.radius.begin(), p.radius.end()), s.contact_tolerance);
  s.critical_time_step = estimate_critical_time_step(s);
  s.undamped_critical_time_step = estimate_undamped_critical_time_step(s);
  s.time_step_fraction = def.time_step_fraction;
  s.fixed_time_step = def.fixed_time_step;
  s.time_step =
      def.fixed_time_step > 0.0 ? def.fixed_time_step : def.time_step_fraction * s.undamped_critical_time_step;
  check(std::isfinite(s.time_step) && s.time_step > 0.0, "world: cannot determine a time step");
}

template void build_world(WorldState<2>&, const WorldDefT<2>&);
template void build_world(WorldState<3>&, const WorldDefT<3>&);

}  // namespace dem
