// Walls as line segments (Cundall & Strack, Fig. 4), their motion and the
// resultants the particles exert on them.
#pragma once

#include <vector>

#include "dem/definitions.h"
#include "dem/measures.h"

namespace dem {

struct Walls {
  std::vector<WallDef> def;            // current P, e and commanded motion
  std::vector<Vec2> initial_point;     // P when the world was built (settlement)
  // The motion that carried each wall over the last cycle: the force law at
  // cycle N needs the velocity over [N-1, N], like the particles' x_dot_{N-1/2}.
  std::vector<Vec2> last_velocity;
  std::vector<double> last_angular_velocity;
  // Resultants from the last force pass (for servos and measures).
  std::vector<Vec2> force;
  std::vector<double> moment;
  std::vector<double> normal_force;
  std::vector<int> contacts;
  std::vector<double> normal_force_arm;  // sum of N_c * s_c, for the eccentricity

  int size() const { return static_cast<int>(def.size()); }
};

// The wall's normal: its direction rotated counter-clockwise (the particle side).
inline Vec2 wall_normal(const WallDef& wall) { return counter_clockwise_perpendicular(wall.direction); }

// Closest point of the segment to x, and its position s along the wall.
struct SegmentPoint {
  Vec2 point;
  double s;
};
SegmentPoint closest_point(const WallDef& wall, const Vec2& x);

// Velocity of a point q attached to a wall moving with (velocity, omega) about P.
inline Vec2 wall_point_velocity(const WallDef& wall, const Vec2& velocity, double omega, const Vec2& q) {
  return velocity + cross(omega, q - wall.point);
}

// Sets each wall's velocity for this cycle (servos from the last measured
// normal force) and moves P and e over one time step.
void move_walls(Walls& walls, double dt);

// Largest distance any point of any wall travelled in the last step.
double max_wall_step(const Walls& walls, double dt);

WallMeasure measure_wall(const Walls& walls, WallId id);

}  // namespace dem
