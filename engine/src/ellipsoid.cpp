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

// u^T A u from u's products, which wait on u only: A's entries then need
// one product and a sum each, where A u and a dot product take two sums.
inline double quadratic_form(const Symmetric& a, const Vec3& u) {
  const double x = u.x(), y = u.y(), z = u.z();
  return (a.xx * (x * x) + a.yy * (y * y) + a.zz * (z * z)) + 2.0 * (a.xy * (x * y) + a.xz * (x * z) + a.yz * (y * z));
}

// The matrix of cofactors (for a symmetric matrix, its adjugate).
inline Symmetric cofactors(const Symmetric& a) {
  return {a.yy * a.zz - a.yz * a.yz, a.xz * a.yz - a.xy * a.zz, a.xy * a.yz - a.xz * a.yy,
          a.xx * a.zz - a.xz * a.xz, a.xy * a.xz - a.xx * a.yz, a.xx * a.yy - a.xy * a.xy};
}

// Below this |g| one step of Halley's method from the last evaluation,
// with the point carried along to second order, ends the search: what it
// leaves is of order g^3 (1e-12 of the potential, about 1e-13 m on
// Miyata's rocks), far below a contact's overlap and the distance a body
// moves in a step. Warm-started from the last cycle, a settling step
// (1e-5 m, 1e-4 rad) starts below it in 99 searches of 100 and a loading
// step in all: one solve a search. Below kFirstOrder (g^2 < 1e-12) Newton's
// step to first order does as well and costs two products fewer.
constexpr double kSecondOrder = 1e-4;
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

// x(mu) - c_i, g(mu) and their derivatives at one mu. With A = M_j + mu M_i
// (its inverse adj(A) / det A), d = A^-1 M_j d0, dd/dmu = -A^-1 M_i d and
// g'(mu) = 2 (M_i d) . dd/dmu.
struct Evaluation {
  Vec3 d, mi_d, slope_d;  // slope_d = dd/dmu
  Symmetric adjugate;
  double inverse_determinant, g, slope;
};

inline Evaluation evaluate(const Symmetric& mi, const Symmetric& mj, const Vec3& mj_d0, double mu) {
  Evaluation e;
  const Symmetric a = mj.plus(mu, mi);
  e.adjugate = cofactors(a);
  e.inverse_determinant = 1.0 / (a.xx * e.adjugate.xx + a.xy * e.adjugate.xy + a.xz * e.adjugate.xz);
  e.d = e.inverse_determinant * (e.adjugate * mj_d0);
  e.mi_d = mi * e.d;
  e.g = e.d.dot(e.mi_d) - 1.0;
  e.slope_d = -e.inverse_determinant * (e.adjugate * e.mi_d);
  e.slope = 2.0 * e.mi_d.dot(e.slope_d);
  return e;
}

// The step that ends a search from an evaluation with |g| < kSecondOrder:
// the new mu and the point there. d'' = -2 A^-1 M_i d' and, because
// (A^-1 M_i d) . M_i d' = -d' . M_i d', g'' = 6 d'^T M_i d'; Halley's step
// dmu = -(g / g') / (1 - g g'' / (2 g'^2)), and the point to second order,
// d + dmu d' + dmu^2 d'' / 2.
inline double finish(const Symmetric& mi, Evaluation& e, double mu) {
  const double newton = -e.g / e.slope;
  if (std::abs(e.g) < kFirstOrder) {
    e.d += newton * e.slope_d;
    return mu + newton;
  }
  const Vec3 mi_slope_d = mi * e.slope_d;
  const double curvature = 6.0 * e.slope_d.dot(mi_slope_d);  // g''
  const double step = newton / (1.0 - e.g * curvature / (2.0 * e.slope * e.slope));
  const Vec3 second = -2.0 * e.inverse_determinant * (e.adjugate * mi_slope_d);  // d''
  e.d += step * e.slope_d + (0.5 * step * step) * second;
  return mu + step;
}

// The two warm-started searches side by side, one in each lane of a pair
// of doubles (lane 0 body i's, lane 1 body j's): they run the same
// operations on different matrices, so each product serves both. Lane by
// lane the arithmetic is IEEE's, as in scalar code: the same bits on any
// machine and thread count.
using Pair = double __attribute__((vector_size(16)));
struct PairVector {
  Pair x, y, z;
};
struct PairMatrix {
  Pair xx, xy, xz, yy, yz, zz;
};

inline Pair swapped(Pair a) { return Pair{a[1], a[0]}; }
inline Pair magnitude(Pair a) { return a < 0.0 ? -a : a; }
inline Pair root(Pair a) { return Pair{std::sqrt(a[0]), std::sqrt(a[1])}; }
inline bool both(decltype(Pair{} < Pair{}) condition) { return condition[0] && condition[1]; }
inline PairMatrix pair_of(const Symmetric& a, const Symmetric& b) {
  return {Pair{a.xx, b.xx}, Pair{a.xy, b.xy}, Pair{a.xz, b.xz}, Pair{a.yy, b.yy}, Pair{a.yz, b.yz}, Pair{a.zz, b.zz}};
}
inline PairMatrix swapped(const PairMatrix& m) {
  return {swapped(m.xx), swapped(m.xy), swapped(m.xz), swapped(m.yy), swapped(m.yz), swapped(m.zz)};
}
inline PairMatrix cofactors(const PairMatrix& a) {
  return {a.yy * a.zz - a.yz * a.yz, a.xz * a.yz - a.xy * a.zz, a.xy * a.yz - a.xz * a.yy,
          a.xx * a.zz - a.xz * a.xz, a.xy * a.xz - a.xx * a.yz, a.xx * a.yy - a.xy * a.xy};
}
inline PairVector pair_of(const Vec3& a, const Vec3& b) {
  return {Pair{a.x(), b.x()}, Pair{a.y(), b.y()}, Pair{a.z(), b.z()}};
}
inline Vec3 lane(const PairVector& v, int k) { return {v.x[k], v.y[k], v.z[k]}; }
inline PairVector operator*(const PairMatrix& m, const PairVector& v) {
  return {m.xx * v.x + m.xy * v.y + m.xz * v.z, m.xy * v.x + m.yy * v.y + m.yz * v.z,
          m.xz * v.x + m.yz * v.y + m.zz * v.z};
}
inline PairVector operator*(Pair s, const PairVector& v) { return {s * v.x, s * v.y, s * v.z}; }
inline PairVector operator+(const PairVector& a, const PairVector& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline PairVector operator-(const PairVector& a, const PairVector& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Pair dot(const PairVector& a, const PairVector& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Both warm searches' first evaluation and, where both end there, their
// last step (as evaluate and finish would take them): Newton's to first
// order when both |g| are below kFirstOrder, else Halley's for both.
// own holds (M_i, M_j), rhs (M_j d0, -M_i d0); the points come back as
// arms d from their centres, with the half-gradients M_own d there.
// Returns false when either search does not end there (the caller then
// searches one body at a time).
//
// Unnormalised, so that the products wait on no division: with
// A = M_other + mu M_own,
// D = det A and adj(A) = D A^-1, the vectors u = adj(A) rhs = D d,
// w = M_own u = D M_own d and z = adj(A) w = -D^2 d' give
//   g = E / D^2 with E = u.w - D^2,   g' = -2 (w.z) / D^3,
// Newton's step -g / g' = E D / Q with Q = 2 w.z, and Halley's
// -(g / g') / (1 - g g'' / (2 g'^2)) = 2 E D (w.z) / Q with
// Q = 4 (w.z)^2 - 3 E z^T M_own z (g'' = 6 z^T M_own z / D^4). The point
// d + s d' + s^2 d'' / 2, with d'' = 2 adj(A) M_own z / D^3 and t = s / D, is
// (u - t z + t^2 adj(A) M_own z) / D. So the products wait for one
// division only, t = E / Q or 2 E (w.z) / Q (1 / D is worked out beside
// them), and the search's own checks (|g| small, g' < 0, the new mu inside
// the bracket) need none. Q grows as a body's size to the -36th power: for
// bodies too small or too large for that in double precision (below about
// 1e-8 m), it leaves its range and the search goes the scalar way, whose
// quantities are normalised.
inline bool deepest_pair(const PairMatrix& own, const PairVector& rhs, Pair mu, PairVector& d, PairVector& gradient,
                         Pair& ends) {
  const PairMatrix other = swapped(own);
  const PairMatrix a{other.xx + mu * own.xx, other.xy + mu * own.xy, other.xz + mu * own.xz,
                     other.yy + mu * own.yy, other.yz + mu * own.yz, other.zz + mu * own.zz};
  const PairMatrix adj = cofactors(a);
  const Pair det = a.xx * adj.xx + a.xy * adj.xy + a.xz * adj.xz;
  const PairVector u = adj * rhs;
  const PairVector w = own * u;
  const PairVector z = adj * w;
  const Pair wz = dot(w, z);
  const Pair det2 = det * det;
  const Pair e = dot(u, w) - det2;  // g D^2
  const Pair size = magnitude(e);
  // |g| < kSecondOrder, g' < 0 and, for g < 0, mu + E D / (2 w.z) > 0.
  if (!both((size < kSecondOrder * det2) & (wz > 0.0) & (det > 1e-300) & (2.0 * mu * wz + e * det > 0.0))) return false;
  // M_own z serves Halley's step and the half-gradient at the new point,
  // M_own d = (w - t M_own z + t^2 M_own adj(A) M_own z) / D, which thus
  // waits on the division for one product only.
  const PairVector own_z = own * z;
  const bool first_order = both(size < kFirstOrder * det2);
  const Pair q = first_order ? 2.0 * wz : 4.0 * wz * wz - 3.0 * e * dot(z, own_z);
  const Pair step = first_order ? e : 2.0 * e * wz;  // t Q
  if (!both((q > 1e-300) & (q < 1e300) & (det < 1e300))) return false;
  const Pair t = step / q, inverse_det = 1.0 / det;
  ends = mu + t * det;
  if (first_order) {
    d = inverse_det * (u - t * z);
    gradient = inverse_det * (w - t * own_z);
  } else {
    const PairVector second = adj * own_z;
    const Pair tt = t * t;
    d = inverse_det * (u - t * z + tt * second);
    gradient = inverse_det * (w - t * own_z + tt * (own * second));
  }
  return true;
}

// f0 = f_i(c_j) = d0^T M_i d0 and mj_d0 = M_j d0, which the caller shares
// with the other body's search.
Deepest deepest_point(const Symmetric& mi, const Symmetric& mj, const Vec3& d0, const Vec3& mj_d0, double f0,
                      double start) {
  if (f0 <= 1.0) {
    // c_j inside i: no such point on this branch; fall back on the line of centres.
    return {d0 / std::sqrt(std::max(f0, 1e-300)), start};
  }
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  double mu = start > 0.0 ? start : 1.0;
  Evaluation e;
  for (int iteration = 0; iteration < 100; ++iteration) {
    e = evaluate(mi, mj, mj_d0, mu);
    const double g = e.g;
    (g > 0.0 ? lo : hi) = mu;
    if (std::abs(g) < 1e-13) break;
    double next = e.slope < 0.0 ? mu - g / e.slope : -1.0;
    if (std::abs(g) < kSecondOrder && next > lo && next < hi) {
      mu = finish(mi, e, mu);
      break;
    }
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? (lo > 0.0 ? std::sqrt(lo * hi) : 0.5 * hi) : 10.0 * mu;
    if (std::abs(next - mu) <= 1e-15 * mu) break;
    mu = next;
  }
  return {e.d, mu};
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
// Along a vector u of any length, k1 k2 = u^T adj(K) u / u^T u.
inline double equivalent_radius(const Symmetric& k, const Vec3& u) {
  const double squared_length = u.squaredNorm();
  const double product = u.dot(cofactors(k) * u);  // k1 k2 |u|^2
  return std::sqrt(squared_length / std::max(product, 1e-300 * squared_length));
}

}  // namespace

namespace {

// The two searches one body at a time (deepest_point), from scratch or
// where the paired step does not end them; out of line, so that the
// common path keeps its registers for itself.
[[gnu::noinline]] void deepest_apart(const Symmetric& mi, const Symmetric& mj, const Vec3& d0, const PairVector& own_d0,
                                     Pair f0, Pair start, PairVector& d, PairVector& g, Pair& mu) {
  const Vec3 mi_d0 = lane(own_d0, 0), mj_d0 = lane(own_d0, 1);
  const Deepest di = deepest_point(mi, mj, d0, mj_d0, f0[0], start[0]);    // on i, deepest in j's potential
  const Deepest dj = deepest_point(mj, mi, -d0, -mi_d0, f0[1], start[1]);  // on j, deepest in i's
  d = pair_of(di.arm, dj.arm);
  g = pair_of(mi, mj) * d;
  mu = Pair{di.multiplier, dj.multiplier};
}

}  // namespace

EllipsoidFrame ellipsoid_frame(const Vec3& axes, const Quaternion& orientation) {
  // R diag(w) R^T = w2 I + (w1 - w2) c1 c1^T + (w3 - w2) c3 c3^T for the
  // columns c1, c2, c3 of a rotation (c1 c1^T + c2 c2^T + c3 c3^T = I):
  // two columns of R and their two outer products serve both matrices,
  // M with w = a^-2 (eqs. 43-44) and M^-1 with w = a^2.
  // Half the columns (the weights take the factor 4, which changes no bit):
  // one product fewer between the quaternion and the matrices.
  const double x = orientation.x(), y = orientation.y(), z = orientation.z(), w = orientation.w();
  const Vec3 c1(0.5 - (y * y + z * z), x * y + w * z, x * z - w * y);
  const Vec3 c3(x * z + w * y, y * z - w * x, 0.5 - (x * x + y * y));
  const Symmetric o1{c1.x() * c1.x(), c1.x() * c1.y(), c1.x() * c1.z(),
                     c1.y() * c1.y(), c1.y() * c1.z(), c1.z() * c1.z()};
  const Symmetric o3{c3.x() * c3.x(), c3.x() * c3.y(), c3.x() * c3.z(),
                     c3.y() * c3.y(), c3.y() * c3.z(), c3.z() * c3.z()};
  const auto turned = [&](double w1, double w2, double w3) {
    Symmetric m = o1.scaled(4.0 * (w1 - w2)).plus(4.0 * (w3 - w2), o3);
    m.xx += w2;
    m.yy += w2;
    m.zz += w2;
    return m;
  };
  const Vec3 squares = axes.cwiseAbs2();
  // a_k^-2 from one division: 1 / (a1 a2 a3)^2 times the other two squares.
  const double inverse_product = 1.0 / (squares.x() * squares.y() * squares.z());
  return {turned(squares.y() * squares.z() * inverse_product, squares.x() * squares.z() * inverse_product,
                 squares.x() * squares.y() * inverse_product),
          turned(squares.x(), squares.y(), squares.z())};
}

void ellipsoid_frames(const std::array<Vec3, 4>& axes, const std::array<Quaternion, 4>& orientation,
                      EllipsoidFrame* out) {
  // As ellipsoid_frame, body k in lane k.
  using V = double __attribute__((vector_size(32)));
  V x, y, z, w, ax, ay, az;
  for (int k = 0; k < 4; ++k) {
    x[k] = orientation[k].x(), y[k] = orientation[k].y(), z[k] = orientation[k].z(), w[k] = orientation[k].w();
    ax[k] = axes[k].x(), ay[k] = axes[k].y(), az[k] = axes[k].z();
  }
  const V c1x = 0.5 - (y * y + z * z), c1y = x * y + w * z, c1z = x * z - w * y;
  const V c3x = x * z + w * y, c3y = y * z - w * x, c3z = 0.5 - (x * x + y * y);
  const V o1[6] = {c1x * c1x, c1x * c1y, c1x * c1z, c1y * c1y, c1y * c1z, c1z * c1z};
  const V o3[6] = {c3x * c3x, c3x * c3y, c3x * c3z, c3y * c3y, c3y * c3z, c3z * c3z};
  const auto turned = [&](V w1, V w2, V w3, V(&m)[6]) {
    const V s1 = 4.0 * (w1 - w2), s3 = 4.0 * (w3 - w2);
    for (int e = 0; e < 6; ++e) m[e] = s1 * o1[e] + s3 * o3[e];
    m[0] += w2;
    m[3] += w2;
    m[5] += w2;
  };
  const V sx = ax * ax, sy = ay * ay, sz = az * az;
  const V inverse_product = 1.0 / (sx * sy * sz);
  V potential[6], reach[6];
  turned(sy * sz * inverse_product, sx * sz * inverse_product, sx * sy * inverse_product, potential);
  turned(sx, sy, sz, reach);
  for (int k = 0; k < 4; ++k) {
    out[k].potential = {potential[0][k], potential[1][k], potential[2][k],
                        potential[3][k], potential[4][k], potential[5][k]};
    out[k].reach = {reach[0][k], reach[1][k], reach[2][k], reach[3][k], reach[4][k], reach[5][k]};
  }
}

EllipsoidContact ellipsoid_contact(const EllipsoidFrame& i, const Vec3& centre_i, const EllipsoidFrame& j,
                                   const Vec3& centre_j, double mu_i, double mu_j) {
  const Symmetric& mi = i.potential;
  const Symmetric& mj = j.potential;
  const Vec3 d0 = centre_j - centre_i;
  const PairMatrix own = pair_of(mi, mj);
  const PairVector both_d0 = pair_of(d0, d0);
  const PairVector own_d0 = own * both_d0;  // (M_i d0, M_j d0)
  const Pair f0 = dot(both_d0, own_d0);     // (f_i(c_j), f_j(c_i)) + 1
  PairVector d, g;                          // the arms P_i - c_i, P_j - c_j, and half the potentials' gradients there
  Pair mu;
  // Warm-started, both searches usually end after their first evaluation:
  // the two at once.
  const Pair sign{1.0, -1.0};
  if (!(f0[0] > 1.0 && f0[1] > 1.0 && mu_i > 0.0 && mu_j > 0.0 &&
        deepest_pair(own, {sign * swapped(own_d0.x), sign * swapped(own_d0.y), sign * swapped(own_d0.z)},
                     Pair{mu_i, mu_j}, d, g, mu))) [[unlikely]] {
    deepest_apart(mi, mj, d0, own_d0, f0, Pair{mu_i, mu_j}, d, g, mu);
  }
  // The outward normals there are opposite (Lagrange) when the bodies
  // just touch; the contact normal is along the average of the two unit
  // normals, g_i / |g_i| - g_j / |g_j|, here times |g_i| |g_j|:
  // s = |g_j| g_i - |g_i| g_j, from one root for both lengths.
  const Pair squares = dot(g, g);  // |g_i|^2, |g_j|^2
  const Pair lengths = root(squares);
  const PairVector weighted = swapped(lengths) * g;  // (|g_j| g_i, |g_i| g_j)
  const Vec3 sum = lane(weighted, 0) - lane(weighted, 1);
  const Vec3 di = lane(d, 0), dj = lane(d, 1);
  // Equivalent radius (see equivalent_radius): the curvature tensors sum to
  // K = M_i / |g_i| + M_j / |g_j| = K' / (|g_i| |g_j|) with
  // K' = |g_j| M_i + |g_i| M_j, so k1 k2 = s^T adj(K) s / |s|^2 =
  // s^T adj(K') s / (|g_i| |g_j|)^2 |s|^2; from the unnormalised normal, so
  // that it need not wait for the root.
  const double squared_length = sum.squaredNorm();
  const double product = quadratic_form(cofactors(mi.scaled(lengths[1]).plus(lengths[0], mj)), sum);
  const double scale = squares[0] * squares[1] * squared_length;  // R_e^2 times product
  // 1 / |s| = sqrt(|s|^2) / |s|^2 and R_e = (k1 k2)^(-1/2) =
  // sqrt(scale product) / product: one division and one root for both,
  // side by side rather than one after the other.
  const Pair denominator{squared_length, std::max(product, 1e-300 * scale)};
  const Pair roots = root(Pair{1.0, scale} * denominator) * (1.0 / denominator);
  const Vec3 gap = di - dj - d0;  // P_i - P_j
  EllipsoidContact c;
  c.normal = roots[0] * sum;
  c.overlap = roots[0] * gap.dot(sum);  // (P_i - P_j) . n
  c.first_point = centre_i + di;
  c.second_point = centre_j + dj;
  c.point = 0.5 * (c.first_point + c.second_point);
  c.effective_radius = roots[1];
  c.multiplier_i = mu[0];
  c.multiplier_j = mu[1];
  return c;
}

namespace {

// Several contacts at once: lanes 2k and 2k + 1 of a vector of doubles
// hold contact k's two searches (body i's, body j's), as Pair does for one
// contact, and every step of ellipsoid_contact is taken in all lanes with
// the same operations in the same order, so lane by lane the same bits.
// The searches end after one evaluation in nearly every contact, so the
// lanes rarely part: a contact whose searches do not end there goes the
// scalar way (deepest_apart) on its own, the others' lanes unchanged.
using Quad = double __attribute__((vector_size(32)));
using Octet = double __attribute__((vector_size(64)));
template <int L>
struct LaneType;
template <>
struct LaneType<2> {
  using type = Pair;
};
template <>
struct LaneType<4> {
  using type = Quad;
};
template <>
struct LaneType<8> {
  using type = Octet;
};
template <int L>
using Lanes = typename LaneType<L>::type;

template <typename V>
using LaneMask = decltype(V{} < V{});

template <typename V>
struct LaneVector {
  V x, y, z;
};
template <typename V>
struct LaneMatrix {
  V xx, xy, xz, yy, yz, zz;
};

// Each lane's partner: lanes 2k and 2k + 1 swapped (a shuffle within each
// pair, which AVX does in one instruction).
// (__builtin_shufflevector: GCC 12 and Clang both have it; the fuzz
// targets are built with Clang.)
template <typename T>
inline T partner(T a) {
  if constexpr (sizeof(T) == 16) {
    return __builtin_shufflevector(a, a, 1, 0);
  } else if constexpr (sizeof(T) == 32) {
    return __builtin_shufflevector(a, a, 1, 0, 3, 2);
  } else {
    static_assert(sizeof(T) == 64);
    return __builtin_shufflevector(a, a, 1, 0, 3, 2, 5, 4, 7, 6);
  }
}
template <typename V>
inline LaneVector<V> partner(const LaneVector<V>& v) {
  return {partner(v.x), partner(v.y), partner(v.z)};
}
template <typename V>
inline LaneMatrix<V> partner(const LaneMatrix<V>& m) {
  return {partner(m.xx), partner(m.xy), partner(m.xz), partner(m.yy), partner(m.yz), partner(m.zz)};
}

template <typename M>
inline bool any(M m) {
  bool out = false;
  for (int k = 0; k < static_cast<int>(sizeof(M) / 8); ++k) out |= m[k] != 0;
  return out;
}
template <typename M>
inline bool all(M m) {
  bool out = true;
  for (int k = 0; k < static_cast<int>(sizeof(M) / 8); ++k) out &= m[k] != 0;
  return out;
}

template <typename V>
inline LaneMatrix<V> cofactors(const LaneMatrix<V>& a) {
  return {a.yy * a.zz - a.yz * a.yz, a.xz * a.yz - a.xy * a.zz, a.xy * a.yz - a.xz * a.yy,
          a.xx * a.zz - a.xz * a.xz, a.xy * a.xz - a.xx * a.yz, a.xx * a.yy - a.xy * a.xy};
}
template <typename V>
inline LaneVector<V> operator*(const LaneMatrix<V>& m, const LaneVector<V>& v) {
  return {m.xx * v.x + m.xy * v.y + m.xz * v.z, m.xy * v.x + m.yy * v.y + m.yz * v.z,
          m.xz * v.x + m.yz * v.y + m.zz * v.z};
}
template <typename V>
inline LaneVector<V> operator*(V s, const LaneVector<V>& v) {
  return {s * v.x, s * v.y, s * v.z};
}
template <typename V>
inline LaneVector<V> operator+(const LaneVector<V>& a, const LaneVector<V>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename V>
inline LaneVector<V> operator-(const LaneVector<V>& a, const LaneVector<V>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename V>
inline V dot(const LaneVector<V>& a, const LaneVector<V>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
// A dot product summed as Eigen sums a Vec3's (x + (y + z), halves
// first), for the lanes to match ellipsoid_contact's Eigen products.
template <typename V>
inline V split_dot(const LaneVector<V>& a, const LaneVector<V>& b) {
  return a.x * b.x + (a.y * b.y + a.z * b.z);
}
template <typename V, typename M>
inline LaneVector<V> select(M m, const LaneVector<V>& a, const LaneVector<V>& b) {
  return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
}
template <typename V>
inline V root(V a) {
  if constexpr (sizeof(V) == 32) {
    return V{std::sqrt(a[0]), std::sqrt(a[1]), std::sqrt(a[2]), std::sqrt(a[3])};
  } else {
    V out;
    for (int k = 0; k < static_cast<int>(sizeof(V) / 8); ++k) out[k] = std::sqrt(a[k]);
    return out;
  }
}

// deepest_pair in every lane. `ended` comes in as the contacts whose
// warm searches may try it (both multipliers positive, each centre
// outside the other body) and goes out as those whose searches both ended
// there (in both of the contact's lanes).
template <typename V>
inline void deepest_lanes(const LaneMatrix<V>& own, const LaneVector<V>& rhs, V mu, LaneMask<V>& ended,
                          LaneVector<V>& d, LaneVector<V>& gradient, V& ends) {
  const LaneMatrix<V> other = partner(own);
  const LaneMatrix<V> a{other.xx + mu * own.xx, other.xy + mu * own.xy, other.xz + mu * own.xz,
                        other.yy + mu * own.yy, other.yz + mu * own.yz, other.zz + mu * own.zz};
  const LaneMatrix<V> adj = cofactors(a);
  const V det = a.xx * adj.xx + a.xy * adj.xy + a.xz * adj.xz;
  const LaneVector<V> u = adj * rhs;
  const LaneVector<V> w = own * u;
  const LaneVector<V> z = adj * w;
  const V wz = dot(w, z);
  const V det2 = det * det;
  const V e = dot(u, w) - det2;
  const V size = e < 0.0 ? -e : e;
  LaneMask<V> ok = ended & (size < kSecondOrder * det2) & (wz > 0.0) & (det > 1e-300) & (2.0 * mu * wz + e * det > 0.0);
  ok &= partner(ok);
  ended = ok;
  if (!any(ok)) return;
  const LaneVector<V> own_z = own * z;
  LaneMask<V> first_order = size < kFirstOrder * det2;
  first_order &= partner(first_order);
  const V q = first_order ? 2.0 * wz : 4.0 * wz * wz - 3.0 * e * dot(z, own_z);
  const V step = first_order ? e : 2.0 * e * wz;
  LaneMask<V> in_range = (q > 1e-300) & (q < 1e300) & (det < 1e300);
  ended = ok & in_range & partner(in_range);
  const V t = step / q, inverse_det = 1.0 / det;
  ends = mu + t * det;
  const LaneVector<V> near = u - t * z;
  const LaneVector<V> near_gradient = w - t * own_z;
  if (all(first_order | ~ended)) {
    d = inverse_det * near;
    gradient = inverse_det * near_gradient;
  } else {
    const LaneVector<V> second = adj * own_z;
    const V tt = t * t;
    d = inverse_det * select(first_order, near, near + tt * second);
    gradient = inverse_det * select(first_order, near_gradient, near_gradient + tt * (own * second));
  }
}

template <int L>
void contacts_in_lanes(const EllipsoidQuery* q, EllipsoidContact* out) {
  using V = Lanes<L>;
  constexpr int kContacts = L / 2;
  LaneMatrix<V> own;
  LaneVector<V> d0;
  V mu;
  for (int k = 0; k < kContacts; ++k) {
    const Symmetric& mi = q[k].i->potential;
    const Symmetric& mj = q[k].j->potential;
    const Vec3 between = q[k].centre_j - q[k].centre_i;
    for (int s = 0; s < 2; ++s) {
      const Symmetric& m = s == 0 ? mi : mj;
      const int l = 2 * k + s;
      own.xx[l] = m.xx, own.xy[l] = m.xy, own.xz[l] = m.xz, own.yy[l] = m.yy, own.yz[l] = m.yz, own.zz[l] = m.zz;
      d0.x[l] = between.x(), d0.y[l] = between.y(), d0.z[l] = between.z();
    }
    mu[2 * k] = q[k].mu_i;
    mu[2 * k + 1] = q[k].mu_j;
  }
  const LaneVector<V> own_d0 = own * d0;  // (M_i d0, M_j d0) in each contact's lanes
  const V f0 = dot(d0, own_d0);
  V sign;
  for (int l = 0; l < L; ++l) sign[l] = l % 2 == 0 ? 1.0 : -1.0;
  const LaneMask<V> odd = sign < 0.0;
  const LaneVector<V> rhs{sign * partner(own_d0.x), sign * partner(own_d0.y), sign * partner(own_d0.z)};
  LaneMask<V> ended = (f0 > 1.0) & (mu > 0.0);
  ended &= partner(ended);
  LaneVector<V> d, g;
  V ends{};
  if (any(ended)) deepest_lanes(own, rhs, mu, ended, d, g, ends);
  for (int k = 0; k < kContacts; ++k) {
    const int l = 2 * k;
    if (ended[l]) [[likely]] {
      continue;
    }
    const PairVector own_d0_k{Pair{own_d0.x[l], own_d0.x[l + 1]}, Pair{own_d0.y[l], own_d0.y[l + 1]},
                              Pair{own_d0.z[l], own_d0.z[l + 1]}};
    PairVector dk, gk;
    Pair muk;
    deepest_apart(q[k].i->potential, q[k].j->potential, q[k].centre_j - q[k].centre_i, own_d0_k, Pair{f0[l], f0[l + 1]},
                  Pair{mu[l], mu[l + 1]}, dk, gk, muk);
    for (int s = 0; s < 2; ++s) {
      d.x[l + s] = dk.x[s], d.y[l + s] = dk.y[s], d.z[l + s] = dk.z[s];
      g.x[l + s] = gk.x[s], g.y[l + s] = gk.y[s], g.z[l + s] = gk.z[s];
      ends[l + s] = muk[s];
    }
  }
  // As in ellipsoid_contact; lane 2k + 1 holds -s of contact k, whose
  // squares and products are those of s.
  const V squares = dot(g, g);
  const V lengths = root(squares);
  const LaneVector<V> weighted = partner(lengths) * g;
  const LaneVector<V> sum = weighted - partner(weighted);
  const V squared_length = split_dot(sum, sum);
  const V other_length = partner(lengths);
  const LaneMatrix<V> scaled{other_length * own.xx, other_length * own.xy, other_length * own.xz,
                             other_length * own.yy, other_length * own.yz, other_length * own.zz};
  const LaneMatrix<V> k_sum = cofactors(LaneMatrix<V>{scaled.xx + partner(scaled.xx), scaled.xy + partner(scaled.xy),
                                                      scaled.xz + partner(scaled.xz), scaled.yy + partner(scaled.yy),
                                                      scaled.yz + partner(scaled.yz), scaled.zz + partner(scaled.zz)});
  const V x = sum.x, y = sum.y, z = sum.z;
  const V product = (k_sum.xx * (x * x) + k_sum.yy * (y * y) + k_sum.zz * (z * z)) +
                    2.0 * (k_sum.xy * (x * y) + k_sum.xz * (x * z) + k_sum.yz * (y * z));
  const V scale = squares * partner(squares) * squared_length;
  const V floor = 1e-300 * scale;
  const V denominator = odd ? (product < floor ? floor : product) : squared_length;
  const V roots = root((odd ? scale : V{} + 1.0) * denominator) * (1.0 / denominator);
  const LaneVector<V> gap = d - partner(d) - d0;
  const V along = split_dot(gap, sum);
  for (int k = 0; k < kContacts; ++k) {
    const int l = 2 * k;
    EllipsoidContact& c = out[k];
    const Vec3 s(sum.x[l], sum.y[l], sum.z[l]);
    c.normal = roots[l] * s;
    c.overlap = roots[l] * along[l];
    c.first_point = q[k].centre_i + Vec3(d.x[l], d.y[l], d.z[l]);
    c.second_point = q[k].centre_j + Vec3(d.x[l + 1], d.y[l + 1], d.z[l + 1]);
    c.point = 0.5 * (c.first_point + c.second_point);
    c.effective_radius = roots[l + 1];
    c.multiplier_i = ends[l];
    c.multiplier_j = ends[l + 1];
  }
}

}  // namespace

void ellipsoid_contacts(const EllipsoidQuery* queries, EllipsoidContact* out, int count) {
  constexpr int kLanes = 4;
  constexpr int kContacts = kLanes / 2;
  int k = 0;
  for (; k + kContacts <= count; k += kContacts) contacts_in_lanes<kLanes>(queries + k, out + k);
  for (; k < count; ++k) {
    const EllipsoidQuery& q = queries[k];
    out[k] = ellipsoid_contact(*q.i, q.centre_i, *q.j, q.centre_j, q.mu_i, q.mu_j);
  }
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
