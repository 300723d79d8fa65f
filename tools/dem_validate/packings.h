// A validation that depends on a random packing is judged over several:
// the case's random packings under another seed (each a different sample
// of the same case), and the median packing's figures.
#pragma once

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

}  // namespace dem::validation
