// What the service reads of a session's world, whatever its dimension:
// the commands' answers, telemetry, stage progress and the steering
// commands' checks take these, each a visit of the session's world
// (on_world, world_session.h) over the engine and engine_readout.h.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dem/protocol/messages.h"
#include "dem/service/engine_readout.h"
#include "dem/service/world_session.h"
#include "dem/world.h"

namespace dem::service {

int wall_count(const WorldSession& session);
WallId find_wall(const WorldSession& session, std::string_view name);  // kInvalidId when unknown
std::string wall_name(const WorldSession& session, WallId wall);
double wall_area(const WorldSession& session, WallId wall);
DampingDef damping(const WorldSession& session);
const std::vector<MaterialDef>& materials(const WorldSession& session);
double critical_time_step(const WorldSession& session);           // s, with the damping now
double undamped_critical_time_step(const WorldSession& session);  // s, what a time step fraction is of
double kinetic_energy(const WorldSession& session);               // J (a pass over the particles and the contacts)

// engine_readout.h's readers on the session's world.
protocol::WallForce read_wall(const WorldSession& session, WallId wall);
std::vector<protocol::WallForce> read_walls(const WorldSession& session);
protocol::ContactStats read_contact_stats(const WorldSession& session);
std::vector<protocol::ContactEntry> query_contacts(const WorldSession& session, const ContactFilter& filter);
std::optional<ServoLimits> default_servo_limits(const WorldSession& session, WallId wall,
                                                const std::vector<ContactModelDef>& models);

}  // namespace dem::service
