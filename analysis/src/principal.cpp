#include "dem/analysis/principal.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace dem::analysis {

template <>
Principal<2> principal(const Tensor<2>& t) {
  Principal<2> p;
  const double sum = t(0, 1) + t(1, 0), difference = t(0, 0) - t(1, 1);
  const double centre = 0.5 * (t(0, 0) + t(1, 1));
  const double radius = 0.5 * std::sqrt(sum * sum + difference * difference);
  p.values = {centre + radius, centre - radius};  // (4.52), (4.53)
  p.angle = 0.5 * std::atan2(sum, difference);    // (4.54)
  const Vec2 major(std::cos(p.angle), std::sin(p.angle));
  p.directions.col(0) = major;
  p.directions.col(1) = Vec2(-major.y(), major.x());
  return p;
}

template <>
Principal<3> principal(const Tensor<3>& t) {
  const Tensor<3> symmetric = 0.5 * (t + t.transpose());
  const Eigen::SelfAdjointEigenSolver<Tensor<3>> solver(symmetric);
  Principal<3> p;
  // Eigen lists them ascending.
  for (int k = 0; k < 3; ++k) {
    p.values[k] = solver.eigenvalues()[2 - k];
    p.directions.col(k) = solver.eigenvectors().col(2 - k);
  }
  return p;
}

}  // namespace dem::analysis
