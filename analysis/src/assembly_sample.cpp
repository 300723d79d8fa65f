#include "dem/analysis/assembly_sample.h"

#include <algorithm>
#include <cmath>

namespace dem::analysis {

template <int Dim>
AssemblySampleT<Dim> sample(const BasicWorld<Dim>& world) {
  AssemblySampleT<Dim> s;
  const auto p = world.particles();
  const auto n = static_cast<std::size_t>(world.particle_count());
  s.position.reserve(n);
  s.radius.reserve(n);
  s.rotation.reserve(n);
  for (const ParticleId i : world.particle_ids()) {
    s.position.push_back(p.position[i]);
    s.radius.push_back(p.radius[i]);
    if constexpr (Dim == 2) {
      s.rotation.push_back(p.rotation[i]);
    } else {
      s.rotation.push_back(2.0 * std::acos(std::min(1.0, std::abs(p.rotation[i].w()))));
    }
  }
  const std::span<const ParticleId> ids = world.particle_ids();
  s.ids.assign(ids.begin(), ids.end());
  // Each id's position in the sample (the ids ascend, with gaps after a trim).
  std::vector<std::int32_t> position(static_cast<std::size_t>(world.particle_id_count()), -1);
  for (std::size_t k = 0; k < ids.size(); ++k) position[ids[k].index()] = static_cast<std::int32_t>(k);
  s.contacts = world.contacts();
  for (ContactRecordT<Dim>& c : s.contacts) {
    c.first = ParticleId{position[c.first.index()]};
    if (c.second_particle.valid()) c.second_particle = ParticleId{position[c.second_particle.index()]};
  }
  s.depth = world.depth();
  s.periodic = world.periodic();
  return s;
}

template AssemblySampleT<2> sample(const BasicWorld<2>&);
template AssemblySampleT<3> sample(const BasicWorld<3>&);

}  // namespace dem::analysis
