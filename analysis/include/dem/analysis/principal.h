// Principal values and directions of a second-order tensor's symmetric
// part: in 2D Randall's (1989) 4.52-4.54 (the Mohr's circle of Fig. 4.1),
// in 3D the eigen-decomposition.
#pragma once

#include <Eigen/Core>

#include "dem/math.h"

namespace dem::analysis {

template <int Dim>
using Tensor = Eigen::Matrix<double, Dim, Dim>;

template <int Dim>
struct Principal {
  Vec<Dim> values = Vec<Dim>::Zero();            // major first, minor last
  Tensor<Dim> directions = Tensor<Dim>::Zero();  // column k: the unit direction of values[k]
  // 2D: the major direction's angle from the x axis, rad, in (-pi/2, pi/2]
  // (Randall 4.54, with the quadrant from atan2). 3D: 0.
  double angle = 0.0;
};

template <int Dim>
Principal<Dim> principal(const Tensor<Dim>& tensor);

}  // namespace dem::analysis
