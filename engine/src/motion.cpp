#include "motion.h"

#include <algorithm>
#include <cmath>

#include "inline.h"
#include "motion_plain.h"
#include "parallel.h"

namespace dem {

void large_half_angle(double h2, double& cosine, double& sine_over_h) {
  const double h = std::sqrt(h2);
  cosine = std::cos(h);
  sine_over_h = std::sin(h) / h;
}

namespace {

// Turns an orientation through omega dt (eq. 23a): an angle in 2D; in 3D a
// unit quaternion turned about omega by the quaternion of the half angle
// h = |omega| dt / 2. Steps turn particles through tiny angles, where the
// series of cos h and sin(h)/h to h^6 is exact to round-off (the next terms
// are below 1e-20 for h < 0.01) and costs no sine or cosine.
//
// The turning quaternion is of unit length to round-off, so the product
// drifts from unit length only by round-off: it is scaled back when the
// drift passes 1e-12, not every step.
void turn(double& angle, double omega, double dt) { angle += omega * dt; }

DEM_INLINE void turn(Quaternion& q, const Vec3& omega, double dt) {
  const double hx = 0.5 * dt * omega.x(), hy = 0.5 * dt * omega.y(), hz = 0.5 * dt * omega.z();
  const double h2 = hx * hx + hy * hy + hz * hz;
  // The series' coefficients as products: a division each would cost more
  // than the rest of the step.
  constexpr double k2 = 1.0 / 2.0, k12 = 1.0 / 12.0, k30 = 1.0 / 30.0;
  constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0;
  double cosine = 1.0 - h2 * k2 * (1.0 - h2 * k12 * (1.0 - h2 * k30));
  double sine_over_h = 1.0 - h2 * k6 * (1.0 - h2 * k20 * (1.0 - h2 * k42));
  if (h2 >= 1e-4) large_half_angle(h2, cosine, sine_over_h);
  // (c, a) (w, v) = (c w - a.v, c v + w a + a x v), a = sin(h)/h (hx, hy, hz).
  turn_by(q.coeffs().data(), cosine, sine_over_h * hx, sine_over_h * hy, sine_over_h * hz);
}

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
  a.max_speed = std::max(a.max_speed, b.max_speed);
  a.gravity_work += b.gravity_work;
  a.global_damping += b.global_damping;
  a.local_damping += b.local_damping;
  a.continuum_work += b.continuum_work;
  a.time_step_ratio = std::max(a.time_step_ratio, b.time_step_ratio);
  return a;
}

// Euler's equations for a body with principal moments I_b (in its axes),
// turned by q: the angular acceleration I^-1 (M - omega x I omega), with I
// in world axes.
Vec3 angular_acceleration(const Quaternion& q, const Vec3& principal, const Vec3& moment, const Vec3& omega) {
  const Vec3 body_omega = q.conjugate() * omega;
  const Vec3 body_momentum = principal.cwiseProduct(body_omega);
  const Vec3 body_moment = q.conjugate() * moment - body_omega.cross(body_momentum);
  return q * body_moment.cwiseQuotient(principal);
}

}  // namespace

// What the law of motion needs besides the particles, by value: a block
// of the loop then reads only its own locals and the particles' arrays.
template <int Dim>
struct MotionConstants {
  Periodic<Dim> cell;
  Vec<Dim> gravity;
  double dt;
  // Global damping C = alpha m, C* = alpha I (eq. 34) in the central
  // difference form of eqs. 35-36: v' = (v keep + F dt / m) scale.
  double alpha, alpha_rotation, keep, scale, keep_rotation, scale_rotation;
  double local, local_rotation;  // Miyata eq. 33
  bool wraps;
  // Randall's fields (kField blocks only): the centripetal gravity, and the
  // continuum field before and in this step (zero rates when there is none).
  CentripetalGravityT<Dim> centripetal;
  ContinuumFieldT<Dim> continuum_before, continuum;
};

template <int Dim>
MotionConstants<Dim> motion_constants(const MotionInputs<Dim>& in) {
  const DampingDef& d = in.damping;
  const double dt = in.dt;
  MotionConstants<Dim> c{in.periodic,
                         in.gravity,
                         dt,
                         d.global_alpha,
                         d.global_alpha_rotation.value_or(d.global_alpha),
                         0.0,
                         0.0,
                         0.0,
                         0.0,
                         d.local_alpha,
                         d.local_alpha_rotation.value_or(d.local_alpha),
                         in.periodic.any()};
  c.keep = 1.0 - 0.5 * c.alpha * dt;
  c.scale = 1.0 / (1.0 + 0.5 * c.alpha * dt);
  c.keep_rotation = 1.0 - 0.5 * c.alpha_rotation * dt;
  c.scale_rotation = 1.0 / (1.0 + 0.5 * c.alpha_rotation * dt);
  if (in.centripetal != nullptr) c.centripetal = *in.centripetal;
  if (in.continuum_before != nullptr) c.continuum_before = *in.continuum_before;
  if (in.continuum != nullptr) c.continuum = *in.continuum;
  return c;
}

// The law of motion over particles [begin, end) for one kind of world:
// local damping, an ellipsoid's inertia tensor, the energy budget and
// Randall's fields (kField) are chosen at compile time, so the common step
// (round particles, no budget) carries none of them.
template <int Dim, bool kLocal, bool kTensor, bool kEnergy, bool kField>
void move_block(Particles<Dim>& p, const MotionConstants<Dim> c, std::int64_t begin, std::int64_t end,
                MotionStep& step) {
  Vec<Dim>* __restrict position = p.position.data();
  Vec<Dim>* __restrict velocity = p.velocity.data();
  Spin<Dim>* __restrict angular_velocity = p.angular_velocity.data();
  Orientation<Dim>* __restrict rotation = p.rotation.data();
  const Vec<Dim>* __restrict force = p.force.data();
  const Spin<Dim>* __restrict moment = p.moment.data();
  const Vec<Dim>* __restrict reference = p.reference_position.data();
  const double* __restrict mass = p.mass.data();
  const double* __restrict inertia = p.inertia.data();
  const double dt = c.dt;
  double max_travel2 = 0.0, max_speed2 = 0.0;
  for (std::int64_t i = begin; i < end; ++i) {
    const double m = mass[i];
    // Body force m g added to the force sum (Cundall & Strack, Motion).
    Vec<Dim> body = c.gravity;
    // The particle's own velocity and the continuum field's at its place
    // (Randall eqs. 4.43-4.44): the velocity of the last step carries the
    // field of the last step, where the particle stood then.
    Vec<Dim> field_before = Vec<Dim>::Zero(), field = Vec<Dim>::Zero();
    if constexpr (kField) {
      body += c.centripetal.at(position[i]);
      field_before = c.continuum_before.velocity(Vec<Dim>(position[i] - velocity[i] * dt));
      field = c.continuum.velocity(position[i]);
    }
    const Vec<Dim> resultant = force[i] + m * body;
    const Vec<Dim> velocity_before = velocity[i];
    Vec<Dim> v0 = velocity_before;
    if constexpr (kField) v0 -= field_before;
    const Spin<Dim> w0 = angular_velocity[i];
    Vec<Dim> local_force = Vec<Dim>::Zero();
    Spin<Dim> local_moment = Space<Dim>::zero_spin();
    if constexpr (kLocal) {
      local_force = local_damping(resultant, v0, c.local);
      local_moment = local_damping(moment[i], w0, c.local_rotation);
    }
    const Vec<Dim> v1 = (v0 * c.keep + (resultant + local_force) * (dt / m)) * c.scale;  // eq. 35
    // The particle moves with its own velocity and the field's (eq. 4.41).
    Vec<Dim> moved = v1;
    if constexpr (kField) moved += field;
    Spin<Dim> spin_rate;
    if constexpr (kTensor) {
      spin_rate = angular_acceleration(rotation[i], p.principal_inertia[i], moment[i] + local_moment, w0);
    } else {
      spin_rate = (moment[i] + local_moment) * (1.0 / inertia[i]);
    }
    const Spin<Dim> w1 = (w0 * c.keep_rotation + spin_rate * dt) * c.scale_rotation;  // eq. 36
    velocity[i] = moved;
    angular_velocity[i] = w1;
    max_speed2 = std::max(max_speed2, moved.squaredNorm());
    Vec<Dim> x = position[i] + moved * dt;  // eq. 22a
    if (c.wraps) c.cell.wrap_step(x);
    position[i] = x;
    turn(rotation[i], w1, dt);  // eq. 23a
    max_travel2 = std::max(max_travel2, c.cell.separation(reference[i], x).squaredNorm());

    if constexpr (kEnergy) {
      // Energy over the step, at the mid-step velocity the scheme is centred on.
      // The damping acts on the particle's own velocity v; under a
      // continuum field the particle's velocity is v + f, and what the
      // kinetic energy gains besides the forces' work and the damping's
      // loss, m (v + f)_mid . (f1 - f0) - alpha m v_mid . f_mid dt, is the
      // field's work.
      const Vec<Dim> v_mid = 0.5 * (v0 + v1);
      const Spin<Dim> w_mid = 0.5 * (w0 + w1);
      step.gravity_work += m * body.dot(moved) * dt;
      step.global_damping +=
          (c.alpha * m * v_mid.squaredNorm() + c.alpha_rotation * p.spin_energy_product(i, w_mid)) * dt;
      const Vec<Dim> moved_mid = 0.5 * (velocity_before + moved);
      step.local_damping -= (local_force.dot(moved_mid) + dot(local_moment, w_mid)) * dt;
      if constexpr (kField) {
        step.continuum_work +=
            m * (moved_mid.dot(field - field_before) - c.alpha * v_mid.dot(0.5 * (field + field_before)) * dt);
      }
    }
  }
  step.max_travel = std::sqrt(max_travel2);
  step.max_speed = std::sqrt(max_speed2);
}

template <int Dim, bool kLocal, bool kTensor, bool kEnergy, bool kField>
MotionStep move_particles(Particles<Dim>& p, const MotionInputs<Dim>& in) {
  const MotionConstants<Dim> c = motion_constants(in);
  const auto partials = for_blocks<MotionStep>(
      static_cast<std::int64_t>(p.size()), in.threads, [&](std::int64_t begin, std::int64_t end, MotionStep& step) {
        if constexpr (!kLocal && !kTensor && !kEnergy && !kField) {
          move_plain_block(p, c.gravity, c.cell, c.dt, c.keep, c.scale, c.keep_rotation, c.scale_rotation, begin, end,
                           step, in.hot_place, in.hot_motion);
        } else {
          move_block<Dim, kLocal, kTensor, kEnergy, kField>(p, c, begin, end, step);
        }
        if (in.hot_place != nullptr && (kLocal || kTensor || kEnergy || kField)) {
          copy_hot_particles(p, in.hot_place, in.hot_motion, begin, end);
        }
      });
  MotionStep total;
  for (const MotionStep& part : partials) total += part;
  return total;
}

// Randall 4.35-4.40: the stiffness a particle meets, K = d|sum F| / dx,
// gives its own critical step 2 (m / K)^(1/2); dt over it, squared, is
// dt^2 K / (4 m) = dt^2 change / (4 m dx). The largest fraction over the
// particles is kept as numerator and denominator, compared without dividing.
template <int Dim>
double check_time_step(Particles<Dim>& p, const MotionInputs<Dim>& in) {
  double ratio_above = 0.0, ratio_below = 1.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double force_norm = p.force[i].norm();
    if (in.check_step) {
      const double dx = p.velocity[i].norm() * in.dt;
      const double change = std::abs(force_norm - p.previous_force[i]);
      if (change * ratio_below > ratio_above * p.mass[i] * dx && dx > 0.0) {
        ratio_above = change;
        ratio_below = p.mass[i] * dx;
      }
    }
    p.previous_force[i] = force_norm;
  }
  return ratio_above > 0.0 ? in.dt * std::sqrt(ratio_above / (4.0 * ratio_below)) : 0.0;
}

template <int Dim>
MotionStep integrate_motion(Particles<Dim>& p, const MotionInputs<Dim>& in) {
  const bool local = in.damping.local_alpha > 0.0 || in.damping.local_alpha_rotation.value_or(0.0) > 0.0;
  const bool tensor = Dim == 3 && !p.principal_inertia.empty();
  const bool field = in.centripetal != nullptr || in.continuum_before != nullptr || in.continuum != nullptr;
  MotionStep step;
  auto run = [&]<bool kLocal, bool kTensor, bool kEnergy, bool kField>() {
    step = move_particles < Dim, kLocal, kTensor && Dim == 3, kEnergy, kField > (p, in);
  };
  auto with_field = [&]<bool kLocal, bool kTensor, bool kEnergy>() {
    if (field) {
      run.template operator()<kLocal, kTensor, kEnergy, true>();
    } else {
      run.template operator()<kLocal, kTensor, kEnergy, false>();
    }
  };
  auto with_energy = [&]<bool kLocal, bool kTensor>() {
    if (in.energy_budget) {
      with_field.template operator()<kLocal, kTensor, true>();
    } else {
      with_field.template operator()<kLocal, kTensor, false>();
    }
  };
  auto with_tensor = [&]<bool kLocal>() {
    if (tensor) {
      with_energy.template operator()<kLocal, true>();
    } else {
      with_energy.template operator()<kLocal, false>();
    }
  };
  if (local) {
    with_tensor.template operator()<true>();
  } else {
    with_tensor.template operator()<false>();
  }
  // The check reads the force sums this step moved the particles with.
  if (in.keep_force) step.time_step_ratio = check_time_step(p, in);
  return step;
}

template MotionStep integrate_motion(Particles<2>&, const MotionInputs<2>&);
template MotionStep integrate_motion(Particles<3>&, const MotionInputs<3>&);

}  // namespace dem
