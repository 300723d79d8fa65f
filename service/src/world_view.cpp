#include "dem/service/world_view.h"

namespace dem::service {

int wall_count(const WorldSession& session) {
  return on_world(session, [](const auto& world) { return world.wall_count(); });
}

WallId find_wall(const WorldSession& session, std::string_view name) {
  return on_world(session, [&](const auto& world) { return world.find_wall(name); });
}

std::string wall_name(const WorldSession& session, WallId wall) {
  return on_world(session, [&](const auto& world) { return world.wall(wall).name; });
}

double wall_area(const WorldSession& session, WallId wall) {
  return on_world(session, [&](const auto& world) { return world.wall_area(wall); });
}

DampingDef damping(const WorldSession& session) {
  return on_world(session, [](const auto& world) { return world.damping(); });
}

const std::vector<MaterialDef>& materials(const WorldSession& session) {
  return on_world(session, [](const auto& world) -> const std::vector<MaterialDef>& { return world.materials(); });
}

double critical_time_step(const WorldSession& session) {
  return on_world(session, [](const auto& world) { return world.critical_time_step(); });
}

double undamped_critical_time_step(const WorldSession& session) {
  return on_world(session, [](const auto& world) { return world.undamped_critical_time_step(); });
}

double kinetic_energy(const WorldSession& session) {
  return on_world(session, [](const auto& world) { return world.assembly_measures().kinetic_energy; });
}

protocol::WallForce read_wall(const WorldSession& session, WallId wall) {
  return on_world(session, [&](const auto& world) { return read_wall(world, wall); });
}

std::vector<protocol::WallForce> read_walls(const WorldSession& session) {
  return on_world(session, [](const auto& world) { return read_walls(world); });
}

protocol::ContactStats read_contact_stats(const WorldSession& session) {
  return on_world(session, [](const auto& world) { return read_contact_stats(world); });
}

std::vector<protocol::ContactEntry> query_contacts(const WorldSession& session, const ContactFilter& filter) {
  return on_world(session, [&](const auto& world) { return query_contacts(world, filter); });
}

std::optional<ServoLimits> default_servo_limits(const WorldSession& session, WallId wall,
                                                const std::vector<ContactModelDef>& models) {
  return on_world(session, [&](const auto& world) { return default_servo_limits(world, wall, models); });
}

}  // namespace dem::service
