#include "packing_seed.h"

namespace dem::validation {

std::uint64_t first_packing_seed(const proto::Case& message) {
  for (const proto::ParticleSource& source : message.particles()) {
    if (source.has_random_packing()) return source.random_packing().seed();
  }
  return 0;
}

void reseed_packings(proto::Case& message, std::uint64_t seed) {
  for (proto::ParticleSource& source : *message.mutable_particles()) {
    if (source.has_random_packing()) source.mutable_random_packing()->set_seed(seed);
  }
}

}  // namespace dem::validation
