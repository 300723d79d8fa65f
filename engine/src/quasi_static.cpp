#include "quasi_static.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <numbers>

#include "contact_forces.h"

namespace dem {

template <int Dim>
double deformation_rate(const Particles<Dim>& particles, const Periodic<Dim>& periodic) {
  const std::size_t n = particles.size();
  if (n < 2) return 0.0;
  Vec<Dim> mean_position = Vec<Dim>::Zero();
  Vec<Dim> mean_velocity = Vec<Dim>::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    mean_position += particles.position[i];
    mean_velocity += particles.velocity[i];
  }
  mean_position /= static_cast<double>(n);
  mean_velocity /= static_cast<double>(n);
  // Least squares: L S = C with S = sum dx dx^T and C = sum dv dx^T over
  // the axes that deform (the others' rows and columns stay 0).
  using Matrix = Eigen::Matrix<double, Dim, Dim>;
  Matrix spread = Matrix::Zero();
  Matrix covariance = Matrix::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<Dim> dx = particles.position[i] - mean_position;
    const Vec<Dim> dv = particles.velocity[i] - mean_velocity;
    spread += dx * dx.transpose();
    covariance += dv * dx.transpose();
  }
  Matrix gradient = Matrix::Zero();
  int deforming[Dim];
  int m = 0;
  for (int d = 0; d < Dim; ++d) {
    if (!periodic.repeats(d)) deforming[m++] = d;
  }
  if (m == 0) return 0.0;
  Eigen::MatrixXd s(m, m);
  Eigen::MatrixXd c(Dim, m);
  for (int a = 0; a < m; ++a) {
    for (int b = 0; b < m; ++b) s(a, b) = spread(deforming[a], deforming[b]);
    for (int r = 0; r < Dim; ++r) c(r, a) = covariance(r, deforming[a]);
  }
  // Particles lined up along an axis leave no gradient to fit along it.
  const Eigen::LDLT<Eigen::MatrixXd> solver(s);
  if (solver.info() != Eigen::Success || !(solver.vectorD().minCoeff() > 1e-12 * s.trace())) return 0.0;
  const Eigen::MatrixXd fitted = solver.solve(c.transpose()).transpose();
  for (int a = 0; a < m; ++a) gradient.col(deforming[a]) = fitted.col(a);
  const Matrix rate = 0.5 * (gradient + gradient.transpose());
  const Eigen::SelfAdjointEigenSolver<Matrix> principal(rate, Eigen::EigenvaluesOnly);
  return principal.eigenvalues().maxCoeff() - principal.eigenvalues().minCoeff();
}

template <int Dim>
double mean_stress(const WorldState<Dim>& s) {
  const Particles<Dim>& p = s.particles;
  if (p.size() == 0) return 0.0;
  // The volume the particles span: their bounding boxes' hull, the period
  // along a repeating axis; 2D times the depth.
  Vec<Dim> low = Vec<Dim>::Constant(std::numeric_limits<double>::max());
  Vec<Dim> high = Vec<Dim>::Constant(std::numeric_limits<double>::lowest());
  for (std::size_t i = 0; i < p.size(); ++i) {
    low = low.cwiseMin(p.position[i] - Vec<Dim>::Constant(p.radius[i]));
    high = high.cwiseMax(p.position[i] + Vec<Dim>::Constant(p.radius[i]));
  }
  double volume = Dim == 2 ? s.depth : 1.0;
  for (int d = 0; d < Dim; ++d) volume *= s.periodic.repeats(d) ? s.periodic.length[d] : high[d] - low[d];
  if (!(volume > 0.0)) return 0.0;
  double virial = 0.0;
  visit_touching_contacts<Dim>(s, [&](const ContactRecordT<Dim>& c) {
    // The arm of each body to the contact point, through the nearest image.
    const Vec<Dim> first_arm = s.periodic.separation(p.position[p.slot_of(c.first)], c.point);
    virial += first_arm.dot(c.force);
    if (c.second_particle != kInvalidId) {
      const Vec<Dim> second_arm = s.periodic.separation(p.position[p.slot_of(c.second_particle)], c.point);
      virial -= second_arm.dot(c.force);
    }
  });
  return virial != 0.0 ? -virial / (Dim * volume) : 0.0;
}

template <int Dim>
GrainScale grain_scale(const WorldState<Dim>& s) {
  const Particles<Dim>& p = s.particles;
  if (p.size() == 0) return {};
  // Discs and superquadrics have unit thickness: their volume is an area.
  const bool flat = Dim == 2 && (s.planar_particle == PlanarParticle::kDisc || s.shape == ShapeKind::kSuperquadric);
  double mass = 0.0, volume = 0.0, diameters = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double v = p.mass[i] / s.materials[static_cast<std::size_t>(p.material[i])].density;
    mass += p.mass[i];
    volume += v;
    diameters += flat ? 2.0 * std::sqrt(v / std::numbers::pi) : 2.0 * std::cbrt(0.75 * v / std::numbers::pi);
  }
  return {diameters / static_cast<double>(p.size()), mass / volume};
}

double inertial_number(double rate, const GrainScale& grains, double stress) {
  if (!(rate > 0.0)) return 0.0;
  if (!(stress > 0.0)) return std::numeric_limits<double>::infinity();
  return rate * grains.diameter * std::sqrt(grains.density / stress);
}

template double deformation_rate(const Particles<2>&, const Periodic<2>&);
template double deformation_rate(const Particles<3>&, const Periodic<3>&);
template double mean_stress(const WorldState<2>&);
template double mean_stress(const WorldState<3>&);
template GrainScale grain_scale(const WorldState<2>&);
template GrainScale grain_scale(const WorldState<3>&);

}  // namespace dem
