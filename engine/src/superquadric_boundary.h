// A superquadric's boundary in the forms its contact searches share: turns
// of the frame, the powers of eq. 34, the boundary point by its radial
// parameter, and the function's value and gradient at a point of the plane.
#pragma once

#include <cmath>

#include "superquadric.h"

namespace dem {

// A turn by a fixed angle, its cosine and sine taken once.
struct Turn {
  double c, s;
  explicit Turn(double angle) : c(std::cos(angle)), s(std::sin(angle)) {}
  Turn(double cosine, double sine) : c(cosine), s(sine) {}
  Vec2 operator()(const Vec2& v) const { return {c * v.x() - s * v.y(), s * v.x() + c * v.y()}; }
  Turn inverse() const { return {c, -s}; }
  // This turn followed by the inverse of `other` (the angle difference).
  Turn minus(const Turn& other) const { return {c * other.c + s * other.s, s * other.c - c * other.s}; }
};

// t^n for t >= 0, by products when n is 0, 2 or 4.
inline double power(double t, double n) {
  if (n == 4.0) {
    const double t2 = t * t;
    return t2 * t2;
  }
  if (n == 2.0) return t * t;
  if (n == 0.0) return 1.0;
  return std::pow(t, n);
}

// The boundary point in direction t from the centre, in the particle's
// frame: p(t) = (a cos t, b sin t) / (|cos t|^n + |sin t|^n)^(1/n). It
// traces the same boundary as eq. 35 but is smooth in t (eq. 35's
// |cos|^(2/n) has an infinite slope where the long sides are flattest, the
// likeliest place to touch), so Newton steps converge on it.
inline Vec2 radial_point(const Superquadric& s, double c, double sn) {
  const double w = power(std::abs(c), s.n) + power(std::abs(sn), s.n);
  double scale;  // w^(-1/n)
  if (s.n == 4.0) {
    scale = 1.0 / std::sqrt(std::sqrt(w));
  } else if (s.n == 2.0) {
    scale = 1.0 / std::sqrt(w);
  } else {
    scale = std::pow(w, -1.0 / s.n);
  }
  return {s.a * c * scale, s.b * sn * scale};
}

// The radial parameter of a boundary point given in the body's frame:
// p(t) lies along (a cos t, b sin t).
inline double radial_parameter(const Superquadric& s, const Vec2& local) {
  return std::atan2(local.y() / s.b, local.x() / s.a);
}

// f of eq. 34 and its gradient at a point of the plane, for a placed body
// turned by `turn`.
struct Level {
  double value;
  Vec2 gradient;
};
inline Level level(const PlacedSuperquadric& body, const Turn& turn, const Vec2& point) {
  const Superquadric& s = body.shape;
  const Vec2 local = turn.inverse()(point - body.centre);
  const double x = std::abs(local.x()) / s.a, y = std::abs(local.y()) / s.b;
  const double xn1 = s.n == 4.0 ? x * x * x : std::pow(x, s.n - 1.0);
  const double yn1 = s.n == 4.0 ? y * y * y : std::pow(y, s.n - 1.0);
  const Vec2 gradient(std::copysign(s.n * xn1 / s.a, local.x()), std::copysign(s.n * yn1 / s.b, local.y()));
  return {xn1 * x + yn1 * y - 1.0, turn(gradient)};
}

}  // namespace dem
