// Typed definition structs that configure a World, each with documented units
// and defaults (the model: Box2D's b2WorldDef + b2DefaultWorldDef()). They
// are written once over the dimension; the 2D names (WorldDef, ParticleDef,
// ...) are the Dim = 2 instances, the 3D ones end in 3 (WorldDef3, ...).
//
// Units are SI throughout (m, kg, s, N, rad). BALL's unitless numbers work
// as they are: a case may use them consistently. 2D discs have unit
// thickness, so "mass density" is mass per unit area x 1 and forces are per
// unit depth (Cundall & Strack 1979).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dem/ids.h"
#include "dem/math.h"

namespace dem {

// A property type ("material") shared by particles or walls (Cundall &
// Strack, Input parameters). Walls use friction, cohesion and the elastic
// constants; density only matters for particles.
struct MaterialDef {
  std::string name;
  double density = 1000.0;      // kg/m^3 (per unit thickness for 2D discs); > 0 for particle materials
  double friction = 0.0;        // tan(phi_mu), the interparticle friction coefficient
  double cohesion = 0.0;        // c, N: shear strength at zero normal force (eq. 19)
  double youngs_modulus = 0.0;  // E, Pa: Hertz laws only (walls: 0 = rigid)
  double poisson_ratio = 0.0;   // nu: Hertz laws only
};

// BALL's linear springs (Cundall & Strack eqs. 16-17): contact stiffnesses.
struct LinearLawDef {
  double normal_stiffness = 1.0e9;  // k_n, N/m
  double shear_stiffness = 1.0e9;   // k_s, N/m
};

// The contact laws a pair of materials can use.
enum class ContactLaw {
  // BALL: incremental linear springs, Coulomb limit with cohesion, dashpots
  // c = beta k (Cundall & Strack eqs. 16-19, 26-28).
  kLinear,
  // Linear spring-dashpot whose normal dashpot gives a coefficient of
  // restitution, incremental shear spring with a Coulomb slider (Miyata
  // et al. 2002, eqs. 13-23).
  kLinearRestitution,
  // Hertz normal force (Randall 1989, 3.13 and 4.5-4.14) with the
  // Mindlin-Deresiewicz tangential law and its loading history (Randall
  // 3.94-3.98, coded as in 4.15-4.25).
  kHertzMindlin,
  // Hertz normal force with the linear-pressure-dependent tangential
  // stiffness k_s = 8 G* a (Miyata et al. 2002, eq. 31).
  kHertzLinearTangential,
};

// Damping of the Hertz laws. The normal dashpot is a fraction beta of the
// critical damping of the current normal stiffness 2 E* a (Randall 4.13):
// D = 2 beta sqrt(m* 2 E* a) n_dot. Given a coefficient of restitution e
// instead, beta = sqrt(5/6) |ln e| / sqrt(ln^2 e + pi^2), the form LIGGGHTS
// uses (../shared/bench/README.md).
struct HertzDampingDef {
  double damping_ratio = 0.0;         // beta, fraction of critical
  std::optional<double> restitution;  // e in (0, 1]; overrides damping_ratio when set
  // The same fraction of critical damping on the tangential stiffness
  // (Randall 4.19; optional there, as the Mindlin law dissipates already).
  bool tangential = false;
};

// Rolling resistance, an option of every law (Iwashita & Oda 1998; Ai et
// al. 2011, model C; engine/src/rolling_resistance.h): a spring of
// stiffness 2.25 k_n mu_r^2 R_r^2 on the bodies' relative rotation, its
// torque capped at mu_r R_r F_n, with a dashpot at a fraction of its
// critical damping while below the cap.
struct RollingResistanceDef {
  double friction = 0.0;       // mu_r, the coefficient of rolling friction (dimensionless); 0 = none
  double damping_ratio = 0.0;  // eta_r, fraction of the rolling spring's critical damping
};

// The contact law for one pair of materials (or for every pair not named
// elsewhere when both ids are kInvalidId). Friction and cohesion default to
// the smaller of the two materials' values (Cundall & Strack eq. 19 and its
// footnote 1); set them here to give a pair its own values. The Hertz laws
// take E and nu from the two materials (a wall material with E = 0 is rigid).
struct ContactModelDef {
  MaterialId material_a = kInvalidId;
  MaterialId material_b = kInvalidId;
  LinearLawDef linear;  // kLinear and kLinearRestitution
  std::optional<double> friction;
  std::optional<double> cohesion;
  ContactLaw law = ContactLaw::kLinear;
  double restitution = 1.0;      // kLinearRestitution: e in (0, 1] (Miyata eq. 17)
  HertzDampingDef hertz;         // kHertzMindlin and kHertzLinearTangential
  RollingResistanceDef rolling;  // any law
};

// Damping options. Contact damping c = beta * k (Cundall & Strack eq. 28)
// for the BALL law (the other laws carry their own dashpots). Global
// damping C = alpha m, C* = alpha I (Cundall & Strack eq. 34; Miyata eq. 32
// with its own rotational constant). Local non-viscous damping (Miyata eq.
// 33, as PFC does it): each component of the resultant force is reduced by
// alpha' times its magnitude against the velocity component, so the
// damping does not depend on the velocity's size and vanishes at rest.
struct DampingDef {
  double contact_beta = 0.0;                    // s
  double global_alpha = 0.0;                    // 1/s, translation (and rotation unless set below)
  std::optional<double> global_alpha_rotation;  // 1/s
  double local_alpha = 0.0;                     // dimensionless, in [0, 1)
  std::optional<double> local_alpha_rotation;   // dimensionless, in [0, 1)
};

// A particle's shape beyond its radius.
template <int Dim>
struct ShapeDefT;

// In 2D, a superquadric (Miyata et al. 2002, eq. 34): |x/a|^n + |y/b|^n = 1
// in the particle's own frame, turned by `angle`; 1 < n <= 10. With a = 0
// (the default) the particle is a disc (or a sphere in the plane) of its
// radius. A world's particles are all discs or all superquadrics.
template <>
struct ShapeDefT<2> {
  double a = 0.0;      // m, semi-axis along the local x axis
  double b = 0.0;      // m, semi-axis along the local y axis
  double n = 2.0;      // shape exponent
  double angle = 0.0;  // rad, of the local x axis, counter-clockwise
  bool superquadric() const { return a > 0.0; }
};

// In 3D, an ellipsoid (Miyata et al. 2002, eq. 43) with semi-axes a1, a2,
// a3 along its own axes, turned by `orientation`; with a1 = 0 (the default)
// the particle is a sphere of its radius. A world's particles are all
// spheres or all ellipsoids.
template <>
struct ShapeDefT<3> {
  Vec3 axes = Vec3::Zero();  // m
  Quaternion orientation = Quaternion::Identity();
  bool ellipsoid() const { return axes.x() > 0.0; }
};

template <int Dim>
struct ParticleDefT {
  Vec<Dim> position = Vec<Dim>::Zero();  // m
  double radius = 1.0;                   // m; a shaped particle's is its bounding radius, set from the shape
  MaterialId material{0};
  Vec<Dim> velocity = Vec<Dim>::Zero();                  // m/s
  Spin<Dim> angular_velocity = Space<Dim>::zero_spin();  // rad/s (2D: counter-clockwise positive)
  ShapeDefT<Dim> shape;
};

// A servo holds the normal force a wall carries at a target: the wall moves
// along its normal at gain * (target - measured), capped at max_speed
// (the servo-controlled plate of Randall 1989, 4.1).
struct ServoDef {
  double target_force = 0.0;  // N (per unit depth for 2D discs); compressive positive
  double gain = 0.0;          // m/(N s)
  double max_speed = 0.0;     // m/s, > 0
};

// How a wall moves: a velocity of its reference point P and an angular
// velocity about P (Cundall & Strack, Fig. 4), or a servo along its normal.
template <int Dim>
struct WallMotionT {
  Vec<Dim> velocity = Vec<Dim>::Zero();                  // m/s
  Spin<Dim> angular_velocity = Space<Dim>::zero_spin();  // rad/s
  std::optional<ServoDef> servo;                         // when set, replaces velocity/angular_velocity
};

template <int Dim>
struct WallDefT;

// A 2D wall is the segment of the line through P with unit direction e
// between P + h1 e and P + h2 e (Cundall & Strack, Fig. 4). Its normal is e
// rotated counter-clockwise: particles are expected on that side, which
// fixes the sign of the wall's normal force and the direction a servo pushes.
template <>
struct WallDefT<2> {
  std::string name;
  Vec2 point = Vec2::Zero();       // P, m
  Vec2 direction = Vec2::UnitX();  // e, unit vector
  double h1 = 0.0;                 // m, h1 < h2
  double h2 = 1.0;                 // m
  MaterialId material{0};
  WallMotionT<2> motion;
  // Taken out of the world (BasicWorld::remove_wall: a hopper's orifice
  // opened, Randall 1989, 6.2): it keeps its id but touches nothing.
  bool removed = false;
};

// A 3D wall is the rectangle P + s u + t v, h1 <= s <= h2, k1 <= t <= k2,
// with u and v orthonormal. Its normal is u x v: particles are expected on
// that side. Or it is built of triangle faces (Miyata et al. 2002, 2.4),
// which then replace the rectangle and move with the wall; P, u and v still
// give its frame, normal and eccentricities. A particle touches such a wall
// at one point, its nearest (deepest) face: faces should form a convex
// surface (a plate, a footing); a box is built of separate walls.
template <>
struct WallDefT<3> {
  std::string name;
  Vec3 point = Vec3::Zero();       // P, m
  Vec3 direction = Vec3::UnitX();  // u, unit vector
  double h1 = 0.0;                 // m, h1 < h2
  double h2 = 1.0;
  Vec3 direction2 = Vec3::UnitY();  // v, unit vector perpendicular to u
  double k1 = 0.0;                  // m, k1 < k2
  double k2 = 1.0;
  MaterialId material{0};
  WallMotionT<3> motion;
  std::vector<std::array<Vec3, 3>> triangles;  // m, vertices where they stand now
  bool removed = false;                        // taken out of the world: keeps its id, touches nothing
};

// Element-test control of a box of walls (a biaxial or triaxial cell): two
// walls per axis, the lower one facing +axis and the upper one -axis, each
// axis driven by a strain rate or held at a stress. Strains and stresses
// are compression positive; the box's extent along an axis is the distance
// between its two walls, and an axis's stress is the mean normal force of
// its walls over the face the other extents span (2D: times the depth).
//
// A strain rate moves the two walls towards each other at rate x extent / 2
// each, so the box deforms at that rate along its axes: the boundary
// strain-rate tensor of Randall (1989) 4.5.2, in its principal axes. With
// rates e and -e on two axes of a 2D box its area stays constant (to
// second order in e dt per step): the constant-volume shear of Randall
// 6.5.2. A stress target servos both walls of the axis: each moves inwards
// at gain x (target - stress), capped at max_speed (the servo-controlled
// boundary of 4.1). A stress path sets the targets of the axes that follow
// it from the other axes' measured stresses every cycle: a constant mean
// stress p holds the mean of all axes at p; a stress ratio R holds those
// axes at sigma_1 / R, sigma_1 the largest stress of the other axes.
enum class AxisControl { kStrainRate, kStress, kStressPath };
enum class StressPath { kNone, kConstantMeanStress, kStressRatio };

struct BoxAxisDef {
  WallId lower = kInvalidId;  // faces +axis
  WallId upper = kInvalidId;  // faces -axis
  AxisControl control = AxisControl::kStrainRate;
  double strain_rate = 0.0;  // 1/s, compression positive (kStrainRate)
  double stress = 0.0;       // Pa, compression positive (kStress)
};

template <int Dim>
struct BoxControlT {
  std::array<BoxAxisDef, Dim> axes;
  StressPath path = StressPath::kNone;
  double path_value = 0.0;  // kConstantMeanStress: p, Pa; kStressRatio: sigma_1 / sigma_3 >= 1
  double gain = 0.0;        // m/(s Pa), > 0 when an axis is stress-controlled
  double max_speed = 0.0;   // m/s, > 0 when an axis is stress-controlled
  // The box's extents when the control was set: its strains count from
  // there. Left at zero, BasicWorld::set_box_control fills them in.
  Vec<Dim> reference_extent = Vec<Dim>::Zero();
  // The particles follow the box's deformation too (Randall 1989, 4.5.2,
  // eqs. 4.41-4.44, after Cundall 1988): each moves with the homogeneous
  // velocity field of the box's axis rates about the box's centre, added
  // to its own velocity, which the law of motion integrates from its
  // forces (and damps) as a perturbation of that field; the contacts see
  // the field's relative velocity e_ij z_j. The walls carry the same rates
  // (Randall's "boundary strain rate tensor of equal magnitude"). Not with
  // periodic boundaries.
  bool continuum = false;
};

// The continuum field a box with `continuum` laid over the particles in
// the last step: the velocity rate_i (x_i - centre_i) along each axis (a
// velocity gradient in the box's axes, extension positive; Randall's
// e_ij, eqs. 4.43-4.44), about the box's centre.
template <int Dim>
struct ContinuumFieldT {
  Vec<Dim> rate = Vec<Dim>::Zero();    // 1/s
  Vec<Dim> centre = Vec<Dim>::Zero();  // m
  Vec<Dim> velocity(const Vec<Dim>& x) const { return rate.cwiseProduct(x - centre); }
};

// A centripetal gravity field (Randall 1989, 6.4.2: "a centripetal gravity
// field ... all the particles would travel together towards the centre"):
// every particle is pulled towards `centre` at `acceleration`, however far
// it is (and not at all at the centre itself). A body force like gravity:
// its work is booked with gravity's.
template <int Dim>
struct CentripetalGravityT {
  Vec<Dim> centre = Vec<Dim>::Zero();  // m
  double acceleration = 0.0;           // m/s^2, >= 0
  // The acceleration of a particle at x.
  Vec<Dim> at(const Vec<Dim>& x) const {
    const Vec<Dim> inwards = centre - x;
    const double distance = inwards.norm();
    return distance > 0.0 ? Vec<Dim>(inwards * (acceleration / distance)) : Vec<Dim>::Zero();
  }
};

// The body forces per unit mass a stage sets (gravity and the centripetal
// field, either or both).
template <int Dim>
struct BodyForceT {
  Vec<Dim> gravity = Vec<Dim>::Zero();  // m/s^2
  std::optional<CentripetalGravityT<Dim>> centripetal;
};

// Periodic boundaries (Miyata et al. 2002; Cundall's periodic cell): along
// each axis that is periodic, the domain [min, max) repeats, particles that
// leave one side enter the other, and pairs interact across the boundary
// through their nearest images. Walls do not repeat; a wall that spans a
// periodic axis has its stress taken over the period along it.
template <int Dim>
struct PeriodicDefT {
  std::array<bool, Dim> axes{};     // which axes repeat
  Vec<Dim> min = Vec<Dim>::Zero();  // m, the periodic cell along those axes
  Vec<Dim> max = Vec<Dim>::Zero();  // m
  bool any() const {
    for (bool a : axes) {
      if (a) return true;
    }
    return false;
  }
};

// What a particle is in the plane: a disc of unit thickness (Cundall &
// Strack) or a sphere whose centre lies in the plane (Randall 1989, 4.4).
enum class PlanarParticle { kDisc, kSphere };

template <int Dim>
struct WorldDefT {
  std::vector<MaterialDef> materials;
  std::vector<ContactModelDef> contact_models;
  std::vector<ParticleDefT<Dim>> particles;
  std::vector<WallDefT<Dim>> walls;
  PeriodicDefT<Dim> periodic;
  std::optional<BoxControlT<Dim>> box_control;  // element-test control of a box of the walls
  DampingDef damping;
  Vec<Dim> gravity = Vec<Dim>::Zero();                          // m/s^2, body force per unit mass
  std::optional<CentripetalGravityT<Dim>> centripetal_gravity;  // Randall 6.4.2; none when absent
  // 2D only: discs or spheres in the plane (3D particles are spheres).
  PlanarParticle planar_particle = PlanarParticle::kDisc;
  // The time step is time_step_fraction times the critical step 2 sqrt(m/k)
  // estimated from the particles and contact models, unless fixed_time_step > 0.
  double time_step_fraction = 0.1;
  double fixed_time_step = 0.0;  // s; 0 = use the fraction of the critical step
  // Pairs closer than this gap are kept in the contact table (BALL's TOL), so
  // the neighbour search only runs when something moved more than half of it.
  // 0 = a tenth of the mean particle radius.
  double contact_tolerance = 0.0;  // m
  int threads = 0;                 // 0 = OMP_NUM_THREADS if set, else all the machine's cores
  // Keep the energy budget (EnergyBudget: work of gravity, walls, dashpots,
  // friction, damping). It costs a little on every contact and particle in
  // every cycle, so a world keeps it only when asked.
  bool energy_budget = false;
};

using ParticleDef = ParticleDefT<2>;
using ParticleDef3 = ParticleDefT<3>;
using WallMotion = WallMotionT<2>;
using WallMotion3 = WallMotionT<3>;
using WallDef = WallDefT<2>;
using WallDef3 = WallDefT<3>;
using WorldDef = WorldDefT<2>;
using WorldDef3 = WorldDefT<3>;
using PeriodicDef = PeriodicDefT<2>;
using PeriodicDef3 = PeriodicDefT<3>;
using BoxControl = BoxControlT<2>;
using BoxControl3 = BoxControlT<3>;
using CentripetalGravity = CentripetalGravityT<2>;
using CentripetalGravity3 = CentripetalGravityT<3>;
using BodyForce = BodyForceT<2>;
using BodyForce3 = BodyForceT<3>;

// A definition with one "default" material and a default contact model for
// every pair, for programs that build worlds in code. Case conversion starts
// from an empty WorldDef instead, so material ids follow the case.
WorldDef default_world_def();

}  // namespace dem
