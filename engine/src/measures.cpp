#include <algorithm>
#include <cmath>
#include <limits>

#include "contact_forces.h"
#include "dem/law_traits.h"
#include "quasi_static.h"
#include "tangential.h"
#include "world_state.h"

namespace dem {

namespace {

// Elastic energy held in one contact's springs: linear 1/2 F^2 / k; Hertz
// normal 2/5 N alpha (the integral of Randall 3.13), tangential at the
// initial stiffness 8 G* a, 1/2 T^2 / (8 G* a).
struct Strain {
  double normal = 0.0, tangential = 0.0;
};

template <int Dim>
Strain strain_energy(bool hertz, const ContactRecordT<Dim>& c, const ContactParams& p, double effective_radius) {
  const double shear = c.tangential_force.norm();
  if (!hertz) {
    return {p.normal_stiffness > 0.0 ? 0.5 * c.normal_force * c.normal_force / p.normal_stiffness : 0.0,
            p.shear_stiffness > 0.0 ? 0.5 * shear * shear / p.shear_stiffness : 0.0};
  }
  const double tangential_stiffness = 8.0 * p.shear_modulus * std::sqrt(effective_radius * c.overlap);
  return {0.4 * c.normal_force * c.overlap,
          tangential_stiffness > 0.0 ? 0.5 * shear * shear / tangential_stiffness : 0.0};
}

}  // namespace

template <int Dim>
AssemblyMeasures measure_assembly(const WorldState<Dim>& s) {
  const Particles<Dim>& p = s.particles;
  AssemblyMeasures m;
  double max_resultant = 0.0;
  double resultants = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    m.kinetic_energy +=
        0.5 * p.mass[i] * p.velocity[i].squaredNorm() + 0.5 * p.spin_energy_product(i, p.angular_velocity[i]);
    const double resultant = (p.force[i] + p.mass[i] * body_acceleration(s, p.position[i])).norm();
    max_resultant = std::max(max_resultant, resultant);
    resultants += resultant;
  }
  Strain strain;
  double contact_forces = 0.0;
  const bool pair_hertz = is_hertz(s.pair_law), wall_hertz = is_hertz(s.wall_law);
  visit_touching_contacts<Dim>(s, [&](const ContactRecordT<Dim>& c) {
    ++m.contacts;
    if (c.second_particle != kInvalidId) ++m.particle_contacts;
    if (c.sliding) ++m.sliding_contacts;
    const double contact_force = std::hypot(c.normal_force, c.tangential_force.norm());
    m.max_contact_force = std::max(m.max_contact_force, contact_force);
    contact_forces += contact_force;
    const Slot x = p.slot_of(c.first);
    const double smaller =
        c.second_particle != kInvalidId ? std::min(p.radius[x], p.radius[p.slot_of(c.second_particle)]) : p.radius[x];
    m.deepest_overlap = std::max(m.deepest_overlap, c.overlap / smaller);
    double effective_radius = p.radius[x];
    Strain held;
    if (c.second_particle != kInvalidId) {
      const Slot y = p.slot_of(c.second_particle);
      effective_radius = p.radius[x] * p.radius[y] / (p.radius[x] + p.radius[y]);
      held = strain_energy(pair_hertz, c, s.params(p.material[x], p.material[y]), effective_radius);
    } else {
      held = strain_energy(wall_hertz, c, s.params(p.material[x], s.walls.def[c.second_wall.index()].material.value()),
                           effective_radius);
    }
    strain.normal += held.normal;
    strain.tangential += held.tangential;
  });
  m.time_step_ratio = s.time_step_ratio;
  m.energy = s.energy;
  m.energy.kinetic = m.kinetic_energy;
  m.energy.strain = strain.normal + strain.tangential;
  // What the tangential springs took and do not hold was lost to sliding
  // and micro-slip (the Mindlin hysteresis).
  if (s.energy_budget) m.energy.friction = s.tangential_work - strain.tangential;
  // Cundall & Strack Table 1 note 2: largest force sum on any particle over
  // the largest contact force.
  if (m.max_contact_force > 0.0) m.out_of_balance = max_resultant / m.max_contact_force;
  m.elastic_energy = m.energy.strain;
  if (m.elastic_energy > 0.0) {
    m.kinetic_to_elastic = m.kinetic_energy / m.elastic_energy;
  } else if (m.kinetic_energy > 0.0) {
    m.kinetic_to_elastic = std::numeric_limits<double>::infinity();
  }
  if (m.contacts > 0) {
    m.sliding_fraction = static_cast<double>(m.sliding_contacts) / m.contacts;
    if (contact_forces > 0.0) {
      m.unbalanced_force = (resultants / static_cast<double>(p.size())) / (contact_forces / m.contacts);
    }
  }
  m.mean_stress = mean_stress(s);
  m.deformation_rate = deformation_rate(p, s.periodic);
  m.inertial_number = inertial_number(m.deformation_rate, grain_scale(s), m.mean_stress);
  return m;
}

template AssemblyMeasures measure_assembly(const WorldState<2>&);
template AssemblyMeasures measure_assembly(const WorldState<3>&);

}  // namespace dem
