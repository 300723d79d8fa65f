// What the steering commands change in a session's world, whatever its
// dimension: each a visit of the session's world (on_world,
// world_session.h), the wire's vectors taken as the engine's of that
// dimension. A 2D world refuses out-of-plane vectors (CommandError); the
// engine's own checks throw DefinitionError. Simulation checks a command's
// arguments before it calls these.
#pragma once

#include "dem/protocol/messages.h"
#include "dem/service/world_session.h"
#include "dem/world.h"

namespace dem::service {

void set_wall_velocity(WorldSession& session, WallId wall, const protocol::Vector3& velocity,
                       const protocol::Vector3& angular_velocity);
void set_wall_servo(WorldSession& session, WallId wall, const ServoDef& servo);
void set_damping(WorldSession& session, const DampingDef& damping);
void set_time_step_fraction(WorldSession& session, double fraction);
void set_friction(WorldSession& session, MaterialId material, double friction);
void set_gravity(WorldSession& session, const protocol::Vector3& gravity);

}  // namespace dem::service
