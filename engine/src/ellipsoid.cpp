#include "ellipsoid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace dem {

namespace {

using Mat3 = Eigen::Matrix3d;

// The potential f(x) = (x - c)^T M (x - c) - 1 in world axes: M = R A^-2 R^T.
Mat3 shape_matrix(const PlacedEllipsoid& e) {
  const Mat3 r = e.orientation.toRotationMatrix();
  return r * e.axes.cwiseInverse().cwiseAbs2().asDiagonal() * r.transpose();
}

// The point of body i's surface where body j's potential is least: with
// quadric potentials the Lagrange condition M_j (x - c_j) + mu M_i (x - c_i) = 0
// gives x(mu) = (M_j + mu M_i)^-1 (M_j c_j + mu M_i c_i), and the
// constraint g(mu) = f_i(x(mu)) = 0 is one equation in mu, falling
// monotonically from f_i(c_j) at mu = 0 to -1 as mu grows. Newton's method
// on it, kept inside a bracket, starting from the last cycle's mu.
struct Deepest {
  Vec3 point;
  double multiplier;
};

Deepest deepest_point(const Mat3& mi, const Vec3& ci, const Mat3& mj, const Vec3& cj, double start) {
  const Vec3 d0 = cj - ci;
  if (d0.dot(mi * d0) <= 1.0) {
    // c_j inside i: no such point on this branch; fall back on the line of centres.
    return {ci + d0 / std::sqrt(std::max(d0.dot(mi * d0), 1e-300)), start};
  }
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  double mu = start > 0.0 ? start : 1.0;
  Vec3 x = Vec3::Zero();
  const Vec3 mj_cj = mj * cj, mi_ci = mi * ci;
  for (int iteration = 0; iteration < 100; ++iteration) {
    // M_j + mu M_i is symmetric positive definite: its closed-form 3x3
    // inverse (cofactors) serves both solves of the step.
    const Mat3 inverse = (mj + mu * mi).inverse();
    x = inverse * (mj_cj + mu * mi_ci);
    const Vec3 d = x - ci;
    const Vec3 mi_d = mi * d;
    const double g = d.dot(mi_d) - 1.0;
    (g > 0.0 ? lo : hi) = mu;
    if (std::abs(g) < 1e-13) break;
    // g'(mu) = 2 d^T M_i dx/dmu with dx/dmu = -(M_j + mu M_i)^-1 M_i d.
    const Vec3 dx_dmu = -(inverse * mi_d);
    const double slope = 2.0 * mi_d.dot(dx_dmu);
    double next = slope < 0.0 ? mu - g / slope : -1.0;
    // Close to the root one Newton step, applied to x to first order, leaves
    // an error of order g^2 (below 1e-14 here): no further solve is needed.
    if (std::abs(g) < 1e-7 && next > lo && next < hi) {
      x += (next - mu) * dx_dmu;
      mu = next;
      break;
    }
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? (lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * hi) : 10.0 * mu;
    if (std::abs(next - mu) <= 1e-15 * mu) break;
    mu = next;
  }
  return {x, mu};
}

// The curvature tensor (shape operator) of f = (x-c)^T M (x-c) - 1 at a
// surface point, projected on the plane normal to n: P H P / |grad f|.
Mat3 curvature_tensor(const Mat3& m, const Vec3& centre, const Vec3& point, const Vec3& n) {
  const Vec3 gradient = 2.0 * m * (point - centre);
  const Mat3 projector = Mat3::Identity() - n * n.transpose();
  return projector * (2.0 * m) * projector / gradient.norm();
}

// The two principal values of a curvature tensor in the plane normal to n
// (the third eigenvalue, along n, is zero).
Eigen::Vector2d in_plane_eigenvalues(const Mat3& k, const Vec3& n) {
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(k);
  const Vec3 values = solver.eigenvalues();
  const Mat3 vectors = solver.eigenvectors();
  // Drop the eigenvector most aligned with n.
  int along = 0;
  for (int c = 1; c < 3; ++c) {
    if (std::abs(vectors.col(c).dot(n)) > std::abs(vectors.col(along).dot(n))) along = c;
  }
  Eigen::Vector2d out;
  for (int c = 0, o = 0; c < 3; ++c) {
    if (c != along) out[o++] = values[c];
  }
  return out;
}

// Equivalent radius from the relative principal curvatures k1, k2 (the
// eigenvalues of the summed curvature tensors in the contact plane).
// Johnson (1985) 4.2: the gap is A u^2 + B v^2 with A = k1/2, B = k2/2
// (Miyata eqs. 45-46), and R_e = (1/2)(AB)^(-1/2) = (k1 k2)^(-1/2). Miyata's
// eq. 48 as printed, 1/sqrt(AB), is twice this: for two spheres it would
// give 2 R* instead of Hertz's R*, so we follow Johnson.
//
// Only the product k1 k2 is needed: the determinant of the tensor
// restricted to the plane normal to n, written in any orthonormal basis
// (t1, t2) of that plane. No eigenvalue problem need be solved.
//
// On the plane the projector of the curvature tensor (curvature_tensor)
// does nothing, so body b contributes 2 t^T M_b t' / |grad f_b| to the
// restricted tensor: no 3x3 products are needed.
struct TangentBasis {
  Vec3 t1, t2;
  explicit TangentBasis(const Vec3& n) {
    const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    t1 = n.cross(helper).normalized();
    t2 = n.cross(t1);
  }
};

// Body b's curvature restricted to the plane: (k11, k12, k22).
Vec3 restricted_curvature(const Mat3& m, const Vec3& centre, const Vec3& point, const TangentBasis& t) {
  const double scale = 2.0 / (2.0 * m * (point - centre)).norm();
  const Vec3 m_t1 = m * t.t1, m_t2 = m * t.t2;
  return scale * Vec3(t.t1.dot(m_t1), t.t1.dot(m_t2), t.t2.dot(m_t2));
}

double equivalent_radius(const Vec3& k) {
  return 1.0 / std::sqrt(std::max(k.x() * k.z() - k.y() * k.y(), 1e-300));
}

}  // namespace

EllipsoidContact ellipsoid_contact(const PlacedEllipsoid& i, const PlacedEllipsoid& j, double mu_i, double mu_j) {
  const Mat3 mi = shape_matrix(i), mj = shape_matrix(j);
  const Deepest di = deepest_point(mi, i.centre, mj, j.centre, mu_i);  // on i, deepest in j's potential
  const Deepest dj = deepest_point(mj, j.centre, mi, i.centre, mu_j);  // on j, deepest in i's
  const Vec3& pi = di.point;
  const Vec3& pj = dj.point;
  // The outward normals there are opposite (Lagrange); average them.
  const Vec3 ni = (mi * (pi - i.centre)).normalized();
  const Vec3 nj = (mj * (pj - j.centre)).normalized();
  EllipsoidContact c;
  c.normal = (ni - nj).normalized();
  c.overlap = (pi - pj).dot(c.normal);
  c.point = 0.5 * (pi + pj);
  const TangentBasis plane(c.normal);
  c.effective_radius = equivalent_radius(restricted_curvature(mi, i.centre, pi, plane) +
                                         restricted_curvature(mj, j.centre, pj, plane));
  c.first_point = pi;
  c.second_point = pj;
  c.multiplier_i = di.multiplier;
  c.multiplier_j = dj.multiplier;
  return c;
}

EllipsoidFaceContact ellipsoid_plane_contact(const PlacedEllipsoid& body, const Vec3& on_plane, const Vec3& towards) {
  const Mat3 m = shape_matrix(body);
  // Eq. 54: where the outward normal is parallel to the plane's, the point
  // nearest the plane is the support point in the direction -towards.
  const Mat3 inverse = m.inverse();
  const Vec3 u = -towards;
  EllipsoidFaceContact c;
  c.support = body.centre + inverse * u / std::sqrt(u.dot(inverse * u));
  c.overlap = (on_plane - c.support).dot(towards);  // eq. 55
  c.projected = c.support + c.overlap * towards;    // eq. 56
  c.effective_radius = equivalent_radius(restricted_curvature(m, body.centre, c.support, TangentBasis(u)));
  return c;
}

Eigen::Vector2d ellipsoid_principal_curvatures(const PlacedEllipsoid& body, const Vec3& point) {
  const Mat3 m = shape_matrix(body);
  const Vec3 n = (m * (point - body.centre)).normalized();
  return in_plane_eigenvalues(curvature_tensor(m, body.centre, point, n), n);
}

EllipsoidMass ellipsoid_mass(const Vec3& a) {
  const double volume = 4.0 / 3.0 * std::numbers::pi * a.x() * a.y() * a.z();
  const Vec3 squares = a.cwiseAbs2();
  return {volume, volume / 5.0 * Vec3(squares.y() + squares.z(), squares.x() + squares.z(), squares.x() + squares.y())};
}

}  // namespace dem
