// Walls: 2D segments (Cundall & Strack, Fig. 4) and 3D rectangles, their
// motion and the resultants the particles exert on them.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "dem/definitions.h"
#include "dem/measures.h"
#include "periodic.h"

namespace dem {

template <int Dim>
struct Walls {
  std::vector<WallDefT<Dim>> def;       // current P, directions and commanded motion
  std::vector<Vec<Dim>> initial_point;  // P when the world was built (settlement)
  // The motion that carried each wall over the last cycle: the force law at
  // cycle N needs the velocity over [N-1, N], like the particles' x_dot_{N-1/2}.
  std::vector<Vec<Dim>> last_velocity;
  std::vector<Spin<Dim>> last_angular_velocity;
  // Resultants from the last force pass (for servos and measures).
  std::vector<Vec<Dim>> force;
  std::vector<Spin<Dim>> moment;
  std::vector<double> normal_force;
  std::vector<int> contacts;
  std::vector<Eccentricity<Dim>> normal_force_arm;  // sum of N_c times its position in the wall
  // Element-test control of a box of these walls, when set: it replaces
  // the motion of the walls it drives.
  std::optional<BoxControlT<Dim>> box;
  double depth = 1.0;  // 2D: out-of-plane depth for the box's stresses

  int size() const { return static_cast<int>(def.size()); }
};

// Why an id names none of the walls ("no wall 7"), or nothing if it names
// one: the one check of a wall id, for the world's edits and accessors
// (BasicWorld::missing_wall) and the box control's axes. A removed wall
// keeps its id and still answers to it.
template <int Dim>
std::optional<std::string> missing_wall(const std::vector<WallDefT<Dim>>& walls, WallId id) {
  if (id.valid() && id.index() < walls.size()) return std::nullopt;
  return "no wall " + to_string(id);
}

// The wall's normal, towards the particle side: e rotated counter-clockwise
// in 2D, u x v in 3D.
inline Vec2 wall_normal(const WallDefT<2>& wall) { return counter_clockwise_perpendicular(wall.direction); }
inline Vec3 wall_normal(const WallDefT<3>& wall) { return wall.direction.cross(wall.direction2); }

// Closest point of the wall to x, and its coordinates in the wall
// (along e in 2D; along u and v in 3D).
template <int Dim>
struct WallPoint {
  Vec<Dim> point;
  Eccentricity<Dim> coordinates;
};
WallPoint<2> closest_point(const WallDefT<2>& wall, const Vec2& x);
WallPoint<3> closest_point(const WallDefT<3>& wall, const Vec3& x);

// closest_point of a segment (2D) or a rectangle (3D; its triangle faces,
// if any, are not looked at): inline for the batched wall rows
// (wall_batch.h), and what closest_point computes, so both give the same bits.
inline WallPoint<2> closest_planar_point(const WallDefT<2>& wall, const Vec2& x) {
  const double s = std::clamp((x - wall.point).dot(wall.direction), wall.h1, wall.h2);
  return {wall.point + s * wall.direction, s};
}
inline WallPoint<3> closest_planar_point(const WallDefT<3>& wall, const Vec3& x) {
  const Vec3 d = x - wall.point;
  const double s = std::clamp(d.dot(wall.direction), wall.h1, wall.h2);
  const double t = std::clamp(d.dot(wall.direction2), wall.k1, wall.k2);
  return {wall.point + s * wall.direction + t * wall.direction2, Eigen::Vector2d(s, t)};
}

// The point of a triangle nearest to x (faces, edges and corners).
Vec3 closest_point_on_triangle(const std::array<Vec3, 3>& t, const Vec3& x);

// Triangular coordinates (L_I, L_J, L_K) of a point of the triangle's
// plane (Miyata et al. 2002, eqs. 57-59); all > 0 inside the face.
Vec3 triangular_coordinates(const std::array<Vec3, 3>& t, const Vec3& q);

// Moves the wall (its reference point and any faces) by shift.
void translate(WallDefT<2>& wall, const Vec2& shift);
void translate(WallDefT<3>& wall, const Vec3& shift);

// Position of the wall's centre in its own coordinates, and its half size.
Eccentricity<2> wall_centre(const WallDefT<2>& wall);
Eccentricity<3> wall_centre(const WallDefT<3>& wall);
Eccentricity<2> wall_half_size(const WallDefT<2>& wall);
Eccentricity<3> wall_half_size(const WallDefT<3>& wall);

// Length (2D) or area (3D) of the wall; along a direction that runs along a
// periodic axis, at most one period (a plate across a periodic cell).
double wall_extent(const WallDefT<2>& wall, const Periodic<2>& periodic);
double wall_extent(const WallDefT<3>& wall, const Periodic<3>& periodic);

// Velocity of a point q attached to a wall moving with (velocity, omega) about P.
template <int Dim>
Vec<Dim> wall_point_velocity(const WallDefT<Dim>& wall, const Vec<Dim>& velocity, const Spin<Dim>& omega,
                             const Vec<Dim>& q) {
  return velocity + cross(omega, Vec<Dim>(q - wall.point));
}

// Sets each wall's velocity for this cycle (servos from the last measured
// normal force) and moves P and its directions over one time step.
template <int Dim>
void move_walls(Walls<Dim>& walls, double dt);

// Largest distance any point of any wall travelled in the last step.
template <int Dim>
double max_wall_step(const Walls<Dim>& walls, double dt);

template <int Dim>
WallMeasureT<Dim> measure_wall(const Walls<Dim>& walls, WallId id);

}  // namespace dem
