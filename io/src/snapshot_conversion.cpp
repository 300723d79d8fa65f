#include "dem/io/snapshot_conversion.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

// The definition and state structs' field lists: a member the lists lack
// fails the build there, and the round-trip test walks them.
#include "dem/snapshot_fields.h"
#include "snapshot_contacts.h"
#include "snapshot_packing.h"
#include "snapshot_structure_checks.h"

namespace dem::io {

namespace {

proto::SnapshotContactLaw to_proto(ContactLaw law) {
  switch (law) {
    case ContactLaw::kLinear:
      return proto::SNAPSHOT_LAW_LINEAR;
    case ContactLaw::kLinearRestitution:
      return proto::SNAPSHOT_LAW_LINEAR_RESTITUTION;
    case ContactLaw::kHertzMindlin:
      return proto::SNAPSHOT_LAW_HERTZ_MINDLIN;
    case ContactLaw::kHertzLinearTangential:
      return proto::SNAPSHOT_LAW_HERTZ_LINEAR_TANGENTIAL;
  }
  return proto::SNAPSHOT_LAW_LINEAR;
}

ContactLaw from_proto(proto::SnapshotContactLaw law) {
  switch (law) {
    case proto::SNAPSHOT_LAW_LINEAR_RESTITUTION:
      return ContactLaw::kLinearRestitution;
    case proto::SNAPSHOT_LAW_HERTZ_MINDLIN:
      return ContactLaw::kHertzMindlin;
    case proto::SNAPSHOT_LAW_HERTZ_LINEAR_TANGENTIAL:
      return ContactLaw::kHertzLinearTangential;
    default:
      return ContactLaw::kLinear;
  }
}

// --- engine -> message ---------------------------------------------------

template <int Dim>
void put_settings(const WorldDefT<Dim>& def, proto::SnapshotSettings& settings) {
  for (const MaterialDef& m : def.materials) {
    proto::SnapshotMaterial& out = *settings.add_material();
    out.set_name(m.name);
    out.set_density(m.density);
    out.set_friction(m.friction);
    out.set_cohesion(m.cohesion);
    out.set_youngs_modulus(m.youngs_modulus);
    out.set_poisson_ratio(m.poisson_ratio);
  }
  for (const ContactModelDef& c : def.contact_models) {
    proto::SnapshotContactModel& out = *settings.add_contact_model();
    out.set_material_a(c.material_a.value());
    out.set_material_b(c.material_b.value());
    out.set_law(to_proto(c.law));
    out.set_normal_stiffness(c.linear.normal_stiffness);
    out.set_shear_stiffness(c.linear.shear_stiffness);
    if (c.friction) out.set_friction(*c.friction);
    if (c.cohesion) out.set_cohesion(*c.cohesion);
    out.set_restitution(c.restitution);
    out.set_hertz_damping_ratio(c.hertz.damping_ratio);
    if (c.hertz.restitution) out.set_hertz_restitution(*c.hertz.restitution);
    out.set_hertz_tangential_damping(c.hertz.tangential);
    out.set_rolling_friction(c.rolling.friction);
    out.set_rolling_damping_ratio(c.rolling.damping_ratio);
  }
  proto::SnapshotDamping& damping = *settings.mutable_damping();
  damping.set_contact_beta(def.damping.contact_beta);
  damping.set_global_alpha(def.damping.global_alpha);
  if (def.damping.global_alpha_rotation) damping.set_global_alpha_rotation(*def.damping.global_alpha_rotation);
  damping.set_local_alpha(def.damping.local_alpha);
  if (def.damping.local_alpha_rotation) damping.set_local_alpha_rotation(*def.damping.local_alpha_rotation);
  put(settings.mutable_gravity(), def.gravity);
  settings.set_time_step_fraction(def.time_step_fraction);
  settings.set_fixed_time_step(def.fixed_time_step);
  settings.set_contact_tolerance(def.contact_tolerance);
  settings.set_threads(def.threads);
  settings.set_energy_budget(def.energy_budget);
  settings.set_planar_spheres(def.planar_particle == PlanarParticle::kSphere);
  for (const bool axis : def.periodic.axes) settings.add_periodic_axes(axis);
  put(settings.mutable_periodic_min(), def.periodic.min);
  put(settings.mutable_periodic_max(), def.periodic.max);
}

// A particle's shape: a 2D superquadric's a, b, n, angle; a 3D ellipsoid's
// semi-axes and orientation.
void put_shape(proto::SnapshotParticles& out, const ShapeDefT<2>& shape) {
  for (const double value : {shape.a, shape.b, shape.n, shape.angle}) out.add_shape(value);
}
void put_shape(proto::SnapshotParticles& out, const ShapeDefT<3>& shape) {
  put(out.mutable_shape(), shape.axes);
  put(out.mutable_shape(), shape.orientation);
}
ShapeDefT<2> get_shape(const proto::SnapshotParticles& in, int i, std::integral_constant<int, 2>) {
  return ShapeDefT<2>{in.shape(4 * i), in.shape(4 * i + 1), in.shape(4 * i + 2), in.shape(4 * i + 3)};
}
ShapeDefT<3> get_shape(const proto::SnapshotParticles& in, int i, std::integral_constant<int, 3>) {
  ShapeDefT<3> shape;
  shape.axes = Packing<Vec3>::get(in.shape(), 7 * i);
  shape.orientation = Packing<Quaternion>::get(in.shape(), 7 * i + 3);
  return shape;
}

template <int Dim>
void put_particles(const WorldSnapshotT<Dim>& s, proto::SnapshotParticles& out) {
  for (std::size_t i = 0; i < s.def.particles.size(); ++i) {
    const ParticleDefT<Dim>& p = s.def.particles[i];
    put(out.mutable_position(), p.position);
    put(out.mutable_velocity(), p.velocity);
    put(out.mutable_angular_velocity(), p.angular_velocity);
    put(out.mutable_rotation(), s.rotation[i]);
    out.add_radius(p.radius);
    out.add_material(p.material.value());
    put(out.mutable_force(), s.force[i]);
    put(out.mutable_moment(), s.moment[i]);
    put_shape(out, p.shape);
  }
}

template <int Dim>
void put_wall(const WallDefT<Dim>& def, const WallSnapshotT<Dim>& state, proto::SnapshotWall& out) {
  out.set_name(def.name);
  put(out.mutable_point(), def.point);
  put(out.mutable_direction(), def.direction);
  out.set_h1(def.h1);
  out.set_h2(def.h2);
  if constexpr (Dim == 3) {
    put(out.mutable_direction2(), def.direction2);
    out.set_k1(def.k1);
    out.set_k2(def.k2);
    for (const auto& face : def.triangles) {
      for (const Vec3& corner : face) put(out.mutable_triangles(), corner);
    }
  }
  out.set_material(def.material.value());
  put(out.mutable_velocity(), def.motion.velocity);
  put(out.mutable_angular_velocity(), def.motion.angular_velocity);
  if (def.motion.servo) {
    out.mutable_servo()->set_target_force(def.motion.servo->target_force);
    out.mutable_servo()->set_gain(def.motion.servo->gain);
    out.mutable_servo()->set_max_speed(def.motion.servo->max_speed);
  }
  put(out.mutable_initial_point(), state.initial_point);
  put(out.mutable_last_velocity(), state.last_velocity);
  put(out.mutable_last_angular_velocity(), state.last_angular_velocity);
  put(out.mutable_force(), state.force);
  put(out.mutable_moment(), state.moment);
  out.set_normal_force(state.normal_force);
  out.set_contacts(state.contacts);
  put(out.mutable_normal_force_arm(), state.normal_force_arm);
  out.set_removed(def.removed);
}

template <int Dim>
void put_box_control(const BoxControlT<Dim>& box, proto::SnapshotBoxControl& out) {
  for (const BoxAxisDef& a : box.axes) {
    proto::SnapshotBoxAxis& axis = *out.add_axis();
    axis.set_lower(a.lower.value());
    axis.set_upper(a.upper.value());
    axis.set_control(static_cast<int>(a.control));
    axis.set_strain_rate(a.strain_rate);
    axis.set_stress(a.stress);
  }
  out.set_path(static_cast<int>(box.path));
  out.set_path_value(box.path_value);
  out.set_gain(box.gain);
  out.set_max_speed(box.max_speed);
  put(out.mutable_reference_extent(), box.reference_extent);
}

template <int Dim>
BoxControlT<Dim> get_box_control(const proto::SnapshotBoxControl& in) {
  BoxControlT<Dim> box;
  for (int i = 0; i < Dim && i < in.axis_size(); ++i) {
    const proto::SnapshotBoxAxis& a = in.axis(i);
    box.axes[static_cast<std::size_t>(i)] = {WallId{a.lower()}, WallId{a.upper()},
                                             static_cast<AxisControl>(a.control()), a.strain_rate(), a.stress()};
  }
  box.path = static_cast<StressPath>(in.path());
  box.path_value = in.path_value();
  box.gain = in.gain();
  box.max_speed = in.max_speed();
  box.reference_extent = get<Vec<Dim>>(in.reference_extent(), 0);
  return box;
}

// --- message -> engine ---------------------------------------------------

template <int Dim>
void get_settings(const proto::SnapshotSettings& settings, WorldDefT<Dim>& def) {
  for (const auto& material : settings.material()) {
    def.materials.push_back(MaterialDef{material.name(), material.density(), material.friction(), material.cohesion(),
                                        material.youngs_modulus(), material.poisson_ratio()});
  }
  for (const auto& model : settings.contact_model()) {
    ContactModelDef c;
    c.material_a = MaterialId{model.material_a()};
    c.material_b = MaterialId{model.material_b()};
    c.law = from_proto(model.law());
    c.linear = LinearLawDef{model.normal_stiffness(), model.shear_stiffness()};
    if (model.has_friction()) c.friction = model.friction();
    if (model.has_cohesion()) c.cohesion = model.cohesion();
    c.restitution = model.restitution();
    c.hertz.damping_ratio = model.hertz_damping_ratio();
    if (model.has_hertz_restitution()) c.hertz.restitution = model.hertz_restitution();
    c.hertz.tangential = model.hertz_tangential_damping();
    c.rolling = RollingResistanceDef{model.rolling_friction(), model.rolling_damping_ratio()};
    def.contact_models.push_back(c);
  }
  const proto::SnapshotDamping& damping = settings.damping();
  def.damping.contact_beta = damping.contact_beta();
  def.damping.global_alpha = damping.global_alpha();
  if (damping.has_global_alpha_rotation()) def.damping.global_alpha_rotation = damping.global_alpha_rotation();
  def.damping.local_alpha = damping.local_alpha();
  if (damping.has_local_alpha_rotation()) def.damping.local_alpha_rotation = damping.local_alpha_rotation();
  def.gravity = get<Vec<Dim>>(settings.gravity(), 0);
  def.time_step_fraction = settings.time_step_fraction();
  def.fixed_time_step = settings.fixed_time_step();
  def.contact_tolerance = settings.contact_tolerance();
  def.threads = settings.threads();
  def.energy_budget = settings.energy_budget();
  def.planar_particle = settings.planar_spheres() ? PlanarParticle::kSphere : PlanarParticle::kDisc;
  for (int axis = 0; axis < Dim; ++axis)
    def.periodic.axes[static_cast<std::size_t>(axis)] = settings.periodic_axes(axis);
  def.periodic.min = get<Vec<Dim>>(settings.periodic_min(), 0);
  def.periodic.max = get<Vec<Dim>>(settings.periodic_max(), 0);
}

template <int Dim>
void get_particles(const proto::SnapshotParticles& p, WorldSnapshotT<Dim>& s) {
  const int count = p.radius_size();
  s.def.particles.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    ParticleDefT<Dim> particle;
    particle.position = get<Vec<Dim>>(p.position(), i);
    particle.radius = p.radius(i);
    particle.material = MaterialId{p.material(i)};
    particle.velocity = get<Vec<Dim>>(p.velocity(), i);
    particle.angular_velocity = get<Spin<Dim>>(p.angular_velocity(), i);
    particle.shape = get_shape(p, i, std::integral_constant<int, Dim>{});
    s.def.particles.push_back(particle);
    s.rotation.push_back(get<Orientation<Dim>>(p.rotation(), i));
    s.force.push_back(get<Vec<Dim>>(p.force(), i));
    s.moment.push_back(get<Spin<Dim>>(p.moment(), i));
  }
}

template <int Dim>
void get_wall(const proto::SnapshotWall& w, WorldSnapshotT<Dim>& s) {
  WallDefT<Dim> wall;
  wall.name = w.name();
  wall.point = get<Vec<Dim>>(w.point(), 0);
  wall.direction = get<Vec<Dim>>(w.direction(), 0);
  wall.h1 = w.h1();
  wall.h2 = w.h2();
  if constexpr (Dim == 3) {
    wall.direction2 = get<Vec3>(w.direction2(), 0);
    wall.k1 = w.k1();
    wall.k2 = w.k2();
    for (int face = 0; face < w.triangles_size() / 9; ++face) {
      wall.triangles.push_back({get<Vec3>(w.triangles(), 3 * face), get<Vec3>(w.triangles(), 3 * face + 1),
                                get<Vec3>(w.triangles(), 3 * face + 2)});
    }
  }
  wall.material = MaterialId{w.material()};
  wall.motion.velocity = get<Vec<Dim>>(w.velocity(), 0);
  wall.motion.angular_velocity = get<Spin<Dim>>(w.angular_velocity(), 0);
  if (w.has_servo()) wall.motion.servo = ServoDef{w.servo().target_force(), w.servo().gain(), w.servo().max_speed()};
  wall.removed = w.removed();
  s.def.walls.push_back(wall);

  WallSnapshotT<Dim> state;
  state.initial_point = get<Vec<Dim>>(w.initial_point(), 0);
  state.last_velocity = get<Vec<Dim>>(w.last_velocity(), 0);
  state.last_angular_velocity = get<Spin<Dim>>(w.last_angular_velocity(), 0);
  state.force = get<Vec<Dim>>(w.force(), 0);
  state.moment = get<Spin<Dim>>(w.moment(), 0);
  state.normal_force = w.normal_force();
  state.contacts = w.contacts();
  state.normal_force_arm = get<Eccentricity<Dim>>(w.normal_force_arm(), 0);
  s.walls.push_back(state);
}

}  // namespace

template <int Dim>
proto::Snapshot snapshot_to_proto(const WorldSnapshotT<Dim>& s, const SnapshotInfo& info) {
  proto::Snapshot m;
  m.set_format(kSnapshotFormat);
  m.set_version(kSnapshotVersion);
  m.set_dimension(Dim);
  m.set_case_name(info.case_name);
  m.set_description(info.description);
  put_settings(s.def, *m.mutable_settings());
  put_particles(s, *m.mutable_particles());
  for (std::size_t i = 0; i < s.def.walls.size(); ++i) put_wall(s.def.walls[i], s.walls[i], *m.add_wall());
  if (s.def.box_control) put_box_control(*s.def.box_control, *m.mutable_box_control());
  put_contacts<Dim>(s.contacts, *m.mutable_contacts());
  proto::SnapshotEnergy& energy = *m.mutable_energy();
  energy.set_initial_kinetic(s.energy.initial_kinetic);
  energy.set_gravity_work(s.energy.gravity_work);
  energy.set_wall_work(s.energy.wall_work);
  energy.set_kinetic(s.energy.kinetic);
  energy.set_strain(s.energy.strain);
  energy.set_contact_damping(s.energy.contact_damping);
  energy.set_friction(s.energy.friction);
  energy.set_global_damping(s.energy.global_damping);
  energy.set_local_damping(s.energy.local_damping);
  energy.set_removed(s.energy.removed);
  m.set_tangential_work(s.tangential_work);
  for (const Vec<Dim>& x : s.reference_positions) put(m.mutable_reference_positions(), x);
  m.set_particle_travel(s.particle_travel);
  m.set_wall_travel(s.wall_travel);
  m.set_contacts_stale(s.contacts_stale);
  for (ParticleId id : s.particle_order) m.add_particle_order(id.value());
  for (ParticleId id : s.particle_ids) m.add_particle_ids(id.value());
  m.set_particle_id_count(s.particle_id_count);
  m.set_sorted_cycle(s.sorted_cycle);
  m.set_cycle(s.cycle);
  m.set_time(s.time);
  m.set_time_step(s.time_step);
  m.set_critical_time_step(s.critical_time_step);
  return m;
}

template <int Dim>
WorldSnapshotT<Dim> snapshot_from_proto(const proto::Snapshot& m, SnapshotInfo* info, const ResourceLimits& limits) {
  Problems problems;
  check_structure<Dim>(m, problems, limits);
  if (!problems.empty()) throw SnapshotError(problems.text());

  WorldSnapshotT<Dim> s;
  get_settings(m.settings(), s.def);
  get_particles(m.particles(), s);
  for (const proto::SnapshotWall& w : m.wall()) get_wall(w, s);
  if (m.has_box_control()) s.def.box_control = get_box_control<Dim>(m.box_control());
  s.contacts = get_contacts<Dim>(m.contacts());
  const proto::SnapshotEnergy& energy = m.energy();
  s.energy =
      EnergyBudget{energy.initial_kinetic(), energy.gravity_work(),    energy.wall_work(), energy.kinetic(),
                   energy.strain(),          energy.contact_damping(), energy.friction(),  energy.global_damping(),
                   energy.local_damping(),   energy.removed()};
  s.tangential_work = m.tangential_work();
  for (int i = 0; i < m.reference_positions_size() / Dim; ++i) {
    s.reference_positions.push_back(get<Vec<Dim>>(m.reference_positions(), i));
  }
  s.particle_travel = m.particle_travel();
  s.wall_travel = m.wall_travel();
  s.contacts_stale = m.contacts_stale();
  for (const std::int32_t id : m.particle_order()) s.particle_order.push_back(ParticleId{id});
  for (const std::int32_t id : m.particle_ids()) s.particle_ids.push_back(ParticleId{id});
  s.particle_id_count = m.particle_id_count();
  s.sorted_cycle = m.sorted_cycle();
  s.cycle = m.cycle();
  s.time = m.time();
  s.time_step = m.time_step();
  s.critical_time_step = m.critical_time_step();
  if (info != nullptr) *info = SnapshotInfo{m.case_name(), m.description()};
  return s;
}

template proto::Snapshot snapshot_to_proto<2>(const WorldSnapshotT<2>&, const SnapshotInfo&);
template proto::Snapshot snapshot_to_proto<3>(const WorldSnapshotT<3>&, const SnapshotInfo&);
template WorldSnapshotT<2> snapshot_from_proto<2>(const proto::Snapshot&, SnapshotInfo*, const ResourceLimits&);
template WorldSnapshotT<3> snapshot_from_proto<3>(const proto::Snapshot&, SnapshotInfo*, const ResourceLimits&);

}  // namespace dem::io
