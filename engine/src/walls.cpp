#include "walls.h"

#include <algorithm>
#include <cmath>

namespace dem {

SegmentPoint closest_point(const WallDef& wall, const Vec2& x) {
  const double s = std::clamp((x - wall.point).dot(wall.direction), wall.h1, wall.h2);
  return {wall.point + s * wall.direction, s};
}

namespace {

// Servo-controlled wall (Randall 1989, 4.1): speed along the normal
// proportional to the force error, capped.
Vec2 servo_velocity(const WallDef& wall, double measured_normal_force) {
  const ServoDef& servo = *wall.motion.servo;
  const double speed = std::clamp(servo.gain * (servo.target_force - measured_normal_force),
                                  -servo.max_speed, servo.max_speed);
  return speed * wall_normal(wall);
}

}  // namespace

void move_walls(Walls& walls, double dt) {
  for (int w = 0; w < walls.size(); ++w) {
    WallDef& wall = walls.def[w];
    const bool servo = wall.motion.servo.has_value();
    const Vec2 velocity = servo ? servo_velocity(wall, walls.normal_force[w]) : wall.motion.velocity;
    const double omega = servo ? 0.0 : wall.motion.angular_velocity;
    wall.point += velocity * dt;
    if (omega != 0.0) {
      const double c = std::cos(omega * dt), s = std::sin(omega * dt);
      const Vec2 e = wall.direction;
      wall.direction = Vec2(c * e.x() - s * e.y(), s * e.x() + c * e.y()).normalized();
    }
    walls.last_velocity[w] = velocity;
    walls.last_angular_velocity[w] = omega;
  }
}

double max_wall_step(const Walls& walls, double dt) {
  double step = 0.0;
  for (int w = 0; w < walls.size(); ++w) {
    const WallDef& wall = walls.def[w];
    const double arm = std::max(std::abs(wall.h1), std::abs(wall.h2));
    const double speed = walls.last_velocity[w].norm() + std::abs(walls.last_angular_velocity[w]) * arm;
    step = std::max(step, speed * dt);
  }
  return step;
}

WallMeasure measure_wall(const Walls& walls, WallId id) {
  const WallDef& wall = walls.def[id];
  WallMeasure m;
  m.wall = id;
  m.force = walls.force[id];
  m.moment = walls.moment[id];
  m.normal_force = walls.normal_force[id];
  m.contacts = walls.contacts[id];
  m.point = wall.point;
  m.displacement = wall.point - walls.initial_point[id];
  // Cundall & Strack Table 1 note 1: eccentricity of the normal force about
  // the wall's centre, over half its length.
  if (m.normal_force != 0.0) {
    const double centre = 0.5 * (wall.h1 + wall.h2);
    const double half_length = 0.5 * (wall.h2 - wall.h1);
    m.eccentricity = (walls.normal_force_arm[id] / m.normal_force - centre) / half_length;
  }
  return m;
}

}  // namespace dem
