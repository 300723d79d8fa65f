// Periodic boundaries: the nearest image of a separation and the wrapping
// of positions into the periodic cell. Axes that do not repeat have length 0.
#pragma once

#include <cmath>

#include "dem/definitions.h"

namespace dem {

// One component of Periodic::separation without a branch, for vector
// loops: the same bits (along an axis that does not repeat, length 0, a
// difference is left as it is).
inline double nearest_image(double difference, double length) {
  const double half = 0.5 * length;
  return difference > half ? difference - length : (difference < -half ? difference + length : difference);
}

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

  // b - a through the nearest image. Positions lie inside the cell, so a
  // difference is under one period and one shift finds the nearest image.
  // (The branches are taken by the few pairs across the cell's edge only.)
  Vec<Dim> separation(const Vec<Dim>& a, const Vec<Dim>& b) const {
    Vec<Dim> d = b - a;
    for (int k = 0; k < Dim; ++k) {
      if (length[k] <= 0.0) continue;
      if (d[k] > 0.5 * length[k]) {
        d[k] -= length[k];
      } else if (d[k] < -0.5 * length[k]) {
        d[k] += length[k];
      }
    }
    return d;
  }
  // The image inside the cell of a position that was inside it one step
  // ago: a particle moves far less than a period in one step.
  void wrap_step(Vec<Dim>& x) const {
    for (int k = 0; k < Dim; ++k) {
      if (length[k] <= 0.0) continue;
      if (x[k] < min[k]) {
        x[k] += length[k];
        if (x[k] < min[k] || x[k] >= min[k] + length[k]) wrap(x);  // it moved farther, or sits on the edge
      } else if (x[k] >= min[k] + length[k]) {
        x[k] -= length[k];
        if (x[k] < min[k] || x[k] >= min[k] + length[k]) wrap(x);
      }
    }
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
