#include <algorithm>
#include <cmath>

#include "tangential.h"
#include "world_state.h"

namespace dem {

namespace {

template <int Dim>
ContactRecordT<Dim> to_record(const ContactState<Dim>& s, ParticleId first) {
  ContactRecordT<Dim> r;
  r.first = first;
  r.point = s.point;
  r.normal = s.normal;
  r.overlap = s.overlap;
  r.normal_force = s.normal_force;
  r.shear_force = reported_shear(s.shear);
  r.tangential_force = -shear_vector(s.shear, s.normal);
  r.normal_damping = s.normal_damping;
  r.shear_damping = reported_shear(s.shear_damping);
  r.sliding = s.sliding;
  r.formed_cycle = s.formed_cycle;
  return r;
}

template <int Dim>
double magnitude(const ContactState<Dim>& s) {
  return std::hypot(s.normal_force, shear_magnitude(s.shear));
}

}  // namespace

// Elastic energy held in one contact's springs: linear 1/2 F^2 / k; Hertz
// normal 2/5 N alpha (the integral of Randall 3.13), tangential at the
// initial stiffness 8 G* a, 1/2 T^2 / (8 G* a).
struct Strain {
  double normal = 0.0, tangential = 0.0;
};

template <int Dim>
Strain strain_energy(ContactLaw law, const ContactState<Dim>& c, const ContactParams& p, double effective_radius) {
  const double shear = shear_magnitude(c.shear);
  if (law == ContactLaw::kLinear || law == ContactLaw::kLinearRestitution) {
    return {p.normal_stiffness > 0.0 ? 0.5 * c.normal_force * c.normal_force / p.normal_stiffness : 0.0,
            p.shear_stiffness > 0.0 ? 0.5 * shear * shear / p.shear_stiffness : 0.0};
  }
  const double tangential_stiffness = 8.0 * p.shear_modulus * std::sqrt(effective_radius * c.overlap);
  return {0.4 * c.normal_force * c.overlap,
          tangential_stiffness > 0.0 ? 0.5 * shear * shear / tangential_stiffness : 0.0};
}

template <int Dim>
AssemblyMeasures measure_assembly(const WorldState<Dim>& s) {
  const Particles<Dim>& p = s.particles;
  AssemblyMeasures m;
  double max_resultant = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    m.kinetic_energy += 0.5 * p.mass[i] * p.velocity[i].squaredNorm() +
                        0.5 * p.spin_energy_product(i, p.angular_velocity[i]);
    max_resultant = std::max(max_resultant, (p.force[i] + p.mass[i] * s.gravity).norm());
  }
  auto count = [&](const ContactState<Dim>& c) {
    if (!c.touching) return;
    ++m.contacts;
    if (c.sliding) ++m.sliding_contacts;
    m.max_contact_force = std::max(m.max_contact_force, magnitude(c));
  };
  Strain strain;
  auto hold = [&](const Strain& held) {
    strain.normal += held.normal;
    strain.tangential += held.tangential;
  };
  for (const PairContact<Dim>& c : s.contacts.pairs) {
    count(c.state);
    if (!c.state.touching) continue;
    const double rx = p.radius[c.first], ry = p.radius[c.second];
    hold(strain_energy(s.pair_law, c.state, s.params(p.material[c.first], p.material[c.second]), rx * ry / (rx + ry)));
  }
  for (const WallContact<Dim>& c : s.contacts.walls) {
    count(c.state);
    if (!c.state.touching) continue;
    hold(strain_energy(s.wall_law, c.state, s.params(p.material[c.particle], s.walls.def[c.wall].material),
                       p.radius[c.particle]));
  }
  m.time_step_ratio = s.time_step_ratio;
  m.energy = s.energy;
  m.energy.kinetic = m.kinetic_energy;
  m.energy.strain = strain.normal + strain.tangential;
  // What the tangential springs took and do not hold was lost to sliding
  // and micro-slip (the Mindlin hysteresis).
  m.energy.friction = s.tangential_work - strain.tangential;
  // Cundall & Strack Table 1 note 2: largest force sum on any particle over
  // the largest contact force.
  if (m.max_contact_force > 0.0) m.out_of_balance = max_resultant / m.max_contact_force;
  return m;
}

template <int Dim>
std::vector<ContactRecordT<Dim>> list_contacts(const WorldState<Dim>& s) {
  std::vector<ContactRecordT<Dim>> records;
  for (const PairContact<Dim>& c : s.contacts.pairs) {
    if (!c.state.touching) continue;
    records.push_back(to_record(c.state, c.first));
    records.back().second_particle = c.second;
  }
  for (const WallContact<Dim>& c : s.contacts.walls) {
    if (!c.state.touching) continue;
    records.push_back(to_record(c.state, c.particle));
    records.back().second_wall = c.wall;
  }
  return records;
}

template <int Dim>
std::optional<ContactRecordT<Dim>> find_pair_contact(const WorldState<Dim>& s, ParticleId a, ParticleId b) {
  const ParticleId first = std::min(a, b), second = std::max(a, b);
  const auto& pairs = s.contacts.pairs;
  const auto it = std::lower_bound(pairs.begin(), pairs.end(), std::pair{first, second},
                                   [](const PairContact<Dim>& c, const std::pair<ParticleId, ParticleId>& key) {
                                     return c.first < key.first || (c.first == key.first && c.second < key.second);
                                   });
  if (it == pairs.end() || it->first != first || it->second != second || !it->state.touching) return std::nullopt;
  ContactRecordT<Dim> r = to_record(it->state, first);
  r.second_particle = second;
  return r;
}

template AssemblyMeasures measure_assembly(const WorldState<2>&);
template AssemblyMeasures measure_assembly(const WorldState<3>&);
template std::vector<ContactRecordT<2>> list_contacts(const WorldState<2>&);
template std::vector<ContactRecordT<3>> list_contacts(const WorldState<3>&);
template std::optional<ContactRecordT<2>> find_pair_contact(const WorldState<2>&, ParticleId, ParticleId);
template std::optional<ContactRecordT<3>> find_pair_contact(const WorldState<3>&, ParticleId, ParticleId);

}  // namespace dem
