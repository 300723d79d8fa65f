// What a World reports: per-wall resultants (Cundall & Strack Table 1),
// assembly measures, and a view of each contact. Written once over Dim; the
// 2D names are the Dim = 2 instances.
#pragma once

#include <cstdint>
#include <tuple>
#include <type_traits>

#include "dem/field_list.h"
#include "dem/ids.h"
#include "dem/math.h"

namespace dem {

// Position of the normal force's centre along the wall, relative to the
// wall's centre and divided by its half length: a scalar along a 2D
// segment, a pair (along u, along v) on a 3D rectangle.
template <int Dim>
using Eccentricity = std::conditional_t<Dim == 2, double, Eigen::Vector2d>;

// Eigen leaves vectors uninitialised by default: these are the zeros.
template <int Dim>
Eccentricity<Dim> zero_eccentricity() {
  if constexpr (Dim == 2) {
    return 0.0;
  } else {
    return Eigen::Vector2d::Zero();
  }
}

// The resultant the particles exert on one wall.
template <int Dim>
struct WallMeasureT {
  WallId wall = kInvalidId;
  Vec<Dim> force = Vec<Dim>::Zero();           // N (per unit depth for 2D discs): sum of contact forces on the wall
  Spin<Dim> moment = Space<Dim>::zero_spin();  // N m, about the wall's reference point P
  double normal_force = 0.0;                   // N, compressive component along the wall's normal
  int contacts = 0;                            // number of touching particles
  // Eccentricity of the normal force over the half length, e / (L/2)
  // (Cundall & Strack Table 1, note 1); 0 without contacts.
  Eccentricity<Dim> eccentricity = zero_eccentricity<Dim>();
  Vec<Dim> point = Vec<Dim>::Zero();         // current position of P, m
  Vec<Dim> displacement = Vec<Dim>::Zero();  // P's displacement since the world was built, m
};

// Where the energy went since the world was built, J (per unit depth for 2D
// discs). What came in (the initial kinetic energy, the work of the body
// forces - gravity and a centripetal field - of moving walls and of a box's
// continuum field) equals what is held (kinetic and elastic strain energy)
// plus what was dissipated, up to the residual, which measures the
// integration and contact-law errors.
struct EnergyBudget {
  double initial_kinetic = 0.0;
  double gravity_work = 0.0;  // work of the body forces: gravity and a centripetal field
  double wall_work = 0.0;     // work of the walls' motion on the particles
  // Work of a box's continuum field (BoxControlT::continuum, Randall 4.5.2)
  // on the particles it carries.
  double continuum_work = 0.0;
  double kinetic = 0.0;          // translation + rotation, at the last half step
  double strain = 0.0;           // elastic energy held in the contact springs now
  double contact_damping = 0.0;  // dissipated by contact dashpots
  double friction = 0.0;         // lost to sliding and micro-slip: work done on the tangential springs they do not hold
  double global_damping = 0.0;   // dissipated by global (mass-proportional) damping
  double local_damping = 0.0;    // dissipated by local non-viscous damping
  double removed = 0.0;          // held by particles and contacts when they were removed
  double residual() const {
    return initial_kinetic + gravity_work + wall_work + continuum_work -
           (kinetic + strain + contact_damping + friction + global_damping + local_damping + removed);
  }
};

struct AssemblyMeasures {
  double kinetic_energy = 0.0;  // J (per unit depth for 2D discs): translation + rotation
  // Largest resultant force on any particle over the largest contact force,
  // Delta F / F (Cundall & Strack Table 1, note 2); 0 without contacts.
  double out_of_balance = 0.0;
  double max_contact_force = 0.0;  // N
  int contacts = 0;                // touching particle-particle and particle-wall pairs
  int particle_contacts = 0;       // of which particle-particle: the coordination number is twice this over N
  int sliding_contacts = 0;        // those at the Coulomb limit (eq. 19)
  // Randall (1989) 4.35-4.40: the time step over the smallest particle-wise
  // critical step 2 (m dx / d|sum F|)^(1/2) seen in the last cycle. Above
  // 0.3 the step is too large for the stiffness the particles meet.
  double time_step_ratio = 0.0;
  // The deepest contact: its overlap over the smaller radius of its bodies
  // (a wall contact's: the particle's; shaped particles: the bounding
  // radius), for the health check (dem/health.h); 0 without contacts.
  double deepest_overlap = 0.0;
  // Quasi-static measures (docs/CASES.md): how far the assembly is from
  // the static equilibrium a slow test assumes (Miyata et al. 2002, 3.2:
  // "quasi-static behavior of the particles").
  double elastic_energy = 0.0;  // J: held in the contact springs (EnergyBudget::strain)
  // Kinetic over elastic energy: far below 1 when the springs, not the
  // motion, hold the energy; infinite with motion and no stored energy.
  double kinetic_to_elastic = 0.0;
  // Mean |sum F| over the particles (gravity included) over the mean contact
  // force: 0 in equilibrium (Ng 2006; Kruyt & Rothenburg); 0 without contacts.
  double unbalanced_force = 0.0;
  double sliding_fraction = 0.0;  // sliding_contacts / contacts; 0 without contacts
  // The Love-Weber mean stress over the volume the particles span, Pa
  // (per unit depth for 2D discs), compression positive.
  double mean_stress = 0.0;
  // The spread of the principal rates of the particles' best linear
  // velocity field (shear rate of a simple shear, strain rate of a uniaxial
  // compression), 1/s.
  double deformation_rate = 0.0;
  // I = deformation_rate d / sqrt(mean_stress / rho), d the mean
  // volume-equivalent diameter: quasi-static below about 1e-3 (GDR MiDi
  // 2004); infinite when a deforming assembly holds no stress.
  double inertial_number = 0.0;
  EnergyBudget energy;
};

// One touching contact. For a particle-wall contact, second_wall is set and
// second_particle is kInvalidId. The normal points from the first particle
// towards the second body (Cundall & Strack's e_i); forces follow the sign
// convention of Fig. 3 (positive normal force is compressive).
template <int Dim>
struct ContactRecordT {
  ParticleId first = kInvalidId;
  ParticleId second_particle = kInvalidId;
  WallId second_wall = kInvalidId;
  Vec<Dim> point = Vec<Dim>::Zero();   // m, halfway through the overlap
  Vec<Dim> normal = Vec<Dim>::Zero();  // e_i, unit
  double overlap = 0.0;                // m
  double normal_force = 0.0;           // F_n, N (spring part)
  // F_s, N (spring part): signed along t_i in 2D (Fig. 3), the magnitude in 3D.
  double shear_force = 0.0;
  // The spring's tangential force on the first particle (-F_s t_i in 2D).
  Vec<Dim> tangential_force = Vec<Dim>::Zero();
  double normal_damping = 0.0;     // D_n, N (eq. 26)
  double shear_damping = 0.0;      // D_s, N (eq. 27): signed in 2D, the magnitude in 3D
  bool sliding = false;            // |F_s| reached (F_s)max
  std::uint64_t formed_cycle = 0;  // the cycle the contact began touching
  // The whole force the pass applied to the first particle (springs and
  // dashpots); the second body received -force. The measures of a region
  // (stress, its normal and tangential parts) read it.
  Vec<Dim> force = Vec<Dim>::Zero();
};

// The one list of a contact record's fields, in the order tables and
// messages show them. The names are the fields' everywhere: the wire's
// ContactEntry (idl/dem/command.idl, filled field by field from this list
// in service/src/contact_entry.h, which fails to build while a record field
// has no wire field of its name or a wire field no record field),
// contacts.csv (io/src/csv_writers.cpp) and Python's contact array.
// Adding a field is a member above, a line below and, to send it, the
// IDL's field of the same name.
template <int Dim>
struct ContactRecordFields {
  using Record = ContactRecordT<Dim>;
  static constexpr auto list = std::make_tuple(
      Field{"first", &Record::first}, Field{"second_particle", &Record::second_particle},
      Field{"second_wall", &Record::second_wall}, Field{"point", &Record::point}, Field{"normal", &Record::normal},
      Field{"overlap", &Record::overlap}, Field{"normal_force", &Record::normal_force},
      Field{"shear_force", &Record::shear_force}, Field{"tangential_force", &Record::tangential_force},
      Field{"normal_damping", &Record::normal_damping}, Field{"shear_damping", &Record::shear_damping},
      Field{"sliding", &Record::sliding}, Field{"formed_cycle", &Record::formed_cycle}, Field{"force", &Record::force});
};

static_assert(lists_every_member<ContactRecordT<2>>(ContactRecordFields<2>::list),
              "ContactRecordT changed: give the new member its line in ContactRecordFields");
static_assert(lists_every_member<ContactRecordT<3>>(ContactRecordFields<3>::list),
              "ContactRecordT changed: give the new member its line in ContactRecordFields");

// The box of an element test (BoxControlT) as it stands: its extents, the
// stresses its walls carry and its strains since the control was set.
template <int Dim>
struct BoxMeasureT {
  Vec<Dim> extent = Vec<Dim>::Zero();  // m, the distance between each axis's two walls
  Vec<Dim> stress = Vec<Dim>::Zero();  // Pa, compression positive: each axis's walls' mean normal force over its face
  Vec<Dim> target =
      Vec<Dim>::Zero();  // Pa, the stress each stress-controlled or path axis is held at now (0 for strain-rate axes)
  // ln(reference / extent) per axis: compression positive, additive over stages.
  Vec<Dim> strain = Vec<Dim>::Zero();
  double volumetric_strain = 0.0;  // the sum of the axes' strains
  double deviator_strain = 0.0;    // the largest axis strain minus the smallest
  double mean_stress = 0.0;        // Pa, the mean of the axes' stresses
};

using WallMeasure = WallMeasureT<2>;
using WallMeasure3 = WallMeasureT<3>;
using BoxMeasure = BoxMeasureT<2>;
using BoxMeasure3 = BoxMeasureT<3>;
using ContactRecord = ContactRecordT<2>;
using ContactRecord3 = ContactRecordT<3>;

}  // namespace dem
