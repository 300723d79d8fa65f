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
  s.contacts = world.contacts();
  s.depth = world.depth();
  s.periodic = world.periodic();
  return s;
}

template AssemblySampleT<2> sample(const BasicWorld<2>&);
template AssemblySampleT<3> sample(const BasicWorld<3>&);

}  // namespace dem::analysis
