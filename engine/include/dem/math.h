// Vector types, and what changes between two and three dimensions: the
// type of a spin (angular velocity, moment) and of an orientation. The
// engine is written once over Dim with these traits.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dem {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;
using Vec2 = Vec<2>;
using Vec3 = Vec<3>;
using Quaternion = Eigen::Quaterniond;

template <int Dim>
struct Space;

// In the plane, spins are scalars about z (counter-clockwise positive) and
// an orientation is an angle.
template <>
struct Space<2> {
  using Spin = double;
  using Orientation = double;
  static Spin zero_spin() { return 0.0; }
  static Orientation identity() { return 0.0; }
};

// In space, spins are vectors and an orientation is a unit quaternion.
template <>
struct Space<3> {
  using Spin = Vec3;
  using Orientation = Quaternion;
  static Spin zero_spin() { return Vec3::Zero(); }
  static Orientation identity() { return Quaternion::Identity(); }
};

template <int Dim>
using Spin = typename Space<Dim>::Spin;
template <int Dim>
using Orientation = typename Space<Dim>::Orientation;

// z-component of the cross product of two in-plane vectors.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
// omega (about z) cross r, for an in-plane r.
inline Vec2 cross(double omega, const Vec2& r) { return {-omega * r.y(), omega * r.x()}; }
inline Vec3 cross(const Vec3& a, const Vec3& b) { return a.cross(b); }

inline double magnitude(double spin) { return spin < 0.0 ? -spin : spin; }
inline double magnitude(const Vec3& spin) { return spin.norm(); }
inline double squared_magnitude(double spin) { return spin * spin; }
inline double squared_magnitude(const Vec3& spin) { return spin.squaredNorm(); }

// Unit vector rotated clockwise through 90 degrees: Cundall & Strack's t_i from e_i (Fig. 2).
inline Vec2 clockwise_perpendicular(const Vec2& e) { return {e.y(), -e.x()}; }
// Unit vector rotated counter-clockwise through 90 degrees.
inline Vec2 counter_clockwise_perpendicular(const Vec2& e) { return {-e.y(), e.x()}; }

}  // namespace dem
