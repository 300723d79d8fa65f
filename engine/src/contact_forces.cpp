#include "contact_forces.h"

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

template <int Dim, typename Law>
ContactEnergy pair_pass(const Particles<Dim>& particles, const Periodic<Dim>& periodic,
                        std::vector<PairContact<Dim>>& pairs,
                        std::vector<ContactForce<Dim>>& forces, const ContactParamTable& params, double dt,
                        int threads) {
  const auto n = static_cast<std::int64_t>(pairs.size());
  return total(for_blocks<ContactEnergy>(n, threads, [&](std::int64_t begin, std::int64_t end, ContactEnergy& energy) {
  for (std::int64_t c = begin; c < end; ++c) {
    PairContact<Dim>& contact = pairs[c];
    ContactState<Dim>& s = contact.state;
    const ParticleId x = contact.first, y = contact.second;
    const Vec<Dim> d = periodic.separation(particles.position[x], particles.position[y]);
    const double distance = d.norm();
    const double rx = particles.radius[x], ry = particles.radius[y];
    const double overlap = rx + ry - distance;
    const Vec<Dim> e = distance > 0.0 ? Vec<Dim>(d / distance) : Vec<Dim>::UnitX();  // eq. 9
    const Vec<Dim> relative =
        relative_contact_velocity(particles.velocity[x], particles.angular_velocity[x], rx, particles.velocity[y],
                                  particles.angular_velocity[y], ry, e);  // eq. 11
    if (s.touching) settle_contact_work(s, relative, dt, energy);
    if (overlap <= 0.0 || distance == 0.0) {  // eq. 8
      separate(s);
      forces[c] = ContactForce<Dim>{};
      continue;
    }
    if (s.touching) carry_shear(s.shear, e);
    const double mx = particles.mass[x], my = particles.mass[y];
    const PairProperties pair{rx * ry / (rx + ry), mx * my / (mx + my)};  // Randall 4.5-4.6
    const ContactKinematics<Dim> k = kinematics(overlap, relative, e);
    Law::apply(s, k, pair, params(particles.material[x], particles.material[y]), dt);
    remember_dashpot(s, e, relative);
    s.normal = e;
    s.point = particles.position[x] + (rx - 0.5 * overlap) * e;
    // Sum M = F_s R for each body (Cundall & Strack, resultant moments).
    const ShearForce<Dim> shear = s.shear + s.shear_damping;
    forces[c] = ContactForce<Dim>{resolve_force(s, e), shear_moment(shear, rx, e), shear_moment(shear, ry, e)};
  }
  }));
}

template <int Dim, typename Law>
ContactEnergy wall_pass(const Particles<Dim>& particles, const Walls<Dim>& walls,
                        std::vector<WallContact<Dim>>& contacts, std::vector<ContactForce<Dim>>& forces,
                        const ContactParamTable& params, double dt, int threads) {
  const auto n = static_cast<std::int64_t>(contacts.size());
  return total(for_blocks<ContactEnergy>(n, threads, [&](std::int64_t begin, std::int64_t end, ContactEnergy& energy) {
  for (std::int64_t c = begin; c < end; ++c) {
    WallContact<Dim>& contact = contacts[c];
    ContactState<Dim>& s = contact.state;
    const ParticleId x = contact.particle;
    const WallDefT<Dim>& wall = walls.def[contact.wall];
    const Vec<Dim>& centre = particles.position[x];
    const double r = particles.radius[x];
    // The wall point A_(w) on the perpendicular through the particle centre (Fig. 1).
    const Vec<Dim> q = closest_point(wall, centre).point;
    const Vec<Dim> d = q - centre;
    const double distance = d.norm();
    const double overlap = r - distance;
    // e points from the particle to the wall; a centre exactly on the wall
    // takes the wall's normal towards the particle side, reversed.
    const Vec<Dim> e = distance > 0.0 ? Vec<Dim>(d / distance) : Vec<Dim>(-wall_normal(wall));
    const Vec<Dim> wall_velocity = wall_point_velocity(wall, walls.last_velocity[contact.wall],
                                                       walls.last_angular_velocity[contact.wall], q);
    const Vec<Dim> relative =
        relative_contact_velocity(particles.velocity[x], particles.angular_velocity[x], r, wall_velocity,
                                  Space<Dim>::zero_spin(), 0.0, e);
    if (s.touching) settle_contact_work(s, relative, dt, energy);
    if (overlap <= 0.0) {
      separate(s);
      forces[c] = ContactForce<Dim>{};
      continue;
    }
    if (s.touching) carry_shear(s.shear, e);
    const PairProperties pair{r, particles.mass[x]};
    const ContactKinematics<Dim> k = kinematics(overlap, relative, e);
    Law::apply(s, k, pair, params(particles.material[x], wall.material), dt);
    remember_dashpot(s, e, relative);
    s.normal = e;
    s.point = centre + (r - 0.5 * overlap) * e;  // halfway between A_(D) and A_(w)
    forces[c] = ContactForce<Dim>{resolve_force(s, e), shear_moment(ShearForce<Dim>(s.shear + s.shear_damping), r, e),
                                  Space<Dim>::zero_spin()};
    // The wall's motion does work on the particle through this contact.
    energy.wall_work += forces[c].force.dot(wall_velocity) * dt;
  }
  }));
}

}  // namespace

template <int Dim>
ContactEnergy compute_pair_forces(ContactLaw law, const Particles<Dim>& particles, const Periodic<Dim>& periodic,
                                  std::vector<PairContact<Dim>>& pairs, std::vector<ContactForce<Dim>>& forces,
                                  const ContactParamTable& params, double dt, int threads) {
  ContactEnergy energy;
  with_law(law, [&]<typename Law>() {
    energy = pair_pass<Dim, Law>(particles, periodic, pairs, forces, params, dt, threads);
  });
  return energy;
}

template <int Dim>
ContactEnergy compute_wall_forces(ContactLaw law, const Particles<Dim>& particles, const Walls<Dim>& walls,
                                  std::vector<WallContact<Dim>>& contacts, std::vector<ContactForce<Dim>>& forces,
                                  const ContactParamTable& params, double dt, int threads) {
  ContactEnergy energy;
  with_law(law, [&]<typename Law>() {
    energy = wall_pass<Dim, Law>(particles, walls, contacts, forces, params, dt, threads);
  });
  return energy;
}

template ContactEnergy compute_pair_forces(ContactLaw, const Particles<2>&, const Periodic<2>&,
                                           std::vector<PairContact<2>>&,
                                  std::vector<ContactForce<2>>&, const ContactParamTable&, double, int);
template ContactEnergy compute_pair_forces(ContactLaw, const Particles<3>&, const Periodic<3>&,
                                           std::vector<PairContact<3>>&,
                                  std::vector<ContactForce<3>>&, const ContactParamTable&, double, int);
template ContactEnergy compute_wall_forces(ContactLaw, const Particles<2>&, const Walls<2>&, std::vector<WallContact<2>>&,
                                  std::vector<ContactForce<2>>&, const ContactParamTable&, double, int);
template ContactEnergy compute_wall_forces(ContactLaw, const Particles<3>&, const Walls<3>&, std::vector<WallContact<3>>&,
                                  std::vector<ContactForce<3>>&, const ContactParamTable&, double, int);

}  // namespace dem
