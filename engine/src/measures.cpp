#include <algorithm>
#include <cmath>

#include "dem/world.h"
#include "world_state.h"

namespace dem {

namespace {

ContactRecord to_record(const ContactState& s, ParticleId first) {
  ContactRecord r;
  r.first = first;
  r.point = s.point;
  r.normal = s.normal;
  r.overlap = s.overlap;
  r.normal_force = s.normal_force;
  r.shear_force = s.shear_force;
  r.normal_damping = s.normal_damping;
  r.shear_damping = s.shear_damping;
  r.sliding = s.sliding;
  return r;
}

double magnitude(const ContactState& s) { return std::hypot(s.normal_force, s.shear_force); }

}  // namespace

std::vector<WallMeasure> World::wall_measures() const {
  std::vector<WallMeasure> measures;
  for (WallId w = 0; w < wall_count(); ++w) measures.push_back(measure_wall(state_->walls, w));
  return measures;
}

AssemblyMeasures World::assembly_measures() const {
  const WorldState& s = *state_;
  const Particles& p = s.particles;
  AssemblyMeasures m;
  double max_resultant = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    m.kinetic_energy += 0.5 * p.mass[i] * p.velocity[i].squaredNorm() +
                        0.5 * p.inertia[i] * p.angular_velocity[i] * p.angular_velocity[i];
    max_resultant = std::max(max_resultant, (p.force[i] + p.mass[i] * s.gravity).norm());
  }
  auto count = [&](const ContactState& c) {
    if (!c.touching) return;
    ++m.contacts;
    if (c.sliding) ++m.sliding_contacts;
    m.max_contact_force = std::max(m.max_contact_force, magnitude(c));
  };
  for (const PairContact& c : s.contacts.pairs) count(c.state);
  for (const WallContact& c : s.contacts.walls) count(c.state);
  // Cundall & Strack Table 1 note 2: largest force sum on any disc over the
  // largest contact force.
  if (m.max_contact_force > 0.0) m.out_of_balance = max_resultant / m.max_contact_force;
  return m;
}

std::vector<ContactRecord> World::contacts() const {
  std::vector<ContactRecord> records;
  for (const PairContact& c : state_->contacts.pairs) {
    if (!c.state.touching) continue;
    records.push_back(to_record(c.state, c.first));
    records.back().second_particle = c.second;
  }
  for (const WallContact& c : state_->contacts.walls) {
    if (!c.state.touching) continue;
    records.push_back(to_record(c.state, c.particle));
    records.back().second_wall = c.wall;
  }
  return records;
}

std::optional<ContactRecord> World::contact_between(ParticleId a, ParticleId b) const {
  const ParticleId first = std::min(a, b), second = std::max(a, b);
  const auto& pairs = state_->contacts.pairs;
  const auto it = std::lower_bound(pairs.begin(), pairs.end(), std::pair{first, second},
                                   [](const PairContact& c, const std::pair<ParticleId, ParticleId>& key) {
                                     return c.first < key.first || (c.first == key.first && c.second < key.second);
                                   });
  if (it == pairs.end() || it->first != first || it->second != second || !it->state.touching) return std::nullopt;
  ContactRecord r = to_record(it->state, first);
  r.second_particle = second;
  return r;
}

}  // namespace dem
