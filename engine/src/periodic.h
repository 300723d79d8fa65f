// Periodic boundaries: the nearest image of a separation and the wrapping
// of positions into the periodic cell. Axes that do not repeat have length 0.
#pragma once

#include <cmath>

#include "dem/definitions.h"

namespace dem {

template <int Dim>
struct Periodic {
  Vec<Dim> min = Vec<Dim>::Zero();
  Vec<Dim> length = Vec<Dim>::Zero();  // 0 along axes that do not repeat

  static Periodic from(const PeriodicDefT<Dim>& def) {
    Periodic p;
    for (int d = 0; d < Dim; ++d) {
      if (!def.axes[d]) continue;
      p.min[d] = def.min[d];
      p.length[d] = def.max[d] - def.min[d];
    }
    return p;
  }
  bool repeats(int axis) const { return length[axis] > 0.0; }
  bool any() const { return (length.array() > 0.0).any(); }

  // b - a through the nearest image.
  Vec<Dim> separation(const Vec<Dim>& a, const Vec<Dim>& b) const {
    Vec<Dim> d = b - a;
    for (int k = 0; k < Dim; ++k) {
      if (length[k] > 0.0) d[k] -= length[k] * std::nearbyint(d[k] / length[k]);
    }
    return d;
  }
  // The image of x inside [min, min + length) along repeating axes.
  void wrap(Vec<Dim>& x) const {
    for (int k = 0; k < Dim; ++k) {
      if (length[k] <= 0.0) continue;
      x[k] -= length[k] * std::floor((x[k] - min[k]) / length[k]);
      if (x[k] >= min[k] + length[k]) x[k] = min[k];  // round-off at the upper edge
    }
  }
};

}  // namespace dem
