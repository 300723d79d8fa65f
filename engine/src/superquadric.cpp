#include "superquadric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include "superquadric_boundary.h"
#include "superquadric_overlap.h"

namespace dem {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

Vec2 rotate(const Vec2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// |t|^p with the sign of t. The exponents the shapes use most (2/n for
// n = 4 and n = 2) have roots and products that cost far less than pow.
double signed_power(double t, double p) {
  if (p == 0.5) return std::copysign(std::sqrt(std::abs(t)), t);
  if (p == 1.0) return t;
  return std::copysign(std::pow(std::abs(t), p), t);
}

// Brent's minimisation (Brent 1973, the golden section with parabolic
// steps) of f on [lo, hi], starting from x inside it.
template <typename F>
double brent_minimise(F f, double lo, double hi, double x, double tolerance) {
  constexpr double kGolden = 0.3819660112501051;
  double w = x, v = x, fx = f(x), fw = fx, fv = fx;
  double d = 0.0, e = 0.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double middle = 0.5 * (lo + hi);
    const double tol1 = tolerance * std::abs(x) + 1e-12, tol2 = 2.0 * tol1;
    if (std::abs(x - middle) <= tol2 - 0.5 * (hi - lo)) break;
    bool golden = true;
    if (std::abs(e) > tol1) {
      // Try a parabola through x, w, v.
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      const double previous = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * previous) && p > q * (lo - x) && p < q * (hi - x)) {
        d = p / q;
        const double u = x + d;
        if (u - lo < tol2 || hi - u < tol2) d = std::copysign(tol1, middle - x);
        golden = false;
      }
    }
    if (golden) {
      e = (x >= middle ? lo : hi) - x;
      d = kGolden * e;
    }
    const double u = std::abs(d) >= tol1 ? x + d : x + std::copysign(tol1, d);
    const double fu = f(u);
    if (fu <= fx) {
      (u >= x ? lo : hi) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? lo : hi) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return x;
}

// The Newton steps' three evaluations (at t and t +- h) side by side in
// the lanes of an AVX vector (the fourth repeats the first), in a third
// of the instructions: the operations of radial_point and
// superquadric_function as written, lane by lane. (Not quite the bits of
// the scalar calls they replace: GCC 12's vectoriser fuses some of the
// scalar code's products and sums into vfmaddsub, -ffp-contract=off
// notwithstanding, and where it does depends on what is inlined.)
using Quad = double __attribute__((vector_size(32)));
using QuadBits = std::int64_t __attribute__((vector_size(32)));

inline Quad magnitude(Quad a) {
  return reinterpret_cast<Quad>(reinterpret_cast<QuadBits>(a) & (QuadBits{} + INT64_MAX));
}
inline Quad root(Quad a) { return Quad{std::sqrt(a[0]), std::sqrt(a[1]), std::sqrt(a[2]), std::sqrt(a[3])}; }
inline Quad power(Quad t, double n) {  // as power(t, n), lane by lane
  if (n == 4.0) {
    const Quad t2 = t * t;
    return t2 * t2;
  }
  if (n == 2.0) return t * t;
  if (n == 0.0) return Quad{} + 1.0;
  return Quad{std::pow(t[0], n), std::pow(t[1], n), std::pow(t[2], n), std::pow(t[3], n)};
}
// Body j's function at body i's boundary points in directions (c, sn),
// turned by `relative` and shifted by `offset` into j's frame.
inline Quad potentials(const Superquadric& i, const Superquadric& j, const Turn& relative, const Vec2& offset, Quad c,
                       Quad sn) {
  const Quad w = power(magnitude(c), i.n) + power(magnitude(sn), i.n);
  Quad scale;  // w^(-1/n)
  if (i.n == 4.0) {
    scale = 1.0 / root(root(w));
  } else if (i.n == 2.0) {
    scale = 1.0 / root(w);
  } else {
    const double e = -1.0 / i.n;
    scale = Quad{std::pow(w[0], e), std::pow(w[1], e), std::pow(w[2], e), std::pow(w[3], e)};
  }
  const Quad px = i.a * c * scale, py = i.b * sn * scale;
  const Quad x = (relative.c * px - relative.s * py) + offset.x();
  const Quad y = (relative.s * px + relative.c * py) + offset.y();
  return power(magnitude(x) / j.a, j.n) + power(magnitude(y) / j.b, j.n) - 1.0;
}

// The boundary point of body i (by its radial parameter t) that minimises
// body j's function (eqs. 36-37). From the last cycle's answer (or, without
// one, the best of a coarse scan), Newton steps on central differences;
// where they cannot be trusted (a curvature that is not positive, a step
// that would leave the neighbourhood) Brent's method finishes the search.
struct RadialAngle {
  double t;     // in [0, 2 pi)
  double c, s;  // cos t, sin t
};
RadialAngle minimise_potential(const PlacedSuperquadric& i, const Turn& turn_i, const PlacedSuperquadric& j,
                               const Turn& turn_j, double hint, bool use_hint) {
  // j's frame: rotate by -(theta_j), about j's centre.
  const Turn relative = turn_i.minus(turn_j);
  const Vec2 offset = turn_j.inverse()(i.centre - j.centre);
  auto potential_at = [&](double c, double s) {
    return superquadric_function(j.shape, relative(radial_point(i.shape, c, s)) + offset);
  };
  auto potential = [&](double t) { return potential_at(std::cos(t), std::sin(t)); };
  constexpr int kSamples = 24;
  constexpr double kStep = kTwoPi / kSamples;
  double best = hint;
  if (!use_hint) {
    double best_value = potential(0.0);
    best = 0.0;
    for (int k = 1; k < kSamples; ++k) {
      const double value = potential(k * kStep);
      if (value < best_value) best_value = value, best = k * kStep;
    }
  }
  // A step of 1e-5 keeps the differences' truncation (h^2) and round-off
  // (1e-16 / h) near 1e-10 in t; a Newton step below it leaves an error of
  // its square, so the search ends there. From the last cycle's answer one
  // step usually suffices.
  double t = best;
  constexpr double kDifference = 1e-5;
  // t +- h by the angle-sum formulas: one cosine and sine an iteration
  // instead of three (they were most of a contact's cost).
  static const double cos_h = std::cos(kDifference), sin_h = std::sin(kDifference);
  bool converged = false;
  double c = 0.0, sn = 0.0;
  for (int iteration = 0; iteration < 8 && !converged; ++iteration) {
    const double h = kDifference;
    c = std::cos(t), sn = std::sin(t);
    const Quad f =
        potentials(i.shape, j.shape, relative, offset, Quad{c, c * cos_h - sn * sin_h, c * cos_h + sn * sin_h, c},
                   Quad{sn, sn * cos_h + c * sin_h, sn * cos_h - c * sin_h, sn});
    const double f0 = f[0], fp = f[1], fm = f[2];
    const double slope = (fp - fm) / (2.0 * h), curvature = (fp - 2.0 * f0 + fm) / (h * h);
    if (!(curvature > 0.0)) break;
    const double step = -slope / curvature;
    if (std::abs(step) > 0.5 * kStep) break;
    t += step;
    converged = std::abs(step) < kDifference;
    if (converged) {
      // The last step is below 1e-5: its cosine and sine by two terms of
      // their series are exact in double precision.
      const double cos_step = 1.0 - 0.5 * step * step, sin_step = step * (1.0 - step * step / 6.0);
      const double turned_c = c * cos_step - sn * sin_step;
      sn = sn * cos_step + c * sin_step;
      c = turned_c;
    }
  }
  if (!converged) {
    t = brent_minimise(potential, best - kStep, best + kStep, best, 1e-10);
    c = std::cos(t), sn = std::sin(t);
  }
  return {std::fmod(std::fmod(t, kTwoPi) + kTwoPi, kTwoPi), c, sn};
}

}  // namespace

double superquadric_function(const Superquadric& s, const Vec2& p) {
  return power(std::abs(p.x()) / s.a, s.n) + power(std::abs(p.y()) / s.b, s.n) - 1.0;
}

Vec2 superquadric_point(const Superquadric& s, double alpha) {
  const double e = 2.0 / s.n;
  return {s.a * signed_power(std::cos(alpha), e), s.b * signed_power(std::sin(alpha), e)};
}

Curvature superquadric_curvature(const Superquadric& s, const Vec2& p) {
  // Derivatives of f (eq. 34) at p; eq. 39 with them, eq. 40 for the normal.
  const double n = s.n;
  const double x = std::abs(p.x()), y = std::abs(p.y());
  const double xa = x / s.a, yb = y / s.b;
  const double xa2 = power(xa, n - 2.0), yb2 = power(yb, n - 2.0);  // n = 4: squares
  const double fx = std::copysign(n / s.a * xa2 * xa, p.x());
  const double fy = std::copysign(n / s.b * yb2 * yb, p.y());
  const double fxx = n * (n - 1.0) / (s.a * s.a) * xa2;
  const double fyy = n * (n - 1.0) / (s.b * s.b) * yb2;
  const double gradient = std::hypot(fx, fy);
  const double denominator = fxx * fy * fy + fyy * fx * fx;  // f_xy = 0 for eq. 34
  const double cap = 1e3 * std::max(s.a, s.b);
  const double radius = denominator > 0.0 ? std::min(cap, gradient * gradient * gradient / denominator) : cap;
  return {radius, Vec2(fx, fy) / gradient};
}

SuperquadricContact superquadric_contact(const PlacedSuperquadric& i, const PlacedSuperquadric& j, double alpha_i_hint,
                                         double alpha_j_hint, bool use_hints) {
  SuperquadricContact c;
  const Turn turn_i(i.angle), turn_j(j.angle);
  const RadialAngle on_i = minimise_potential(i, turn_i, j, turn_j, alpha_i_hint, use_hints);
  const RadialAngle on_j = minimise_potential(j, turn_j, i, turn_i, alpha_j_hint, use_hints);
  c.alpha_i = on_i.t;
  c.alpha_j = on_j.t;
  // Circles of curvature at P_i and P_j (eqs. 38-41), in the plane.
  const Vec2 pi = radial_point(i.shape, on_i.c, on_i.s), pj = radial_point(j.shape, on_j.c, on_j.s);
  const Curvature ki = superquadric_curvature(i.shape, pi), kj = superquadric_curvature(j.shape, pj);
  const Vec2 ci = i.centre + turn_i(pi - ki.radius * ki.normal);
  const Vec2 cj = j.centre + turn_j(pj - kj.radius * kj.normal);
  const Vec2 between = cj - ci;
  const double d = between.norm();
  c.overlap = ki.radius + kj.radius - d;  // eq. 42
  c.radius_i = ki.radius;
  c.radius_j = kj.radius;
  c.first_point = i.centre + turn_i(pi);
  c.second_point = j.centre + turn_j(pj);
  c.normal = d > 0.0 ? Vec2(between / d) : Vec2(turn_i(ki.normal));
  c.point = ci + (ki.radius - 0.5 * c.overlap) * c.normal;
  if (c.overlap > 0.0) {
    if (const auto centroid = overlap_centroid(i, j, c, on_i.t, on_j.t)) c.point = *centroid;
  }
  return c;
}

SupportContact superquadric_line_contact(const PlacedSuperquadric& body, const Vec2& on_line, const Vec2& outward) {
  // The support point in direction u = outward (the boundary point that
  // reaches furthest past the line), local frame: where the boundary's
  // normal is u, x = a sgn(u_x) |a u_x|^(1/(n-1)) / S and likewise y, with
  // S making f = 0.
  const Superquadric& s = body.shape;
  const Vec2 u = rotate(outward, -body.angle);
  const double q = 1.0 / (s.n - 1.0);
  const double px = std::pow(std::abs(s.a * u.x()), q), py = std::pow(std::abs(s.b * u.y()), q);
  const double scale = std::pow(std::pow(px, s.n) + std::pow(py, s.n), 1.0 / s.n);
  const Vec2 local(std::copysign(s.a * px / scale, u.x()), std::copysign(s.b * py / scale, u.y()));
  const Vec2 point = body.centre + rotate(local, body.angle);
  SupportContact contact{(point - on_line).dot(outward), point, superquadric_curvature(s, local).radius, point};
  if (contact.overlap > 0.0) {
    if (const auto centroid = line_overlap_centroid(body, on_line, outward, contact)) contact.centroid = *centroid;
  }
  return contact;
}

double superquadric_bounding_radius(const Superquadric& s) {
  const double larger = std::max(s.a, s.b);
  if (s.n <= 2.0) return larger;  // inside the ellipse of its semi-axes
  // The farthest boundary point (eq. 35) over a quadrant: sampled finely,
  // then a margin far above the sampling error of a smooth maximum.
  constexpr int kSamples = 4096;
  double farthest = larger;
  for (int k = 1; k < kSamples; ++k) {
    const double alpha = 0.5 * std::numbers::pi * k / kSamples;
    farthest = std::max(farthest, superquadric_point(s, alpha).norm());
  }
  return farthest > larger ? farthest * (1.0 + 1e-6) : larger;
}

SuperquadricMass superquadric_mass(const Superquadric& s) {
  // Dirichlet's integral over a quadrant of (x/a)^n + (y/b)^n <= 1:
  //   integral of x^p y^q dA = a^(p+1) b^(q+1) / n^2 G((p+1)/n) G((q+1)/n) / G((p+q+2)/n + 1).
  const double n = s.n;
  const double g1 = std::tgamma(1.0 / n), g3 = std::tgamma(3.0 / n);
  const double area = 4.0 * s.a * s.b / (n * n) * g1 * g1 / std::tgamma(2.0 / n + 1.0);
  const double polar =
      4.0 * (s.a * s.a * s.a * s.b + s.a * s.b * s.b * s.b) / (n * n) * g1 * g3 / std::tgamma(4.0 / n + 1.0);
  return {area, polar};
}

}  // namespace dem
