#include "dem/service/world_view.h"

namespace dem::service {

int wall_count(const WorldView& view) {
  return on_world(view, [](const auto& world) { return world.wall_count(); });
}

WallId find_wall(const WorldView& view, std::string_view name) {
  return on_world(view, [&](const auto& world) { return world.find_wall(name); });
}

std::string wall_name(const WorldView& view, WallId wall) {
  return on_world(view, [&](const auto& world) { return world.wall(wall).name; });
}

double wall_area(const WorldView& view, WallId wall) {
  return on_world(view, [&](const auto& world) { return world.wall_area(wall); });
}

DampingDef damping(const WorldView& view) {
  return on_world(view, [](const auto& world) { return world.damping(); });
}

const std::vector<MaterialDef>& materials(const WorldView& view) {
  return on_world(view, [](const auto& world) -> const std::vector<MaterialDef>& { return world.materials(); });
}

double critical_time_step(const WorldView& view) {
  return on_world(view, [](const auto& world) { return world.critical_time_step(); });
}

double undamped_critical_time_step(const WorldView& view) {
  return on_world(view, [](const auto& world) { return world.undamped_critical_time_step(); });
}

double kinetic_energy(const WorldView& view) {
  return on_world(view, [](const auto& world) { return world.assembly_measures().kinetic_energy; });
}

protocol::WallForce read_wall(const WorldView& view, WallId wall) {
  return on_world(view, [&](const auto& world) { return read_wall(world, wall); });
}

std::vector<protocol::WallForce> read_walls(const WorldView& view) {
  return on_world(view, [](const auto& world) { return read_walls(world); });
}

protocol::ContactStats read_contact_stats(const WorldView& view) {
  return on_world(view, [](const auto& world) { return read_contact_stats(world); });
}

std::vector<protocol::ContactEntry> query_contacts(const WorldView& view, const ContactFilter& filter) {
  return on_world(view, [&](const auto& world) { return query_contacts(world, filter); });
}

std::optional<ServoLimits> default_servo_limits(const WorldView& view, WallId wall,
                                                const std::vector<ContactModelDef>& models) {
  return on_world(view, [&](const auto& world) { return default_servo_limits(world, wall, models); });
}

}  // namespace dem::service
