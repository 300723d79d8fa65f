// The tangential (shear) part of a contact in either dimension. In 2D the
// shear history is BALL's signed scalar F_s along t_i = e_i rotated
// clockwise (Cundall & Strack, Fig. 2-3); in 3D it is a vector in the
// tangent plane. These overloads are all the force laws need to know.
#pragma once

#include <cmath>

#include "dem/snapshot.h"
#include "inline.h"

namespace dem {

// Relative velocity of the first body's surface point with respect to the
// second's (Cundall & Strack eq. 11); e points from the first to the second.
DEM_INLINE Vec2 relative_contact_velocity(const Vec2& v1, double w1, double r1, const Vec2& v2, double w2, double r2,
                                          const Vec2& e) {
  return (v1 - v2) - (w1 * r1 + w2 * r2) * clockwise_perpendicular(e);
}
DEM_INLINE Vec3 relative_contact_velocity(const Vec3& v1, const Vec3& w1, double r1, const Vec3& v2, const Vec3& w2,
                                          double r2, const Vec3& e) {
  return (v1 + w1.cross(r1 * e)) - (v2 - w2.cross(r2 * e));
}

// Tangential part of a relative velocity: s_dot (eq. 13) in 2D, the
// projection on the tangent plane in 3D.
DEM_INLINE double tangential_velocity(const Vec2& relative, const Vec2& e) {
  return relative.dot(clockwise_perpendicular(e));
}
DEM_INLINE Vec3 tangential_velocity(const Vec3& relative, const Vec3& e) { return relative - relative.dot(e) * e; }

// The shear force as a vector (F_s t_i in 2D); the first body receives minus this.
DEM_INLINE Vec2 shear_vector(double shear, const Vec2& e) { return shear * clockwise_perpendicular(e); }
DEM_INLINE Vec3 shear_vector(const Vec3& shear, const Vec3&) { return shear; }

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

DEM_INLINE double squared_shear(double shear) { return shear * shear; }
DEM_INLINE double squared_shear(const Vec3& shear) { return shear.squaredNorm(); }

// a where c holds, else b, component by component. The force pass over
// packed rows (contact_batch.h) runs the laws as straight-line code, so
// they choose between values instead of branching.
DEM_INLINE double choose(bool c, double a, double b) { return c ? a : b; }
DEM_INLINE Vec3 choose(bool c, const Vec3& a, const Vec3& b) {
  return {c ? a.x() : b.x(), c ? a.y() : b.y(), c ? a.z() : b.z()};
}

// Coulomb limit (Cundall & Strack eq. 19): a spring force beyond it is held
// at it, keeping its direction, and the contact slides. limit >= 0; squares
// compare without a root.
DEM_INLINE double held_at(double shear, double, double limit, bool sliding) {
  return sliding ? (shear < 0.0 ? -limit : limit) : shear;  // sliding: |shear| > limit >= 0
}
DEM_INLINE Vec3 held_at(const Vec3& shear, double magnitude2, double limit, bool sliding) {
  return shear * (sliding ? limit / std::sqrt(magnitude2) : 1.0);  // sliding: magnitude2 > limit^2 >= 0
}
template <typename State>
DEM_INLINE void apply_coulomb_limit(State& s, double limit) {
  const double magnitude2 = squared_shear(s.shear);
  s.sliding = magnitude2 > limit * limit;
  s.shear = held_at(s.shear, magnitude2, limit, s.sliding);
}

// Keeps the shear history in the tangent plane as the contact turns. In 2D
// F_s is measured along t_i, which turns with the contact already; in 3D the
// vector is projected on the new tangent plane and keeps its magnitude.
DEM_INLINE void carry_shear(double&, const Vec2&) {}
DEM_INLINE void carry_shear(Vec3& shear, const Vec3& e) {
  const double magnitude2 = shear.squaredNorm();
  const Vec3 projected = shear - shear.dot(e) * e;
  const double projected2 = projected.squaredNorm();
  const double scale = projected2 > 0.0 ? std::sqrt(magnitude2 / projected2) : 0.0;
  shear = choose(magnitude2 == 0.0, shear, Vec3(projected * scale));
}

// Moment of the tangential force about a body's centre, the contact lying a
// distance r along e: r times the lever below, F_s R in 2D (Cundall &
// Strack, resultant moments).
DEM_INLINE double shear_lever(double total_shear, const Vec2&) { return total_shear; }
DEM_INLINE Vec3 shear_lever(const Vec3& total_shear, const Vec3& e) { return e.cross(-total_shear); }
DEM_INLINE double shear_moment(double total_shear, double r, const Vec2& e) { return r * shear_lever(total_shear, e); }
DEM_INLINE Vec3 shear_moment(const Vec3& total_shear, double r, const Vec3& e) {
  return r * shear_lever(total_shear, e);
}

// The signed F_s of Fig. 3 in 2D, the magnitude in 3D, for reports.
inline double reported_shear(double shear) { return shear; }
inline double reported_shear(const Vec3& shear) { return shear.norm(); }

}  // namespace dem
