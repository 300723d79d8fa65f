// The tangential (shear) part of a contact in either dimension. In 2D the
// shear history is BALL's signed scalar F_s along t_i = e_i rotated
// clockwise (Cundall & Strack, Fig. 2-3); in 3D it is a vector in the
// tangent plane. These overloads are all the force laws need to know.
#pragma once

#include <cmath>

#include "dem/snapshot.h"

namespace dem {

// Relative velocity of the first body's surface point with respect to the
// second's (Cundall & Strack eq. 11); e points from the first to the second.
inline Vec2 relative_contact_velocity(const Vec2& v1, double w1, double r1, const Vec2& v2, double w2, double r2,
                                      const Vec2& e) {
  return (v1 - v2) - (w1 * r1 + w2 * r2) * clockwise_perpendicular(e);
}
inline Vec3 relative_contact_velocity(const Vec3& v1, const Vec3& w1, double r1, const Vec3& v2, const Vec3& w2,
                                      double r2, const Vec3& e) {
  return (v1 + w1.cross(r1 * e)) - (v2 - w2.cross(r2 * e));
}

// Tangential part of a relative velocity: s_dot (eq. 13) in 2D, the
// projection on the tangent plane in 3D.
inline double tangential_velocity(const Vec2& relative, const Vec2& e) {
  return relative.dot(clockwise_perpendicular(e));
}
inline Vec3 tangential_velocity(const Vec3& relative, const Vec3& e) { return relative - relative.dot(e) * e; }

// The shear force as a vector (F_s t_i in 2D); the first body receives minus this.
inline Vec2 shear_vector(double shear, const Vec2& e) { return shear * clockwise_perpendicular(e); }
inline Vec3 shear_vector(const Vec3& shear, const Vec3&) { return shear; }

inline double shear_magnitude(double shear) { return std::abs(shear); }
inline double shear_dot(double a, double b) { return a * b; }
inline double shear_dot(const Vec3& a, const Vec3& b) { return a.dot(b); }
inline double shear_magnitude(const Vec3& shear) { return shear.norm(); }

// Scales the shear force down to the Coulomb limit, keeping its direction (eq. 19).
inline void clamp_shear(double& shear, double limit) { shear = std::copysign(limit, shear); }
inline void clamp_shear(Vec3& shear, double limit) {
  const double magnitude = shear.norm();
  if (magnitude > 0.0) shear *= limit / magnitude;
}

// Coulomb limit (Cundall & Strack eq. 19): a spring force beyond it is held at it and the contact slides.
template <typename State>
void apply_coulomb_limit(State& s, double limit) {
  s.sliding = shear_magnitude(s.shear) > limit;
  if (s.sliding) clamp_shear(s.shear, limit);
}

// Keeps the shear history in the tangent plane as the contact turns. In 2D
// F_s is measured along t_i, which turns with the contact already; in 3D the
// vector is projected on the new tangent plane and keeps its magnitude.
inline void carry_shear(double&, const Vec2&) {}
inline void carry_shear(Vec3& shear, const Vec3& e) {
  const double magnitude = shear.norm();
  if (magnitude == 0.0) return;
  shear -= shear.dot(e) * e;
  const double projected = shear.norm();
  shear = projected > 0.0 ? Vec3(shear * (magnitude / projected)) : Vec3::Zero();
}

// Moment of the tangential force about a body's centre, the contact lying a
// distance r along e: F_s R in 2D (Cundall & Strack, resultant moments).
inline double shear_moment(double total_shear, double r, const Vec2&) { return total_shear * r; }
inline Vec3 shear_moment(const Vec3& total_shear, double r, const Vec3& e) { return r * e.cross(-total_shear); }

// The signed F_s of Fig. 3 in 2D, the magnitude in 3D, for reports.
inline double reported_shear(double shear) { return shear; }
inline double reported_shear(const Vec3& shear) { return shear.norm(); }

}  // namespace dem
