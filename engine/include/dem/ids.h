// Dense integer ids, passed by value and validated at the API. The same ids
// appear in output files and (later) on the wire.
#pragma once

#include <cstdint>

namespace dem {

using ParticleId = std::int32_t;  // index into the particle arrays, in definition order
using WallId = std::int32_t;      // index into the wall arrays, in definition order
using MaterialId = std::int32_t;  // index into WorldDef::materials

inline constexpr std::int32_t kInvalidId = -1;

}  // namespace dem
