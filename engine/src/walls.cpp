#include "walls.h"

#include <algorithm>
#include <cmath>

namespace dem {

WallPoint<2> closest_point(const WallDefT<2>& wall, const Vec2& x) {
  const double s = std::clamp((x - wall.point).dot(wall.direction), wall.h1, wall.h2);
  return {wall.point + s * wall.direction, s};
}

WallPoint<3> closest_point(const WallDefT<3>& wall, const Vec3& x) {
  const Vec3 d = x - wall.point;
  const double s = std::clamp(d.dot(wall.direction), wall.h1, wall.h2);
  const double t = std::clamp(d.dot(wall.direction2), wall.k1, wall.k2);
  return {wall.point + s * wall.direction + t * wall.direction2, Eigen::Vector2d(s, t)};
}

Eccentricity<2> wall_centre(const WallDefT<2>& wall) { return 0.5 * (wall.h1 + wall.h2); }
Eccentricity<3> wall_centre(const WallDefT<3>& wall) {
  return {0.5 * (wall.h1 + wall.h2), 0.5 * (wall.k1 + wall.k2)};
}
Eccentricity<2> wall_half_size(const WallDefT<2>& wall) { return 0.5 * (wall.h2 - wall.h1); }
Eccentricity<3> wall_half_size(const WallDefT<3>& wall) {
  return {0.5 * (wall.h2 - wall.h1), 0.5 * (wall.k2 - wall.k1)};
}
namespace {

// The wall's length along a unit direction, clipped to the period of the
// axis it runs along (if it runs along one).
template <int Dim>
double clipped(double length, const Vec<Dim>& direction, const Periodic<Dim>& periodic) {
  for (int d = 0; d < Dim; ++d) {
    if (periodic.repeats(d) && std::abs(std::abs(direction[d]) - 1.0) < 1e-12) {
      return std::min(length, periodic.length[d]);
    }
  }
  return length;
}

}  // namespace

double wall_extent(const WallDefT<2>& wall, const Periodic<2>& periodic) {
  return clipped(wall.h2 - wall.h1, wall.direction, periodic);
}
double wall_extent(const WallDefT<3>& wall, const Periodic<3>& periodic) {
  return clipped(wall.h2 - wall.h1, wall.direction, periodic) * clipped(wall.k2 - wall.k1, wall.direction2, periodic);
}

namespace {

// Servo-controlled wall (Randall 1989, 4.1): speed along the normal
// proportional to the force error, capped.
template <int Dim>
Vec<Dim> servo_velocity(const WallDefT<Dim>& wall, double measured_normal_force) {
  const ServoDef& servo = *wall.motion.servo;
  const double speed = std::clamp(servo.gain * (servo.target_force - measured_normal_force),
                                  -servo.max_speed, servo.max_speed);
  return speed * wall_normal(wall);
}

// Turns the wall's directions about P through omega dt.
void rotate(WallDefT<2>& wall, double omega, double dt) {
  if (omega == 0.0) return;
  const double c = std::cos(omega * dt), s = std::sin(omega * dt);
  const Vec2 e = wall.direction;
  wall.direction = Vec2(c * e.x() - s * e.y(), s * e.x() + c * e.y()).normalized();
}

void rotate(WallDefT<3>& wall, const Vec3& omega, double dt) {
  const double angle = omega.norm() * dt;
  if (angle == 0.0) return;
  const Eigen::AngleAxisd turn(angle, omega.normalized());
  wall.direction = (turn * wall.direction).normalized();
  // Keep u and v orthonormal against round-off.
  const Vec3 v = turn * wall.direction2;
  wall.direction2 = (v - v.dot(wall.direction) * wall.direction).normalized();
}

double reach(const WallDefT<2>& wall) { return std::max(std::abs(wall.h1), std::abs(wall.h2)); }
double reach(const WallDefT<3>& wall) {
  return std::hypot(std::max(std::abs(wall.h1), std::abs(wall.h2)), std::max(std::abs(wall.k1), std::abs(wall.k2)));
}

}  // namespace

template <int Dim>
void move_walls(Walls<Dim>& walls, double dt) {
  for (int w = 0; w < walls.size(); ++w) {
    WallDefT<Dim>& wall = walls.def[w];
    const bool servo = wall.motion.servo.has_value();
    const Vec<Dim> velocity = servo ? servo_velocity(wall, walls.normal_force[w]) : wall.motion.velocity;
    const Spin<Dim> omega = servo ? Space<Dim>::zero_spin() : wall.motion.angular_velocity;
    wall.point += velocity * dt;
    rotate(wall, omega, dt);
    walls.last_velocity[w] = velocity;
    walls.last_angular_velocity[w] = omega;
  }
}

template <int Dim>
double max_wall_step(const Walls<Dim>& walls, double dt) {
  double step = 0.0;
  for (int w = 0; w < walls.size(); ++w) {
    const double speed =
        walls.last_velocity[w].norm() + magnitude(walls.last_angular_velocity[w]) * reach(walls.def[w]);
    step = std::max(step, speed * dt);
  }
  return step;
}

template <int Dim>
WallMeasureT<Dim> measure_wall(const Walls<Dim>& walls, WallId id) {
  const WallDefT<Dim>& wall = walls.def[id];
  WallMeasureT<Dim> m;
  m.wall = id;
  m.force = walls.force[id];
  m.moment = walls.moment[id];
  m.normal_force = walls.normal_force[id];
  m.contacts = walls.contacts[id];
  m.point = wall.point;
  m.displacement = wall.point - walls.initial_point[id];
  // Cundall & Strack Table 1 note 1: eccentricity of the normal force about
  // the wall's centre, over half its length (per direction in 3D).
  if (m.normal_force != 0.0) {
    if constexpr (Dim == 2) {
      m.eccentricity = (walls.normal_force_arm[id] / m.normal_force - wall_centre(wall)) / wall_half_size(wall);
    } else {
      m.eccentricity = (walls.normal_force_arm[id] / m.normal_force - wall_centre(wall))
                           .cwiseQuotient(wall_half_size(wall));
    }
  }
  return m;
}

template void move_walls(Walls<2>&, double);
template void move_walls(Walls<3>&, double);
template double max_wall_step(const Walls<2>&, double);
template double max_wall_step(const Walls<3>&, double);
template WallMeasureT<2> measure_wall(const Walls<2>&, WallId);
template WallMeasureT<3> measure_wall(const Walls<3>&, WallId);

}  // namespace dem
