#include "ellipsoid.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace dem {

namespace {

using Mat3 = Eigen::Matrix3d;

using Symmetric = SymmetricMatrix;

Mat3 full(const Symmetric& m) {
  Mat3 out;
  out << m.xx, m.xy, m.xz, m.xy, m.yy, m.yz, m.xz, m.yz, m.zz;
  return out;
}

// The matrix of cofactors (for a symmetric matrix, its adjugate).
Symmetric cofactors(const Symmetric& a) {
  return {a.yy * a.zz - a.yz * a.yz, a.xz * a.yz - a.xy * a.zz, a.xy * a.yz - a.xz * a.yy,
          a.xx * a.zz - a.xz * a.xz, a.xy * a.xz - a.xx * a.yz, a.xx * a.yy - a.xy * a.xy};
}

// The inverse of a symmetric positive definite matrix by its cofactors.
Symmetric inverse(const Symmetric& a) {
  const Symmetric c = cofactors(a);
  return c.scaled(1.0 / (a.xx * c.xx + a.xy * c.xy + a.xz * c.xz));
}

// R diag(w) R^T entry by entry: sum_k R_ak w_k R_bk.
Symmetric turned_diagonal(const Mat3& r, const Vec3& w) {
  const Vec3 r0 = r.row(0).transpose(), r1 = r.row(1).transpose(), r2 = r.row(2).transpose();
  const Vec3 w0 = r0.cwiseProduct(w), w1 = r1.cwiseProduct(w);
  return {w0.dot(r0), w0.dot(r1), w0.dot(r2), w1.dot(r1), w1.dot(r2), r2.cwiseProduct(w).dot(r2)};
}

// Below this |g| one Newton step, applied to the point to first order,
// ends the search: what it leaves is of order g^2 (1e-12 of the potential,
// about 1e-13 m on Miyata's rocks), far below a contact's overlap and the
// distance a body moves in a step. A warm-started search through a slow
// loading starts below it and needs one solve.
constexpr double kFirstOrder = 1e-6;

// The point of body i's surface where body j's potential is least: with
// quadric potentials the Lagrange condition M_j (x - c_j) + mu M_i (x - c_i) = 0
// gives x(mu) - c_i = (M_j + mu M_i)^-1 M_j (c_j - c_i), and the
// constraint g(mu) = f_i(x(mu)) = 0 is one equation in mu, falling
// monotonically from f_i(c_j) at mu = 0 to -1 as mu grows. Newton's method
// on it, kept inside a bracket, starting from the last cycle's mu. The
// point is returned as its arm from c_i: relative to the centre, rounding
// does not grow with the bodies' distance from the origin.
struct Deepest {
  Vec3 arm;  // x - c_i
  double multiplier;
};

Deepest deepest_point(const Symmetric& mi, const Symmetric& mj, const Vec3& d0, double start) {
  const double f0 = d0.dot(mi * d0);
  if (f0 <= 1.0) {
    // c_j inside i: no such point on this branch; fall back on the line of centres.
    return {d0 / std::sqrt(std::max(f0, 1e-300)), start};
  }
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  double mu = start > 0.0 ? start : 1.0;
  Vec3 d = Vec3::Zero();
  const Vec3 mj_d0 = mj * d0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    // One inverse serves both solves of the step.
    const Symmetric inverse_m = inverse(mj.plus(mu, mi));
    d = inverse_m * mj_d0;
    const Vec3 mi_d = mi * d;
    const double g = d.dot(mi_d) - 1.0;
    (g > 0.0 ? lo : hi) = mu;
    if (std::abs(g) < 1e-13) break;
    // g'(mu) = 2 d^T M_i dx/dmu with dx/dmu = -(M_j + mu M_i)^-1 M_i d.
    const Vec3 dx_dmu = -(inverse_m * mi_d);
    const double slope = 2.0 * mi_d.dot(dx_dmu);
    double next = slope < 0.0 ? mu - g / slope : -1.0;
    if (std::abs(g) < kFirstOrder && next > lo && next < hi) {
      d += (next - mu) * dx_dmu;
      mu = next;
      break;
    }
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? (lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * hi) : 10.0 * mu;
    if (std::abs(next - mu) <= 1e-15 * mu) break;
    mu = next;
  }
  return {d, mu};
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
// restricted to the plane normal to the unit vector n, which is
// n^T adj(K) n (in axes with n the third, the adjugate's last diagonal
// entry is the upper 2x2 determinant). No eigenvalue problem, no basis of
// the plane. On the plane the projector of curvature_tensor does nothing,
// so a body whose potential's half-gradient at the point is M (x - c)
// contributes M / |M (x - c)| there: the bodies' matrices are summed first.
double equivalent_radius(const Symmetric& k, const Vec3& n) {
  const double product = n.dot(cofactors(k) * n);  // k1 k2
  return 1.0 / std::sqrt(std::max(product, 1e-300));
}

}  // namespace

EllipsoidFrame ellipsoid_frame(const Vec3& axes, const Quaternion& orientation) {
  const Mat3 r = orientation.toRotationMatrix();
  const Vec3 squares = axes.cwiseAbs2();
  return {turned_diagonal(r, squares.cwiseInverse()), turned_diagonal(r, squares)};
}

EllipsoidContact ellipsoid_contact(const EllipsoidFrame& i, const Vec3& centre_i, const EllipsoidFrame& j,
                                   const Vec3& centre_j, double mu_i, double mu_j) {
  const Symmetric& mi = i.potential;
  const Symmetric& mj = j.potential;
  const Vec3 d0 = centre_j - centre_i;
  const Deepest di = deepest_point(mi, mj, d0, mu_i);   // on i, deepest in j's potential
  const Deepest dj = deepest_point(mj, mi, -d0, mu_j);  // on j, deepest in i's
  // The outward normals there are opposite (Lagrange); average them.
  const Vec3 gi = mi * di.arm, gj = mj * dj.arm;  // half the potentials' gradients
  const double inverse_gi = 1.0 / gi.norm(), inverse_gj = 1.0 / gj.norm();
  EllipsoidContact c;
  c.normal = (inverse_gi * gi - inverse_gj * gj).normalized();
  c.overlap = (di.arm - dj.arm - d0).dot(c.normal);  // (P_i - P_j) . n
  c.first_point = centre_i + di.arm;
  c.second_point = centre_j + dj.arm;
  c.point = 0.5 * (c.first_point + c.second_point);
  c.effective_radius = equivalent_radius(mi.scaled(inverse_gi).plus(inverse_gj, mj), c.normal);
  c.multiplier_i = di.multiplier;
  c.multiplier_j = dj.multiplier;
  return c;
}

EllipsoidContact ellipsoid_contact(const PlacedEllipsoid& i, const PlacedEllipsoid& j, double mu_i, double mu_j) {
  return ellipsoid_contact(ellipsoid_frame(i.axes, i.orientation), i.centre, ellipsoid_frame(j.axes, j.orientation),
                           j.centre, mu_i, mu_j);
}

EllipsoidFaceContact ellipsoid_plane_contact(const EllipsoidFrame& body, const Vec3& centre, const Vec3& on_plane,
                                             const Vec3& towards) {
  // Eq. 54: where the outward normal is parallel to the plane's, the point
  // nearest the plane is the support point in the direction u = -towards,
  // M^-1 u / sqrt(u^T M^-1 u) from the centre.
  const Vec3 u = -towards;
  const Vec3 reach_u = body.reach * u;
  const Vec3 arm = reach_u / std::sqrt(u.dot(reach_u));
  EllipsoidFaceContact c;
  c.support = centre + arm;
  c.overlap = (on_plane - c.support).dot(towards);  // eq. 55
  c.projected = c.support + c.overlap * towards;    // eq. 56
  c.effective_radius = equivalent_radius(body.potential.scaled(1.0 / (body.potential * arm).norm()), towards);
  return c;
}

EllipsoidFaceContact ellipsoid_plane_contact(const PlacedEllipsoid& body, const Vec3& on_plane, const Vec3& towards) {
  return ellipsoid_plane_contact(ellipsoid_frame(body.axes, body.orientation), body.centre, on_plane, towards);
}

Eigen::Vector2d ellipsoid_principal_curvatures(const PlacedEllipsoid& body, const Vec3& point) {
  const Mat3 m = full(ellipsoid_frame(body.axes, body.orientation).potential);
  const Vec3 n = (m * (point - body.centre)).normalized();
  return in_plane_eigenvalues(curvature_tensor(m, body.centre, point, n), n);
}

EllipsoidMass ellipsoid_mass(const Vec3& a) {
  const double volume = 4.0 / 3.0 * std::numbers::pi * a.x() * a.y() * a.z();
  const Vec3 squares = a.cwiseAbs2();
  return {volume, volume / 5.0 * Vec3(squares.y() + squares.z(), squares.x() + squares.z(), squares.x() + squares.y())};
}

}  // namespace dem
