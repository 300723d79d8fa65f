// A read view of a session's world in its dimension, and what the service
// reads through it: the one place the dimension is hidden for reading.
// WorldSession (world_session.h) steps and steers a world and holds its
// state; everything that only reads - the commands' answers, telemetry,
// stage progress, tables, snapshots - takes its view() and these
// functions, each a visit of the view over the engine and engine_readout.h.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "dem/protocol/messages.h"
#include "dem/service/engine_readout.h"
#include "dem/world.h"

namespace dem::service {

// Valid while the session is and until its world is replaced (WorldSession::restore).
using WorldView = std::variant<const BasicWorld<2>*, const BasicWorld<3>*>;

// `read(world)` on the world the view shows, whatever its dimension.
template <class Read>
decltype(auto) on_world(const WorldView& view, Read&& read) {
  return std::visit([&](const auto* world) -> decltype(auto) { return read(*world); }, view);
}

int wall_count(const WorldView& view);
WallId find_wall(const WorldView& view, std::string_view name);  // kInvalidId when unknown
std::string wall_name(const WorldView& view, WallId wall);
double wall_area(const WorldView& view, WallId wall);
DampingDef damping(const WorldView& view);
const std::vector<MaterialDef>& materials(const WorldView& view);
double critical_time_step(const WorldView& view);           // s, with the damping now
double undamped_critical_time_step(const WorldView& view);  // s, what a time step fraction is of
double kinetic_energy(const WorldView& view);               // J (a pass over the particles and the contacts)

// engine_readout.h's readers on the view.
protocol::WallForce read_wall(const WorldView& view, WallId wall);
std::vector<protocol::WallForce> read_walls(const WorldView& view);
protocol::ContactStats read_contact_stats(const WorldView& view);
std::vector<protocol::ContactEntry> query_contacts(const WorldView& view, const ContactFilter& filter);
std::optional<ServoLimits> default_servo_limits(const WorldView& view, WallId wall,
                                                const std::vector<ContactModelDef>& models);

}  // namespace dem::service
