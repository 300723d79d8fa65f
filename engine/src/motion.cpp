#include "motion.h"

#include <algorithm>
#include <cmath>

#include "parallel.h"

namespace dem {

template <int Dim>
void sum_particle_forces(Particles<Dim>& particles, const ContactTable<Dim>& table, int threads) {
  const auto n = static_cast<std::int64_t>(particles.size());
  const ContactIndex& index = table.index;
  DEM_PARALLEL_FOR(threads, n)
  for (std::int64_t i = 0; i < n; ++i) {
    Vec<Dim> force = Vec<Dim>::Zero();
    Spin<Dim> moment = Space<Dim>::zero_spin();
    for (std::int32_t k = index.pair_offsets[i]; k < index.pair_offsets[i + 1]; ++k) {
      const std::int32_t entry = index.pair_entries[k];
      const ContactForce<Dim>& c = table.pair_forces[entry >> 1];
      if ((entry & 1) == 0) {
        force += c.force;
        moment += c.moment_first;
      } else {
        force -= c.force;
        moment += c.moment_second;
      }
    }
    for (std::int32_t k = index.wall_offsets[i]; k < index.wall_offsets[i + 1]; ++k) {
      const ContactForce<Dim>& c = table.wall_forces[index.wall_entries[k]];
      force += c.force;
      moment += c.moment_first;
    }
    particles.force[i] = force;
    particles.moment[i] = moment;
  }
}

template <int Dim>
void sum_wall_forces(Walls<Dim>& walls, const std::vector<WallContact<Dim>>& contacts,
                     const std::vector<ContactForce<Dim>>& forces) {
  std::fill(walls.force.begin(), walls.force.end(), Vec<Dim>::Zero());
  std::fill(walls.moment.begin(), walls.moment.end(), Space<Dim>::zero_spin());
  std::fill(walls.normal_force.begin(), walls.normal_force.end(), 0.0);
  std::fill(walls.contacts.begin(), walls.contacts.end(), 0);
  std::fill(walls.normal_force_arm.begin(), walls.normal_force_arm.end(), zero_eccentricity<Dim>());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const WallContact<Dim>& c = contacts[k];
    if (!c.state.touching) continue;
    const WallDefT<Dim>& wall = walls.def[c.wall];
    const Vec<Dim> on_wall = -forces[k].force;
    // Compressive normal force: the particle pushes the wall away from its particle side.
    const double normal = -on_wall.dot(wall_normal(wall));
    walls.force[c.wall] += on_wall;
    walls.moment[c.wall] += cross(Vec<Dim>(c.state.point - wall.point), on_wall);
    walls.normal_force[c.wall] += normal;
    walls.normal_force_arm[c.wall] += normal * closest_point(wall, c.state.point).coordinates;
    ++walls.contacts[c.wall];
  }
}

namespace {

// Turns an orientation through omega dt (eq. 23a): an angle in 2D, a unit
// quaternion turned about omega in 3D.
void turn(double& angle, double omega, double dt) { angle += omega * dt; }
void turn(Quaternion& q, const Vec3& omega, double dt) {
  const double angle = omega.norm() * dt;
  if (angle == 0.0) return;
  q = (Quaternion(Eigen::AngleAxisd(angle, omega.normalized())) * q).normalized();
}

}  // namespace

template <int Dim>
double integrate_motion(Particles<Dim>& particles, const std::vector<Vec<Dim>>& reference, const Vec<Dim>& gravity,
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
    const Vec<Dim> force = particles.force[i] + m * gravity;
    particles.velocity[i] = (particles.velocity[i] * keep + force * (dt / m)) * scale;  // eq. 35
    particles.angular_velocity[i] =
        (particles.angular_velocity[i] * keep + particles.moment[i] * (dt / particles.inertia[i])) * scale;  // eq. 36
    particles.position[i] += particles.velocity[i] * dt;  // eq. 22a
    turn(particles.rotation[i], particles.angular_velocity[i], dt);  // eq. 23a
    max_moved = std::max(max_moved, (particles.position[i] - reference[i]).squaredNorm());
  }
  return std::sqrt(max_moved);
}

template void sum_particle_forces(Particles<2>&, const ContactTable<2>&, int);
template void sum_particle_forces(Particles<3>&, const ContactTable<3>&, int);
template void sum_wall_forces(Walls<2>&, const std::vector<WallContact<2>>&, const std::vector<ContactForce<2>>&);
template void sum_wall_forces(Walls<3>&, const std::vector<WallContact<3>>&, const std::vector<ContactForce<3>>&);
template double integrate_motion(Particles<2>&, const std::vector<Vec2>&, const Vec2&, double, double, int);
template double integrate_motion(Particles<3>&, const std::vector<Vec3>&, const Vec3&, double, double, int);

}  // namespace dem
