// The complete state of a World as plain data, for exact restart: a World
// rebuilt from a snapshot continues bit for bit as the original would have,
// and reports the same measures and contacts at once.
// The conversion layer (io/) turns it into a Protocol Buffers message.
#pragma once

#include <cstdint>
#include <vector>

#include "dem/definitions.h"

namespace dem {

// One touching contact: its history (Cundall & Strack eq. 18) and what the
// last force pass made of it. Contacts that do not touch carry no history,
// so only touching ones are stored.
struct ContactSnapshot {
  ParticleId first = kInvalidId;
  std::int32_t second = kInvalidId;  // a particle, or a wall when with_wall
  bool with_wall = false;
  double normal_force = 0.0;
  double shear_force = 0.0;
  bool sliding = false;
  double overlap = 0.0;
  double normal_damping = 0.0;
  double shear_damping = 0.0;
  Vec2 normal = Vec2::Zero();
  Vec2 point = Vec2::Zero();
  Vec2 force = Vec2::Zero();   // on the first particle
  double moment_first = 0.0;
  double moment_second = 0.0;
};

struct WallSnapshot {
  Vec2 initial_point = Vec2::Zero();  // for settlement
  Vec2 last_velocity = Vec2::Zero();  // the motion over the last cycle
  double last_angular_velocity = 0.0;
  Vec2 force = Vec2::Zero();          // resultants of the last force pass
  double moment = 0.0;
  double normal_force = 0.0;
  int contacts = 0;
  double normal_force_arm = 0.0;
};

struct WorldSnapshot {
  // The definition as it stands now: materials, contact models, damping,
  // gravity, threads, time-step settings; walls at their current position,
  // direction and commanded motion; particles at their current position,
  // (half-step) velocity and angular velocity.
  WorldDef def;
  std::vector<double> rotation;        // per particle
  std::vector<Vec2> force;             // per particle, last force sums
  std::vector<double> moment;          // per particle
  std::vector<WallSnapshot> walls;     // per wall
  std::vector<ContactSnapshot> contacts;
  std::uint64_t cycle = 0;
  double time = 0.0;
  double time_step = 0.0;           // s, as in use (not re-estimated on restore)
  double critical_time_step = 0.0;  // s
};

}  // namespace dem
