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

namespace {

// Local non-viscous damping (Miyata eq. 33, per component as PFC applies
// it): each component of the resultant loses alpha' times its magnitude,
// against the velocity component.
template <typename Derived, typename VelocityDerived>
auto local_damping(const Eigen::MatrixBase<Derived>& force, const Eigen::MatrixBase<VelocityDerived>& velocity,
                   double alpha) {
  using V = typename Derived::PlainObject;
  V damping = V::Zero();
  for (Eigen::Index d = 0; d < force.size(); ++d) {
    if (velocity[d] != 0.0) damping[d] = -alpha * std::abs(force[d]) * (velocity[d] > 0.0 ? 1.0 : -1.0);
  }
  return damping;
}
double local_damping(double moment, double spin, double alpha) {
  return spin == 0.0 ? 0.0 : -alpha * std::abs(moment) * (spin > 0.0 ? 1.0 : -1.0);
}

double dot(double a, double b) { return a * b; }
double dot(const Vec3& a, const Vec3& b) { return a.dot(b); }

MotionStep& operator+=(MotionStep& a, const MotionStep& b) {
  a.max_travel = std::max(a.max_travel, b.max_travel);
  a.gravity_work += b.gravity_work;
  a.global_damping += b.global_damping;
  a.local_damping += b.local_damping;
  a.time_step_ratio = std::max(a.time_step_ratio, b.time_step_ratio);
  return a;
}

}  // namespace

// Euler's equations for a body with principal moments I_b (in its axes),
// turned by q: the angular acceleration I^-1 (M - omega x I omega), with I
// in world axes.
Vec3 angular_acceleration(const Quaternion& q, const Vec3& principal, const Vec3& moment, const Vec3& omega) {
  const Vec3 body_omega = q.conjugate() * omega;
  const Vec3 body_momentum = principal.cwiseProduct(body_omega);
  const Vec3 body_moment = q.conjugate() * moment - body_omega.cross(body_momentum);
  return q * body_moment.cwiseQuotient(principal);
}

template <int Dim>
MotionStep integrate_motion(Particles<Dim>& particles, const std::vector<Vec<Dim>>& reference,
                            const Periodic<Dim>& periodic, const Vec<Dim>& gravity, const DampingDef& damping,
                            bool tensor_rotation, double dt, int threads) {
  const bool wraps = periodic.any();
  const auto n = static_cast<std::int64_t>(particles.size());
  // Global damping C = alpha m, C* = alpha I (eq. 34) in the central
  // difference form of eqs. 35-36; Miyata eq. 32 lets rotation have its own constant.
  const double alpha = damping.global_alpha;
  const double alpha_rotation = damping.global_alpha_rotation.value_or(alpha);
  const double keep = 1.0 - 0.5 * alpha * dt, scale = 1.0 / (1.0 + 0.5 * alpha * dt);
  const double keep_rotation = 1.0 - 0.5 * alpha_rotation * dt;
  const double scale_rotation = 1.0 / (1.0 + 0.5 * alpha_rotation * dt);
  const double local = damping.local_alpha;
  const double local_rotation = damping.local_alpha_rotation.value_or(local);
  const auto partials = for_blocks<MotionStep>(n, threads, [&](std::int64_t begin, std::int64_t end, MotionStep& step) {
    for (std::int64_t i = begin; i < end; ++i) {
      const double m = particles.mass[i], inertia = particles.inertia[i];
      // Body force m g added to the force sum (Cundall & Strack, Motion).
      const Vec<Dim> resultant = particles.force[i] + m * gravity;
      const Vec<Dim> v0 = particles.velocity[i];
      const Spin<Dim> w0 = particles.angular_velocity[i];
      const Vec<Dim> local_force = local_damping(resultant, v0, local);
      const Spin<Dim> local_moment = local_damping(particles.moment[i], w0, local_rotation);
      particles.velocity[i] = (v0 * keep + (resultant + local_force) * (dt / m)) * scale;  // eq. 35
      Spin<Dim> spin_rate = (particles.moment[i] + local_moment) / inertia;
      if constexpr (Dim == 3) {
        if (tensor_rotation) {
          spin_rate = angular_acceleration(particles.rotation[i], particles.principal_inertia[i],
                                           particles.moment[i] + local_moment, w0);
        }
      }
      particles.angular_velocity[i] = (w0 * keep_rotation + spin_rate * dt) * scale_rotation;  // eq. 36
      const Vec<Dim>& v1 = particles.velocity[i];
      const Spin<Dim>& w1 = particles.angular_velocity[i];
      particles.position[i] += v1 * dt;                        // eq. 22a
      turn(particles.rotation[i], w1, dt);                     // eq. 23a
      if (wraps) periodic.wrap(particles.position[i]);
      step.max_travel = std::max(step.max_travel, periodic.separation(reference[i], particles.position[i]).norm());

      // Energy over the step, at the mid-step velocity the scheme is centred on.
      const Vec<Dim> v_mid = 0.5 * (v0 + v1);
      const Spin<Dim> w_mid = 0.5 * (w0 + w1);
      step.gravity_work += m * gravity.dot(v1) * dt;
      step.global_damping +=
          (alpha * m * v_mid.squaredNorm() + alpha_rotation * particles.spin_energy_product(i, w_mid)) * dt;
      step.local_damping -= (local_force.dot(v_mid) + dot(local_moment, w_mid)) * dt;

      // Randall 4.35-4.40: the stiffness the particle meets, K = d|sum F| / dx,
      // gives its own critical step 2 (m / K)^(1/2).
      const double force_norm = particles.force[i].norm();
      const double dx = v1.norm() * dt;
      const double change = std::abs(force_norm - particles.previous_force[i]);
      if (dx > 0.0 && change > 0.0) {
        step.time_step_ratio = std::max(step.time_step_ratio, dt / (2.0 * std::sqrt(m * dx / change)));
      }
      particles.previous_force[i] = force_norm;
    }
  });
  MotionStep total;
  for (const MotionStep& p : partials) total += p;
  return total;
}

template void sum_particle_forces(Particles<2>&, const ContactTable<2>&, int);
template void sum_particle_forces(Particles<3>&, const ContactTable<3>&, int);
template void sum_wall_forces(Walls<2>&, const std::vector<WallContact<2>>&, const std::vector<ContactForce<2>>&);
template void sum_wall_forces(Walls<3>&, const std::vector<WallContact<3>>&, const std::vector<ContactForce<3>>&);
template MotionStep integrate_motion(Particles<2>&, const std::vector<Vec2>&, const Periodic<2>&, const Vec2&,
                                     const DampingDef&, bool, double, int);
template MotionStep integrate_motion(Particles<3>&, const std::vector<Vec3>&, const Periodic<3>&, const Vec3&,
                                     const DampingDef&, bool, double, int);

}  // namespace dem
