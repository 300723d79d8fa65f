// A value unlike a field's value, for tests that change each field of a
// list in turn and check what follows (test_snapshot_fields.cpp,
// test_particle_fields.cpp).
#pragma once

#include <type_traits>

#include "dem/math.h"

namespace dem::testing {

// A value unlike v and unlike the value given to any other field (k
// differs per field); a rotation stays a rotation.
template <typename T>
T distinct(const T& v, int k) {
  if constexpr (std::is_same_v<T, bool>) {
    return !v;
  } else if constexpr (std::is_integral_v<T>) {
    return v + static_cast<T>(100 + k);
  } else if constexpr (std::is_floating_point_v<T>) {
    return v + 0.125 * (k + 1);
  } else if constexpr (std::is_same_v<T, Quaternion>) {
    return (v * Quaternion(Eigen::AngleAxisd(0.125 * (k + 1), Vec3::UnitZ()))).normalized();
  } else {
    T out = v;
    for (Eigen::Index i = 0; i < out.size(); ++i) out[i] += 0.125 * (k + 1) + 0.0078125 * static_cast<double>(i);
    return out;
  }
}

}  // namespace dem::testing
