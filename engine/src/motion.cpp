#include "motion.h"

#include <algorithm>
#include <cmath>

#include "parallel.h"

namespace dem {

void sum_particle_forces(Particles& particles, const ContactTable& table, int threads) {
  const auto n = static_cast<std::int64_t>(particles.size());
  const ContactIndex& index = table.index;
  DEM_PARALLEL_FOR(threads, n)
  for (std::int64_t i = 0; i < n; ++i) {
    Vec2 force = Vec2::Zero();
    double moment = 0.0;
    for (std::int32_t k = index.pair_offsets[i]; k < index.pair_offsets[i + 1]; ++k) {
      const std::int32_t entry = index.pair_entries[k];
      const ContactForce& c = table.pair_forces[entry >> 1];
      if ((entry & 1) == 0) {
        force += c.force;
        moment += c.moment_first;
      } else {
        force -= c.force;
        moment += c.moment_second;
      }
    }
    for (std::int32_t k = index.wall_offsets[i]; k < index.wall_offsets[i + 1]; ++k) {
      const ContactForce& c = table.wall_forces[index.wall_entries[k]];
      force += c.force;
      moment += c.moment_first;
    }
    particles.force[i] = force;
    particles.moment[i] = moment;
  }
}

void sum_wall_forces(Walls& walls, const std::vector<WallContact>& contacts, const std::vector<ContactForce>& forces) {
  std::fill(walls.force.begin(), walls.force.end(), Vec2::Zero());
  std::fill(walls.moment.begin(), walls.moment.end(), 0.0);
  std::fill(walls.normal_force.begin(), walls.normal_force.end(), 0.0);
  std::fill(walls.contacts.begin(), walls.contacts.end(), 0);
  std::fill(walls.normal_force_arm.begin(), walls.normal_force_arm.end(), 0.0);
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const WallContact& c = contacts[k];
    if (!c.state.touching) continue;
    const WallDef& wall = walls.def[c.wall];
    const Vec2 on_wall = -forces[k].force;
    const Vec2 arm = c.state.point - wall.point;
    // Compressive normal force: the particle pushes the wall away from its particle side.
    const double normal = -on_wall.dot(wall_normal(wall));
    walls.force[c.wall] += on_wall;
    walls.moment[c.wall] += cross(arm, on_wall);
    walls.normal_force[c.wall] += normal;
    walls.normal_force_arm[c.wall] += normal * arm.dot(wall.direction);
    ++walls.contacts[c.wall];
  }
}

double integrate_motion(Particles& particles, const std::vector<Vec2>& reference, const Vec2& gravity,
                        double global_alpha, double dt, int threads) {
  const auto n = static_cast<std::int64_t>(particles.size());
  // Global damping C = alpha m, C* = alpha I (eq. 34) in the central
  // difference form of eqs. 35-36.
  const double keep = 1.0 - 0.5 * global_alpha * dt;
  const double scale = 1.0 / (1.0 + 0.5 * global_alpha * dt);
  double max_moved = 0.0;
  DEM_PARALLEL_FOR_MAX(threads, n, max_moved)
  for (std::int64_t i = 0; i < n; ++i) {
    const double m = particles.mass[i];
    // Body force m g added to the force sum (Cundall & Strack, Motion).
    const Vec2 force = particles.force[i] + m * gravity;
    particles.velocity[i] = (particles.velocity[i] * keep + force * (dt / m)) * scale;  // eq. 35
    particles.angular_velocity[i] =
        (particles.angular_velocity[i] * keep + particles.moment[i] * (dt / particles.inertia[i])) * scale;  // eq. 36
    particles.position[i] += particles.velocity[i] * dt;          // eq. 22a
    particles.rotation[i] += particles.angular_velocity[i] * dt;  // eq. 23a
    max_moved = std::max(max_moved, (particles.position[i] - reference[i]).squaredNorm());
  }
  return std::sqrt(max_moved);
}

}  // namespace dem
