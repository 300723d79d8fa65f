#include "walls.h"

#include <algorithm>
#include <cmath>

#include "box_control.h"

namespace dem {

WallPoint<2> closest_point(const WallDefT<2>& wall, const Vec2& x) { return closest_planar_point(wall, x); }

Vec3 closest_point_on_triangle(const std::array<Vec3, 3>& t, const Vec3& x) {
  // Ericson (2005), Real-Time Collision Detection 5.1.5: by the Voronoi
  // region of x among the corners, edges and face.
  const Vec3 &a = t[0], &b = t[1], &c = t[2];
  const Vec3 ab = b - a, ac = c - a, ax = x - a;
  const double d1 = ab.dot(ax), d2 = ac.dot(ax);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bx = x - b;
  const double d3 = ab.dot(bx), d4 = ac.dot(bx);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cx = x - c;
  const double d5 = ab.dot(cx), d6 = ac.dot(cx);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

Vec3 triangular_coordinates(const std::array<Vec3, 3>& t, const Vec3& q) {
  // Areas of the sub-triangles over the whole (eqs. 57-59), signed by the face's normal.
  const Vec3 normal = (t[1] - t[0]).cross(t[2] - t[0]);
  const double whole = normal.squaredNorm();
  return {(t[1] - q).cross(t[2] - q).dot(normal) / whole, (t[2] - q).cross(t[0] - q).dot(normal) / whole,
          (t[0] - q).cross(t[1] - q).dot(normal) / whole};
}

WallPoint<3> closest_point(const WallDefT<3>& wall, const Vec3& x) {
  if (!wall.triangles.empty()) {
    Vec3 best = closest_point_on_triangle(wall.triangles[0], x);
    for (std::size_t k = 1; k < wall.triangles.size(); ++k) {
      const Vec3 q = closest_point_on_triangle(wall.triangles[k], x);
      if ((q - x).squaredNorm() < (best - x).squaredNorm()) best = q;
    }
    const Vec3 d = best - wall.point;
    return {best, Eigen::Vector2d(d.dot(wall.direction), d.dot(wall.direction2))};
  }
  return closest_planar_point(wall, x);
}

Eccentricity<2> wall_centre(const WallDefT<2>& wall) { return 0.5 * (wall.h1 + wall.h2); }
Eccentricity<3> wall_centre(const WallDefT<3>& wall) { return {0.5 * (wall.h1 + wall.h2), 0.5 * (wall.k1 + wall.k2)}; }
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
  if (!wall.triangles.empty()) {
    double area = 0.0;  // of all the faces
    for (const auto& t : wall.triangles) area += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
    return area;
  }
  return clipped(wall.h2 - wall.h1, wall.direction, periodic) * clipped(wall.k2 - wall.k1, wall.direction2, periodic);
}

void translate(WallDefT<2>& wall, const Vec2& shift) { wall.point += shift; }
void translate(WallDefT<3>& wall, const Vec3& shift) {
  wall.point += shift;
  for (auto& t : wall.triangles) {
    for (Vec3& corner : t) corner += shift;
  }
}

namespace {

// Servo-controlled wall (Randall 1989, 4.1): speed along the normal
// proportional to the force error, capped.
template <int Dim>
Vec<Dim> servo_velocity(const WallDefT<Dim>& wall, double measured_normal_force) {
  const ServoDef& servo = *wall.motion.servo;
  const double speed =
      std::clamp(servo.gain * (servo.target_force - measured_normal_force), -servo.max_speed, servo.max_speed);
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
  for (auto& t : wall.triangles) {
    for (Vec3& corner : t) corner = wall.point + turn * (corner - wall.point);
  }
  wall.direction = (turn * wall.direction).normalized();
  // Keep u and v orthonormal against round-off.
  const Vec3 v = turn * wall.direction2;
  wall.direction2 = (v - v.dot(wall.direction) * wall.direction).normalized();
}

double reach(const WallDefT<2>& wall) { return std::max(std::abs(wall.h1), std::abs(wall.h2)); }
double reach(const WallDefT<3>& wall) {
  if (!wall.triangles.empty()) {
    double r = 0.0;
    for (const auto& t : wall.triangles) {
      for (const Vec3& corner : t) r = std::max(r, (corner - wall.point).norm());
    }
    return r;
  }
  return std::hypot(std::max(std::abs(wall.h1), std::abs(wall.h2)), std::max(std::abs(wall.k1), std::abs(wall.k2)));
}

}  // namespace

template <int Dim>
void move_walls(Walls<Dim>& walls, double dt) {
  // A box control drives its walls: their velocities from its strain rates
  // and servos, on the stresses of the last force pass.
  std::vector<Vec<Dim>> box_velocity;
  std::vector<bool> in_box;
  if (walls.box) {
    box_velocity.assign(static_cast<std::size_t>(walls.size()), Vec<Dim>::Zero());
    in_box.assign(static_cast<std::size_t>(walls.size()), false);
    set_box_velocities(walls, *walls.box, box_velocity);
    for (const BoxAxisDef& a : walls.box->axes) in_box[a.lower.index()] = in_box[a.upper.index()] = true;
  }
  for (int w = 0; w < walls.size(); ++w) {
    WallDefT<Dim>& wall = walls.def[w];
    if (wall.removed) {  // out of the world: it stays where it was taken out
      walls.last_velocity[w] = Vec<Dim>::Zero();
      walls.last_angular_velocity[w] = Space<Dim>::zero_spin();
      continue;
    }
    const bool boxed = walls.box && in_box[static_cast<std::size_t>(w)];
    const bool servo = !boxed && wall.motion.servo.has_value();
    const Vec<Dim> velocity = boxed   ? box_velocity[static_cast<std::size_t>(w)]
                              : servo ? servo_velocity(wall, walls.normal_force[w])
                                      : wall.motion.velocity;
    const Spin<Dim> omega = boxed || servo ? Space<Dim>::zero_spin() : wall.motion.angular_velocity;
    translate(wall, velocity * dt);
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
WallMeasureT<Dim> measure_wall(const Walls<Dim>& walls, WallId wall_id) {
  const std::size_t id = wall_id.index();
  const WallDefT<Dim>& wall = walls.def[id];
  WallMeasureT<Dim> m;
  m.wall = wall_id;
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
      m.eccentricity =
          (walls.normal_force_arm[id] / m.normal_force - wall_centre(wall)).cwiseQuotient(wall_half_size(wall));
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
