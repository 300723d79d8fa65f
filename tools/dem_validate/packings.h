// A validation that depends on a random packing is judged over several:
// the case's random packings under another seed (each a different sample
// of the same case), and the median packing's figures.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/case.pb.h"

namespace dem::validation {

// The first random packing's seed; 0 when the case has none.
std::uint64_t first_packing_seed(const proto::Case& message);

// Gives every random packing of the case the seed.
void reseed_packings(proto::Case& message, std::uint64_t seed);

// The median of one figure over packings (the mean of the middle two for
// an even count); 0 for none.
double median(std::vector<double> values);

// Sets each of `figures` (members of a run's measured figures) in `into`
// to its median over the packings.
template <typename Measured, std::size_t N>
void set_medians(Measured& into, const std::vector<Measured>& packings, double Measured::*const (&figures)[N]) {
  for (const auto figure : figures) {
    std::vector<double> values;
    values.reserve(packings.size());
    for (const Measured& p : packings) values.push_back(p.*figure);
    into.*figure = median(std::move(values));
  }
}

}  // namespace dem::validation
