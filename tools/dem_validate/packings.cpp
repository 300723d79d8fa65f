#include "packings.h"

#include <algorithm>

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

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::ranges::sort(values);
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace dem::validation
