// Vector types and the few 2D identities the engine uses everywhere.
#pragma once

#include <Eigen/Core>

namespace dem {

using Vec2 = Eigen::Vector2d;

// z-component of the cross product of two in-plane vectors.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// omega (about z) cross r, for an in-plane r.
inline Vec2 cross(double omega, const Vec2& r) { return {-omega * r.y(), omega * r.x()}; }

// Unit vector rotated clockwise through 90 degrees: Cundall & Strack's t_i from e_i (Fig. 2).
inline Vec2 clockwise_perpendicular(const Vec2& e) { return {e.y(), -e.x()}; }

// Unit vector rotated counter-clockwise through 90 degrees.
inline Vec2 counter_clockwise_perpendicular(const Vec2& e) { return {-e.y(), e.x()}; }

}  // namespace dem
