#include "dem/io/snapshot_conversion.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "snapshot_checks.h"

namespace dem::io {

namespace {

// A snapshot must hold every field of the engine's definition and state
// structs, or a restored world would not continue bit for bit. These
// mirrors fail the build when a struct grows, pointing here.
#define DEM_SNAPSHOT_COVERS(Type, Mirror)       \
  static_assert(sizeof(Type) == sizeof(Mirror), \
                #Type " changed: update idl/dem/snapshot.proto and io/src/snapshot_conversion.cpp")
struct MaterialMirror {
  std::string name;
  double density, friction, cohesion, youngs_modulus, poisson_ratio;
};
struct HertzDampingMirror {
  double damping_ratio;
  std::optional<double> restitution;
  bool tangential;
};
struct ContactModelMirror {
  MaterialId a, b;
  LinearLawDef linear;
  std::optional<double> friction, cohesion;
  ContactLaw law;
  double restitution;
  HertzDampingDef hertz;
  RollingResistanceDef rolling;
};
struct RollingMirror {
  double friction, damping_ratio;
};
struct DampingMirror {
  double contact_beta, global_alpha;
  std::optional<double> global_alpha_rotation;
  double local_alpha;
  std::optional<double> local_alpha_rotation;
};
struct EnergyMirror {
  double initial_kinetic, gravity_work, wall_work, kinetic, strain, contact_damping, friction, global_damping,
      local_damping, removed;
};
struct ServoMirror {
  double target_force, gain, max_speed;
};
template <int Dim>
struct WorldDefMirror {
  std::vector<MaterialDef> m;
  std::vector<ContactModelDef> c;
  std::vector<ParticleDefT<Dim>> p;
  std::vector<WallDefT<Dim>> w;
  PeriodicDefT<Dim> periodic;
  std::optional<BoxControlT<Dim>> box;
  DampingDef d;
  Vec<Dim> g;
  PlanarParticle pp;
  double f, fixed, tol;
  int threads;
  bool energy_budget;
};
template <int Dim>
struct ParticleMirror {
  Vec<Dim> position;
  double radius;
  MaterialId material;
  Vec<Dim> velocity;
  Spin<Dim> angular_velocity;
  ShapeDefT<Dim> shape;
};
struct Shape2Mirror {
  double a, b, n, angle;
};
struct Shape3Mirror {
  Vec3 axes;
  Quaternion orientation;
};
template <int Dim>
struct PeriodicMirror {
  std::array<bool, Dim> axes;
  Vec<Dim> min, max;
};
struct Wall2Mirror {
  std::string name;
  Vec2 point, direction;
  double h1, h2;
  MaterialId material;
  WallMotionT<2> motion;
  bool removed;
};
struct Wall3Mirror {
  std::string name;
  Vec3 point, direction;
  double h1, h2;
  Vec3 direction2;
  double k1, k2;
  MaterialId material;
  WallMotionT<3> motion;
  std::vector<std::array<Vec3, 3>> triangles;
  bool removed;
};
struct BoxAxisMirror {
  WallId lower, upper;
  AxisControl control;
  double strain_rate, stress;
};
template <int Dim>
struct BoxControlMirror {
  std::array<BoxAxisDef, Dim> axes;
  StressPath path;
  double path_value, gain, max_speed;
  Vec<Dim> reference_extent;
};
struct MindlinMirror {
  double direction;
  bool unloading, reloading;
  double t_star, t_star2, lag;
};
template <int Dim>
struct ContactSnapshotMirror {
  ParticleId first;
  std::int32_t second;
  bool with_wall;
  double normal_force;
  ShearForce<Dim> shear_force;
  bool sliding;
  double overlap, normal_damping;
  ShearForce<Dim> shear_damping;
  Vec<Dim> normal, point, force;
  Spin<Dim> moment_first, moment_second;
  std::uint64_t formed_cycle;
  bool touching;
  MindlinHistory mindlin;
  Vec<Dim> mindlin_axis;
  double mindlin_theta;
  Vec<Dim> dashpot_force, tangential_spring, relative_velocity;
  double search_first, search_second;
  bool has_search;
  Spin<Dim> rolling_torque;
};
template <int Dim>
struct WallSnapshotMirror {
  Vec<Dim> initial_point, last_velocity;
  Spin<Dim> last_angular_velocity;
  Vec<Dim> force;
  Spin<Dim> moment;
  double normal_force;
  int contacts;
  Eccentricity<Dim> normal_force_arm;
};
template <int Dim>
struct WorldSnapshotMirror {
  WorldDefT<Dim> def;
  std::vector<Orientation<Dim>> rotation;
  std::vector<Vec<Dim>> force;
  std::vector<Spin<Dim>> moment;
  std::vector<WallSnapshotT<Dim>> walls;
  std::vector<ContactSnapshotT<Dim>> contacts;
  std::vector<Vec<Dim>> reference_positions;
  double particle_travel, wall_travel;
  bool contacts_stale;
  std::vector<ParticleId> particle_order;
  std::uint64_t sorted_cycle;
  EnergyBudget energy;
  double tangential_work;
  std::uint64_t cycle;
  double time, time_step, critical_time_step;
};
DEM_SNAPSHOT_COVERS(ContactSnapshotT<2>, ContactSnapshotMirror<2>);
DEM_SNAPSHOT_COVERS(ContactSnapshotT<3>, ContactSnapshotMirror<3>);
DEM_SNAPSHOT_COVERS(WallSnapshotT<2>, WallSnapshotMirror<2>);
DEM_SNAPSHOT_COVERS(WallSnapshotT<3>, WallSnapshotMirror<3>);
DEM_SNAPSHOT_COVERS(WorldSnapshotT<2>, WorldSnapshotMirror<2>);
DEM_SNAPSHOT_COVERS(WorldSnapshotT<3>, WorldSnapshotMirror<3>);
DEM_SNAPSHOT_COVERS(MaterialDef, MaterialMirror);
DEM_SNAPSHOT_COVERS(HertzDampingDef, HertzDampingMirror);
DEM_SNAPSHOT_COVERS(ContactModelDef, ContactModelMirror);
DEM_SNAPSHOT_COVERS(RollingResistanceDef, RollingMirror);
DEM_SNAPSHOT_COVERS(DampingDef, DampingMirror);
DEM_SNAPSHOT_COVERS(EnergyBudget, EnergyMirror);
DEM_SNAPSHOT_COVERS(MindlinHistory, MindlinMirror);
DEM_SNAPSHOT_COVERS(ServoDef, ServoMirror);
DEM_SNAPSHOT_COVERS(ParticleDefT<2>, ParticleMirror<2>);
DEM_SNAPSHOT_COVERS(ParticleDefT<3>, ParticleMirror<3>);
DEM_SNAPSHOT_COVERS(ShapeDefT<2>, Shape2Mirror);
DEM_SNAPSHOT_COVERS(ShapeDefT<3>, Shape3Mirror);
DEM_SNAPSHOT_COVERS(PeriodicDefT<2>, PeriodicMirror<2>);
DEM_SNAPSHOT_COVERS(PeriodicDefT<3>, PeriodicMirror<3>);
DEM_SNAPSHOT_COVERS(WorldDefT<2>, WorldDefMirror<2>);
DEM_SNAPSHOT_COVERS(WorldDefT<3>, WorldDefMirror<3>);
DEM_SNAPSHOT_COVERS(WallDefT<2>, Wall2Mirror);
DEM_SNAPSHOT_COVERS(WallDefT<3>, Wall3Mirror);
DEM_SNAPSHOT_COVERS(BoxAxisDef, BoxAxisMirror);
DEM_SNAPSHOT_COVERS(BoxControlT<2>, BoxControlMirror<2>);
DEM_SNAPSHOT_COVERS(BoxControlT<3>, BoxControlMirror<3>);
#undef DEM_SNAPSHOT_COVERS

using Doubles = google::protobuf::RepeatedField<double>;

// How each quantity is packed into a flat array of doubles
// (idl/dem/snapshot.proto): a scalar (2D spin, angle, shear), a 2-vector
// (2D vector, 3D eccentricity), a 3-vector, a quaternion as w, x, y, z.
template <typename T>
struct Packing;
template <>
struct Packing<double> {
  static constexpr std::size_t width = 1;
  static void put(Doubles* out, double v) { out->Add(v); }
  static double get(const Doubles& in, int at) { return in[at]; }
};
template <>
struct Packing<Vec2> {
  static constexpr std::size_t width = 2;
  static void put(Doubles* out, const Vec2& v) {
    out->Add(v.x());
    out->Add(v.y());
  }
  static Vec2 get(const Doubles& in, int at) { return {in[at], in[at + 1]}; }
};
template <>
struct Packing<Vec3> {
  static constexpr std::size_t width = 3;
  static void put(Doubles* out, const Vec3& v) {
    out->Add(v.x());
    out->Add(v.y());
    out->Add(v.z());
  }
  static Vec3 get(const Doubles& in, int at) { return {in[at], in[at + 1], in[at + 2]}; }
};
template <>
struct Packing<Quaternion> {
  static constexpr std::size_t width = 4;
  static void put(Doubles* out, const Quaternion& q) {
    out->Add(q.w());
    out->Add(q.x());
    out->Add(q.y());
    out->Add(q.z());
  }
  static Quaternion get(const Doubles& in, int at) { return Quaternion(in[at], in[at + 1], in[at + 2], in[at + 3]); }
};

template <typename T>
void put(Doubles* out, const T& value) {
  Packing<T>::put(out, value);
}
// The index-th item of a packed array of T.
template <typename T>
T get(const Doubles& in, int index) {
  return Packing<T>::get(in, index * static_cast<int>(Packing<T>::width));
}
template <typename T>
constexpr std::size_t width = Packing<T>::width;

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
    out.set_material_a(c.material_a);
    out.set_material_b(c.material_b);
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
template <int Dim>
constexpr std::size_t kShapeWidth = Dim == 2 ? 4 : 7;
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
    out.add_material(p.material);
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
  out.set_material(def.material);
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
    axis.set_lower(a.lower);
    axis.set_upper(a.upper);
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
    box.axes[static_cast<std::size_t>(i)] = {a.lower(), a.upper(), static_cast<AxisControl>(a.control()),
                                             a.strain_rate(), a.stress()};
  }
  box.path = static_cast<StressPath>(in.path());
  box.path_value = in.path_value();
  box.gain = in.gain();
  box.max_speed = in.max_speed();
  box.reference_extent = get<Vec<Dim>>(in.reference_extent(), 0);
  return box;
}

template <int Dim>
void put_contacts(const std::vector<ContactSnapshotT<Dim>>& contacts, proto::SnapshotContacts& out) {
  for (const ContactSnapshotT<Dim>& c : contacts) {
    out.add_first(c.first);
    out.add_second(c.second);
    out.add_with_wall(c.with_wall);
    out.add_normal_force(c.normal_force);
    put(out.mutable_shear_force(), c.shear_force);
    out.add_sliding(c.sliding);
    out.add_overlap(c.overlap);
    out.add_normal_damping(c.normal_damping);
    put(out.mutable_shear_damping(), c.shear_damping);
    put(out.mutable_normal(), c.normal);
    put(out.mutable_point(), c.point);
    put(out.mutable_force(), c.force);
    put(out.mutable_moment_first(), c.moment_first);
    put(out.mutable_moment_second(), c.moment_second);
    out.add_formed_cycle(c.formed_cycle);
    out.add_touching(c.touching);
    out.add_mindlin_direction(c.mindlin.direction);
    out.add_mindlin_unloading(c.mindlin.unloading);
    out.add_mindlin_reloading(c.mindlin.reloading);
    out.add_mindlin_t_star(c.mindlin.t_star);
    out.add_mindlin_t_star2(c.mindlin.t_star2);
    out.add_mindlin_lag(c.mindlin.lag);
    put(out.mutable_mindlin_axis(), c.mindlin_axis);
    out.add_mindlin_theta(c.mindlin_theta);
    put(out.mutable_dashpot_force(), c.dashpot_force);
    put(out.mutable_tangential_spring(), c.tangential_spring);
    put(out.mutable_relative_velocity(), c.relative_velocity);
    out.add_search_first(c.search_first);
    out.add_search_second(c.search_second);
    out.add_has_search(c.has_search);
    put(out.mutable_rolling_torque(), c.rolling_torque);
  }
}

// --- checks --------------------------------------------------------------

// Collects what is wrong with a message, each problem naming its field.
class Problems {
 public:
  void add(const std::string& path, const std::string& message) {
    if (list_.size() < kMaxListed) list_.push_back(path + ": " + message);
    ++count_;
  }
  bool empty() const { return count_ == 0; }
  std::string text() const {
    std::string out;
    for (const std::string& p : list_) out += (out.empty() ? "" : "\n") + p;
    if (count_ > list_.size()) out += "\n... and " + std::to_string(count_ - list_.size()) + " more problems";
    return out;
  }

 private:
  static constexpr std::size_t kMaxListed = 12;
  std::vector<std::string> list_;
  std::size_t count_ = 0;
};

// A packed array must hold `width` finite values for each of `count` items.
bool check_array(Problems& problems, const std::string& path, const Doubles& values, std::size_t count,
                 std::size_t item_width) {
  if (static_cast<std::size_t>(values.size()) != count * item_width) {
    problems.add(path, "has " + std::to_string(values.size()) + " values, expected " +
                           std::to_string(count * item_width) + " (" + std::to_string(item_width) + " for each of " +
                           std::to_string(count) + ")");
    return false;
  }
  for (int i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      problems.add(path + "[" + std::to_string(static_cast<std::size_t>(i) / item_width) + "]",
                   "is not a finite number");
      return false;
    }
  }
  return true;
}

template <typename Field>
bool check_length(Problems& problems, const std::string& path, const Field& values, std::size_t count) {
  if (static_cast<std::size_t>(values.size()) == count) return true;
  problems.add(path, "has " + std::to_string(values.size()) + " values, expected " + std::to_string(count));
  return false;
}

void check_finite(Problems& problems, const std::string& path, double value) {
  if (!std::isfinite(value)) problems.add(path, "is not a finite number");
}

bool in_range(std::int32_t id, std::size_t count) { return id >= 0 && static_cast<std::size_t>(id) < count; }

struct Counts {
  std::size_t particles = 0;
  std::size_t walls = 0;
  std::size_t contacts = 0;
  std::size_t materials = 0;
};

template <int Dim>
void check_settings(Problems& problems, const proto::SnapshotSettings& s, const Counts& n) {
  for (int i = 0; i < s.contact_model_size(); ++i) {
    const auto& c = s.contact_model(i);
    const bool default_law = c.material_a() == kInvalidId && c.material_b() == kInvalidId;
    if (!default_law && (!in_range(c.material_a(), n.materials) || !in_range(c.material_b(), n.materials))) {
      problems.add("settings.contact_model[" + std::to_string(i) + "]",
                   "material ids (" + std::to_string(c.material_a()) + ", " + std::to_string(c.material_b()) +
                       ") out of range for " + std::to_string(n.materials) + " materials");
    }
  }
  check_array(problems, "settings.gravity", s.gravity(), 1, Dim);
  check_length(problems, "settings.periodic_axes", s.periodic_axes(), Dim);
  check_array(problems, "settings.periodic_min", s.periodic_min(), 1, Dim);
  check_array(problems, "settings.periodic_max", s.periodic_max(), 1, Dim);
  check_finite(problems, "settings.time_step_fraction", s.time_step_fraction());
  check_finite(problems, "settings.fixed_time_step", s.fixed_time_step());
  check_finite(problems, "settings.contact_tolerance", s.contact_tolerance());
}

template <int Dim>
void check_particles(Problems& problems, const proto::SnapshotParticles& p, const Counts& n) {
  check_array(problems, "particles.position", p.position(), n.particles, Dim);
  check_array(problems, "particles.velocity", p.velocity(), n.particles, Dim);
  check_array(problems, "particles.angular_velocity", p.angular_velocity(), n.particles, width<Spin<Dim>>);
  check_array(problems, "particles.rotation", p.rotation(), n.particles, width<Orientation<Dim>>);
  check_array(problems, "particles.force", p.force(), n.particles, Dim);
  check_array(problems, "particles.moment", p.moment(), n.particles, width<Spin<Dim>>);
  check_array(problems, "particles.shape", p.shape(), n.particles, kShapeWidth<Dim>);
  if (!check_length(problems, "particles.material", p.material(), n.particles)) return;
  for (int i = 0; i < p.radius_size(); ++i) {
    if (!(p.radius(i) > 0.0) || !std::isfinite(p.radius(i))) {
      problems.add("particles.radius[" + std::to_string(i) + "]", "must be a finite number > 0");
    }
    if (!in_range(p.material(i), n.materials)) {
      problems.add("particles.material[" + std::to_string(i) + "]", "material " + std::to_string(p.material(i)) +
                                                                        " out of range for " +
                                                                        std::to_string(n.materials) + " materials");
    }
  }
}

template <int Dim>
void check_wall(Problems& problems, const proto::SnapshotWall& w, int index, const Counts& n) {
  const std::string path = "wall[" + std::to_string(index) + "]";
  const std::size_t spin = width<Spin<Dim>>;
  for (const auto& [name, values, item_width] :
       {std::tuple{"point", &w.point(), std::size_t{Dim}},
        {"direction", &w.direction(), std::size_t{Dim}},
        {"direction2", &w.direction2(), std::size_t{Dim == 3 ? 3u : 0u}},
        {"velocity", &w.velocity(), std::size_t{Dim}},
        {"angular_velocity", &w.angular_velocity(), spin},
        {"initial_point", &w.initial_point(), std::size_t{Dim}},
        {"last_velocity", &w.last_velocity(), std::size_t{Dim}},
        {"last_angular_velocity", &w.last_angular_velocity(), spin},
        {"force", &w.force(), std::size_t{Dim}},
        {"moment", &w.moment(), spin},
        {"normal_force_arm", &w.normal_force_arm(), width<Eccentricity<Dim>>}}) {
    check_array(problems, path + "." + name, *values, 1, item_width);
  }
  if (!in_range(w.material(), n.materials)) {
    problems.add(path + ".material", "material " + std::to_string(w.material()) + " out of range");
  }
  const int per_face = Dim == 3 ? 9 : 1;
  if (Dim == 2 && w.triangles_size() > 0) problems.add(path + ".triangles", "a 2D wall has no triangle faces");
  if (Dim == 3) {
    check_array(problems, path + ".triangles", w.triangles(), static_cast<std::size_t>(w.triangles_size() / per_face),
                static_cast<std::size_t>(per_face));
  }
  for (const auto& [name, value] :
       {std::pair{"h1", w.h1()}, {"h2", w.h2()}, {"k1", w.k1()}, {"k2", w.k2()}, {"normal_force", w.normal_force()}}) {
    check_finite(problems, path + "." + name, value);
  }
}

template <int Dim>
void check_contacts(Problems& problems, const proto::SnapshotContacts& c, const Counts& n) {
  bool sizes = check_length(problems, "contacts.second", c.second(), n.contacts);
  sizes = check_length(problems, "contacts.with_wall", c.with_wall(), n.contacts) && sizes;
  sizes = check_length(problems, "contacts.sliding", c.sliding(), n.contacts) && sizes;
  sizes = check_length(problems, "contacts.formed_cycle", c.formed_cycle(), n.contacts) && sizes;
  sizes = check_length(problems, "contacts.touching", c.touching(), n.contacts) && sizes;
  sizes = check_length(problems, "contacts.mindlin_unloading", c.mindlin_unloading(), n.contacts) && sizes;
  sizes = check_length(problems, "contacts.mindlin_reloading", c.mindlin_reloading(), n.contacts) && sizes;
  sizes = check_length(problems, "contacts.has_search", c.has_search(), n.contacts) && sizes;
  const std::size_t shear = width<ShearForce<Dim>>;
  const std::size_t spin = width<Spin<Dim>>;
  for (const auto& [name, values, item_width] : {std::tuple{"normal_force", &c.normal_force(), std::size_t{1}},
                                                 {"shear_force", &c.shear_force(), shear},
                                                 {"overlap", &c.overlap(), std::size_t{1}},
                                                 {"normal_damping", &c.normal_damping(), std::size_t{1}},
                                                 {"shear_damping", &c.shear_damping(), shear},
                                                 {"normal", &c.normal(), std::size_t{Dim}},
                                                 {"point", &c.point(), std::size_t{Dim}},
                                                 {"force", &c.force(), std::size_t{Dim}},
                                                 {"moment_first", &c.moment_first(), spin},
                                                 {"moment_second", &c.moment_second(), spin},
                                                 {"mindlin_direction", &c.mindlin_direction(), std::size_t{1}},
                                                 {"mindlin_t_star", &c.mindlin_t_star(), std::size_t{1}},
                                                 {"mindlin_t_star2", &c.mindlin_t_star2(), std::size_t{1}},
                                                 {"mindlin_lag", &c.mindlin_lag(), std::size_t{1}},
                                                 {"mindlin_axis", &c.mindlin_axis(), std::size_t{Dim}},
                                                 {"dashpot_force", &c.dashpot_force(), std::size_t{Dim}},
                                                 {"relative_velocity", &c.relative_velocity(), std::size_t{Dim}},
                                                 {"search_first", &c.search_first(), std::size_t{1}},
                                                 {"search_second", &c.search_second(), std::size_t{1}}}) {
    sizes = check_array(problems, std::string("contacts.") + name, *values, n.contacts, item_width) && sizes;
  }
  // Added after version 1 was first written: empty in older snapshots.
  for (const auto& [name, values, item_width] : {std::tuple{"mindlin_theta", &c.mindlin_theta(), std::size_t{1}},
                                                 {"tangential_spring", &c.tangential_spring(), std::size_t{Dim}},
                                                 {"rolling_torque", &c.rolling_torque(), spin}}) {
    if (values->size() > 0) {
      sizes = check_array(problems, std::string("contacts.") + name, *values, n.contacts, item_width) && sizes;
    }
  }
  if (!sizes) return;
  for (int i = 0; i < c.first_size(); ++i) {
    const std::string path = "contacts[" + std::to_string(i) + "]";
    if (!in_range(c.first(i), n.particles)) {
      problems.add(path + ".first", "particle " + std::to_string(c.first(i)) + " out of range");
    }
    if (!in_range(c.second(i), c.with_wall(i) ? n.walls : n.particles)) {
      problems.add(path + ".second",
                   std::string(c.with_wall(i) ? "wall " : "particle ") + std::to_string(c.second(i)) + " out of range");
    }
  }
}

template <int Dim>
void check(const proto::Snapshot& m, Problems& problems, const ResourceLimits& limits) {
  if (m.format() != kSnapshotFormat) {
    problems.add("format", "is \"" + m.format() + "\", not \"" + kSnapshotFormat + "\": not a dem snapshot");
    return;  // nothing else can be trusted
  }
  if (m.version() != kSnapshotVersion) {
    problems.add("version", std::to_string(m.version()) + " is not supported (this program reads version " +
                                std::to_string(kSnapshotVersion) + ")");
    return;
  }
  if (m.dimension() != Dim) {
    problems.add("dimension",
                 "the snapshot is " + std::to_string(m.dimension()) + "D, expected " + std::to_string(Dim) + "D");
    return;
  }
  for (const auto& [path, message] : snapshot_value_problems(m, limits)) problems.add(path, message);
  Counts n;
  n.particles = static_cast<std::size_t>(m.particles().radius_size());
  n.walls = static_cast<std::size_t>(m.wall_size());
  n.contacts = static_cast<std::size_t>(m.contacts().first_size());
  n.materials = static_cast<std::size_t>(m.settings().material_size());
  check_settings<Dim>(problems, m.settings(), n);
  check_particles<Dim>(problems, m.particles(), n);
  for (int i = 0; i < m.wall_size(); ++i) check_wall<Dim>(problems, m.wall(i), i, n);
  check_contacts<Dim>(problems, m.contacts(), n);
  for (const auto& [name, value] : {std::pair{"energy.initial_kinetic", m.energy().initial_kinetic()},
                                    {"energy.gravity_work", m.energy().gravity_work()},
                                    {"energy.wall_work", m.energy().wall_work()},
                                    {"energy.kinetic", m.energy().kinetic()},
                                    {"energy.strain", m.energy().strain()},
                                    {"energy.contact_damping", m.energy().contact_damping()},
                                    {"energy.friction", m.energy().friction()},
                                    {"energy.global_damping", m.energy().global_damping()},
                                    {"energy.local_damping", m.energy().local_damping()},
                                    {"energy.removed", m.energy().removed()},
                                    {"tangential_work", m.tangential_work()}}) {
    check_finite(problems, name, value);
  }
  if (m.reference_positions_size() > 0) {
    check_array(problems, "reference_positions", m.reference_positions(), n.particles, Dim);
  }
  if (m.has_box_control()) {
    const proto::SnapshotBoxControl& box = m.box_control();
    if (box.axis_size() != Dim) {
      problems.add("box_control.axis",
                   "has " + std::to_string(box.axis_size()) + " axes, expected " + std::to_string(Dim));
    }
    for (int i = 0; i < box.axis_size(); ++i) {
      const std::string path = "box_control.axis[" + std::to_string(i) + "]";
      if (!in_range(box.axis(i).lower(), n.walls)) problems.add(path + ".lower", "names no wall");
      if (!in_range(box.axis(i).upper(), n.walls)) problems.add(path + ".upper", "names no wall");
      if (box.axis(i).control() < 0 || box.axis(i).control() > 2) problems.add(path + ".control", "must be 0, 1 or 2");
    }
    if (box.path() < 0 || box.path() > 2) problems.add("box_control.path", "must be 0, 1 or 2");
    check_length(problems, "box_control.reference_extent", box.reference_extent(), Dim);
  }
  if (m.particle_order_size() > 0) {
    if (static_cast<std::size_t>(m.particle_order_size()) != n.particles) {
      problems.add("particle_order", "has " + std::to_string(m.particle_order_size()) + " entries for " +
                                         std::to_string(n.particles) + " particles");
    } else {
      std::vector<bool> seen(n.particles, false);
      for (int i = 0; i < m.particle_order_size(); ++i) {
        const std::int32_t id = m.particle_order(i);
        if (!in_range(id, n.particles) || seen[static_cast<std::size_t>(id)]) {
          problems.add("particle_order[" + std::to_string(i) + "]", "is not a permutation of the particle ids");
          break;
        }
        seen[static_cast<std::size_t>(id)] = true;
      }
    }
  }
  check_finite(problems, "particle_travel", m.particle_travel());
  check_finite(problems, "wall_travel", m.wall_travel());
  check_finite(problems, "time", m.time());
  if (!(m.time_step() > 0.0) || !std::isfinite(m.time_step())) problems.add("time_step", "must be a finite number > 0");
  check_finite(problems, "critical_time_step", m.critical_time_step());
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
    c.material_a = model.material_a();
    c.material_b = model.material_b();
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
    particle.material = p.material(i);
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
  wall.material = w.material();
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

template <int Dim>
void get_contacts(const proto::SnapshotContacts& c, WorldSnapshotT<Dim>& s) {
  s.contacts.reserve(static_cast<std::size_t>(c.first_size()));
  for (int i = 0; i < c.first_size(); ++i) {
    ContactSnapshotT<Dim> contact;
    contact.first = c.first(i);
    contact.second = c.second(i);
    contact.with_wall = c.with_wall(i);
    contact.normal_force = c.normal_force(i);
    contact.shear_force = get<ShearForce<Dim>>(c.shear_force(), i);
    contact.sliding = c.sliding(i);
    contact.overlap = c.overlap(i);
    contact.normal_damping = c.normal_damping(i);
    contact.shear_damping = get<ShearForce<Dim>>(c.shear_damping(), i);
    contact.normal = get<Vec<Dim>>(c.normal(), i);
    contact.point = get<Vec<Dim>>(c.point(), i);
    contact.force = get<Vec<Dim>>(c.force(), i);
    contact.moment_first = get<Spin<Dim>>(c.moment_first(), i);
    contact.moment_second = get<Spin<Dim>>(c.moment_second(), i);
    contact.formed_cycle = c.formed_cycle(i);
    contact.touching = c.touching(i);
    contact.mindlin = MindlinHistory{c.mindlin_direction(i), c.mindlin_unloading(i), c.mindlin_reloading(i),
                                     c.mindlin_t_star(i),    c.mindlin_t_star2(i),   c.mindlin_lag(i)};
    contact.mindlin_axis = get<Vec<Dim>>(c.mindlin_axis(), i);
    if (c.mindlin_theta_size() > 0) contact.mindlin_theta = c.mindlin_theta(i);
    contact.dashpot_force = get<Vec<Dim>>(c.dashpot_force(), i);
    if (c.tangential_spring_size() > 0) contact.tangential_spring = get<Vec<Dim>>(c.tangential_spring(), i);
    contact.relative_velocity = get<Vec<Dim>>(c.relative_velocity(), i);
    contact.search_first = c.search_first(i);
    contact.search_second = c.search_second(i);
    contact.has_search = c.has_search(i);
    if (c.rolling_torque_size() > 0) contact.rolling_torque = get<Spin<Dim>>(c.rolling_torque(), i);
    s.contacts.push_back(contact);
  }
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
  put_contacts(s.contacts, *m.mutable_contacts());
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
  for (ParticleId id : s.particle_order) m.add_particle_order(id);
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
  check<Dim>(m, problems, limits);
  if (!problems.empty()) throw SnapshotError(problems.text());

  WorldSnapshotT<Dim> s;
  get_settings(m.settings(), s.def);
  get_particles(m.particles(), s);
  for (const proto::SnapshotWall& w : m.wall()) get_wall(w, s);
  if (m.has_box_control()) s.def.box_control = get_box_control<Dim>(m.box_control());
  get_contacts(m.contacts(), s);
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
  s.particle_order.assign(m.particle_order().begin(), m.particle_order().end());
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
