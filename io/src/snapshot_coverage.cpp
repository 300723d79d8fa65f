// Compile-time guards only: a snapshot must hold every field of the
// engine's definition and state structs, or a restored world would not
// continue bit for bit. The contact fields have their own list and guard
// (for_each_contact_field in dem/snapshot.h); the structs below are mirrored
// here, so the build fails when one grows.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dem/definitions.h"
#include "dem/snapshot.h"

namespace dem::io {

namespace {

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
  std::vector<ParticleId> particle_ids;
  std::int32_t particle_id_count;
  std::uint64_t sorted_cycle;
  EnergyBudget energy;
  double tangential_work;
  std::uint64_t cycle;
  double time, time_step, critical_time_step;
};
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

}  // namespace

}  // namespace dem::io
