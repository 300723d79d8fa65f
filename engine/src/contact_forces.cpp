#include "contact_forces.h"

#include "contact_geometry.h"
#include "law_dispatch.h"
#include "parallel.h"

namespace dem {

namespace {

// Force on the first body from the spring and dashpot forces: F_n and F_s
// act opposite to e_i and t_i (Cundall & Strack, Fig. 3).
template <int Dim>
Vec<Dim> resolve_force(const ContactState<Dim>& s, const Vec<Dim>& e) {
  return -(s.normal_force + s.normal_damping) * e - shear_vector(ShearForce<Dim>(s.shear + s.shear_damping), e);
}

template <int Dim>
ContactKinematics<Dim> kinematics(double overlap, const Vec<Dim>& relative, const Vec<Dim>& e) {
  return {overlap, relative.dot(e), tangential_velocity(relative, e), e};  // eqs. 12-13
}

// The work of last cycle's contact forces, settled now. A force of cycle N
// acts from N - 1/2 to N + 1/2 while the bodies move at the mean of the
// relative velocity it was computed from and the next one, so
// F_N . (v_(N-1/2) + v_(N+1/2)) / 2 dt is what the kinetic energy paid:
// for the dashpots (eqs. 26-27) it is dissipated; for the tangential spring
// it is stored, or lost to sliding.
template <int Dim>
void settle_contact_work(ContactState<Dim>& s, const Vec<Dim>& relative, double dt, ContactEnergy& energy) {
  const Vec<Dim> mean = 0.5 * (s.relative_velocity + relative);
  energy.damping -= s.dashpot_force.dot(mean) * dt;
  energy.tangential_work += shear_vector(s.shear, s.normal).dot(mean) * dt;
  s.dashpot_force.setZero();
}

// Records this cycle's dashpot force (on the first body) and the relative velocity it came from.
template <int Dim>
void remember_dashpot(ContactState<Dim>& s, const Vec<Dim>& e, const Vec<Dim>& relative) {
  s.dashpot_force = -s.normal_damping * e - shear_vector(s.shear_damping, e);
  s.relative_velocity = relative;
}

ContactEnergy total(const std::vector<ContactEnergy>& partials) {
  ContactEnergy sum;
  for (const ContactEnergy& p : partials) sum += p;
  return sum;
}

// Relative velocity of the first body's contact point with respect to the
// second's (Cundall & Strack eq. 11): round bodies in BALL's form, other
// shapes through their lever arms.
template <typename Shape, int Dim>
Vec<Dim> contact_velocity(const Particles<Dim>& p, ParticleId x, const Vec<Dim>& second_velocity,
                          const Spin<Dim>& second_spin, double second_radius, const ContactGeometry<Dim>& g) {
  if constexpr (Shape::round) {
    return relative_contact_velocity(p.velocity[x], p.angular_velocity[x], p.radius[x], second_velocity,
                                     second_spin, second_radius, g.normal);
  } else {
    return (p.velocity[x] + cross(p.angular_velocity[x], g.arm_first)) -
           (second_velocity + cross(second_spin, g.arm_second));
  }
}

// The contact's force on the first body and its moments on both: F_s R for
// round bodies (Cundall & Strack, resultant moments), arm x F otherwise.
template <typename Shape, int Dim>
ContactForce<Dim> contact_force(const ContactState<Dim>& s, const ContactGeometry<Dim>& g, double r_first,
                                double r_second) {
  const Vec<Dim> force = resolve_force(s, g.normal);
  if constexpr (Shape::round) {
    const ShearForce<Dim> shear = s.shear + s.shear_damping;
    return {force, shear_moment(shear, r_first, g.normal), shear_moment(shear, r_second, g.normal)};
  } else {
    return {force, cross(g.arm_first, force), cross(g.arm_second, Vec<Dim>(-force))};
  }
}

template <int Dim, typename Law, typename Shape>
ContactEnergy pair_pass(std::uint64_t cycle, const Particles<Dim>& particles, const Periodic<Dim>& periodic,
                        std::vector<PairContact<Dim>>& pairs, std::vector<ContactForce<Dim>>& forces,
                        const ContactParamTable& params, double dt, int threads) {
  const auto n = static_cast<std::int64_t>(pairs.size());
  return total(for_blocks<ContactEnergy>(n, threads, [&](std::int64_t begin, std::int64_t end, ContactEnergy& energy) {
    for (std::int64_t c = begin; c < end; ++c) {
      PairContact<Dim>& contact = pairs[c];
      ContactState<Dim>& s = contact.state;
      const ParticleId x = contact.first, y = contact.second;
      const ContactGeometry<Dim> g = Shape::pair(particles, periodic, x, y, s);
      const Vec<Dim> relative = contact_velocity<Shape>(particles, x, particles.velocity[y],
                                                        particles.angular_velocity[y], particles.radius[y], g);
      if (s.touching) settle_contact_work(s, relative, dt, energy);
      if (g.overlap <= 0.0) {  // eq. 8
        separate(s);
        forces[c] = ContactForce<Dim>{};
        continue;
      }
      if (s.touching) carry_shear(s.shear, g.normal);
      if (!s.touching) s.formed_cycle = cycle;
      const double mx = particles.mass[x], my = particles.mass[y];
      const PairProperties pair{g.effective_radius, mx * my / (mx + my)};  // Randall 4.5-4.6
      const ContactKinematics<Dim> k = kinematics(g.overlap, relative, g.normal);
      Law::apply(s, k, pair, params(particles.material[x], particles.material[y]), dt);
      remember_dashpot(s, g.normal, relative);
      s.normal = g.normal;
      s.point = g.point;
      forces[c] = contact_force<Shape>(s, g, particles.radius[x], particles.radius[y]);
    }
  }));
}

template <int Dim, typename Law, typename Shape>
ContactEnergy wall_pass(std::uint64_t cycle, const Particles<Dim>& particles, const Walls<Dim>& walls,
                        std::vector<WallContact<Dim>>& contacts, std::vector<ContactForce<Dim>>& forces,
                        const ContactParamTable& params, double dt, int threads) {
  const auto n = static_cast<std::int64_t>(contacts.size());
  return total(for_blocks<ContactEnergy>(n, threads, [&](std::int64_t begin, std::int64_t end, ContactEnergy& energy) {
    for (std::int64_t c = begin; c < end; ++c) {
      WallContact<Dim>& contact = contacts[c];
      ContactState<Dim>& s = contact.state;
      const ParticleId x = contact.particle;
      const WallDefT<Dim>& wall = walls.def[contact.wall];
      const ContactGeometry<Dim> g = Shape::wall(particles, wall, x);
      // The wall's velocity at the contact point.
      const Vec<Dim> wall_velocity = wall_point_velocity(wall, walls.last_velocity[contact.wall],
                                                         walls.last_angular_velocity[contact.wall], g.point);
      const Vec<Dim> relative =
          contact_velocity<Shape>(particles, x, wall_velocity, Space<Dim>::zero_spin(), 0.0, g);
      if (s.touching) settle_contact_work(s, relative, dt, energy);
      if (g.overlap <= 0.0) {
        separate(s);
        forces[c] = ContactForce<Dim>{};
        continue;
      }
      if (s.touching) carry_shear(s.shear, g.normal);
      if (!s.touching) s.formed_cycle = cycle;
      const PairProperties pair{g.effective_radius, particles.mass[x]};
      const ContactKinematics<Dim> k = kinematics(g.overlap, relative, g.normal);
      Law::apply(s, k, pair, params(particles.material[x], wall.material), dt);
      remember_dashpot(s, g.normal, relative);
      s.normal = g.normal;
      s.point = g.point;
      forces[c] = contact_force<Shape>(s, g, particles.radius[x], 0.0);
      forces[c].moment_second = Space<Dim>::zero_spin();
      // The wall's motion does work on the particle through this contact.
      energy.wall_work += forces[c].force.dot(wall_velocity) * dt;
    }
  }));
}

// Calls pass.template operator()<Shape>() with the particles' shape policy.
template <int Dim, typename Pass>
void with_shape(ShapeKind shape, Pass&& pass) {
  if constexpr (Dim == 2) {
    if (shape == ShapeKind::kSuperquadric) {
      pass.template operator()<SuperquadricShape>();
      return;
    }
  } else {
    if (shape == ShapeKind::kEllipsoid) {
      pass.template operator()<EllipsoidShape>();
      return;
    }
  }
  pass.template operator()<RoundShape>();
}

}  // namespace

template <int Dim>
ContactEnergy compute_pair_forces(ContactLaw law, ShapeKind shape, std::uint64_t cycle,
                                  const Particles<Dim>& particles, const Periodic<Dim>& periodic, std::vector<PairContact<Dim>>& pairs,
                                  std::vector<ContactForce<Dim>>& forces, const ContactParamTable& params, double dt,
                                  int threads) {
  ContactEnergy energy;
  with_law(law, [&]<typename Law>() {
    with_shape<Dim>(shape, [&]<typename Shape>() {
      energy = pair_pass<Dim, Law, Shape>(cycle, particles, periodic, pairs, forces, params, dt, threads);
    });
  });
  return energy;
}

template <int Dim>
ContactEnergy compute_wall_forces(ContactLaw law, ShapeKind shape, std::uint64_t cycle,
                                  const Particles<Dim>& particles, const Walls<Dim>& walls, std::vector<WallContact<Dim>>& contacts,
                                  std::vector<ContactForce<Dim>>& forces, const ContactParamTable& params, double dt,
                                  int threads) {
  ContactEnergy energy;
  with_law(law, [&]<typename Law>() {
    with_shape<Dim>(shape, [&]<typename Shape>() {
      energy = wall_pass<Dim, Law, Shape>(cycle, particles, walls, contacts, forces, params, dt, threads);
    });
  });
  return energy;
}

template ContactEnergy compute_pair_forces(ContactLaw, ShapeKind, std::uint64_t, const Particles<2>&, const Periodic<2>&,
                                           std::vector<PairContact<2>>&,
                                  std::vector<ContactForce<2>>&, const ContactParamTable&, double, int);
template ContactEnergy compute_pair_forces(ContactLaw, ShapeKind, std::uint64_t, const Particles<3>&, const Periodic<3>&,
                                           std::vector<PairContact<3>>&,
                                  std::vector<ContactForce<3>>&, const ContactParamTable&, double, int);
template ContactEnergy compute_wall_forces(ContactLaw, ShapeKind, std::uint64_t, const Particles<2>&, const Walls<2>&, std::vector<WallContact<2>>&,
                                  std::vector<ContactForce<2>>&, const ContactParamTable&, double, int);
template ContactEnergy compute_wall_forces(ContactLaw, ShapeKind, std::uint64_t, const Particles<3>&, const Walls<3>&, std::vector<WallContact<3>>&,
                                  std::vector<ContactForce<3>>&, const ContactParamTable&, double, int);

}  // namespace dem
