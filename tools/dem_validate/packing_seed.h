// The random packings of a case under another seed: a validation that
// depends on a random packing is judged over several (each a different
// sample of the same case).
#pragma once

#include <cstdint>

#include "dem/case.pb.h"

namespace dem::validation {

// The first random packing's seed; 0 when the case has none.
std::uint64_t first_packing_seed(const proto::Case& message);

// Gives every random packing of the case the seed.
void reseed_packings(proto::Case& message, std::uint64_t seed);

}  // namespace dem::validation
