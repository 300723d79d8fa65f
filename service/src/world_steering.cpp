#include "dem/service/world_steering.h"

#include <string>
#include <type_traits>

#include "dem/service/command_error.h"

namespace dem::service {

namespace {

// Wire vectors as engine quantities: a 2D world has no z, and turns about z only.
Vec2 vector_of(const protocol::Vector3& v, std::integral_constant<int, 2>, const std::string& what) {
  if (v.z != 0.0) {
    throw CommandError(protocol::ReplyStatus::kBadRequest, what + " has a z component, but the simulation is 2D");
  }
  return {v.x, v.y};
}
Vec3 vector_of(const protocol::Vector3& v, std::integral_constant<int, 3>, const std::string&) {
  return {v.x, v.y, v.z};
}
double spin_of(const protocol::Vector3& w, std::integral_constant<int, 2>, const std::string& what) {
  if (w.x != 0.0 || w.y != 0.0) {
    throw CommandError(protocol::ReplyStatus::kBadRequest, what + ": a 2D wall turns about z only, x and y must be 0");
  }
  return w.z;
}
Vec3 spin_of(const protocol::Vector3& w, std::integral_constant<int, 3>, const std::string&) { return {w.x, w.y, w.z}; }

}  // namespace

void set_wall_velocity(WorldSession& session, WallId wall, const protocol::Vector3& velocity,
                       const protocol::Vector3& angular_velocity) {
  on_world(session, [&]<int Dim>(BasicWorld<Dim>& world) {
    constexpr std::integral_constant<int, Dim> kDim{};
    WallMotionT<Dim> motion;
    motion.velocity = vector_of(velocity, kDim, "the velocity");
    motion.angular_velocity = spin_of(angular_velocity, kDim, "the angular velocity");
    world.set_wall_motion(wall, motion);
  });
}

void set_wall_servo(WorldSession& session, WallId wall, const ServoDef& servo) {
  on_world(session, [&]<int Dim>(BasicWorld<Dim>& world) {
    WallMotionT<Dim> motion;
    motion.servo = servo;
    world.set_wall_motion(wall, motion);
  });
}

void set_damping(WorldSession& session, const DampingDef& damping) {
  on_world(session, [&](auto& world) { world.set_damping(damping); });
}

void set_time_step_fraction(WorldSession& session, double fraction) {
  on_world(session, [&](auto& world) { world.set_time_step_fraction(fraction); });
}

void set_friction(WorldSession& session, MaterialId material, double friction) {
  on_world(session, [&](auto& world) { world.set_friction(material, friction); });
}

void set_gravity(WorldSession& session, const protocol::Vector3& gravity) {
  on_world(session, [&]<int Dim>(BasicWorld<Dim>& world) {
    world.set_gravity(vector_of(gravity, std::integral_constant<int, Dim>{}, "gravity"));
  });
}

}  // namespace dem::service
