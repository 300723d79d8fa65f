#include "contact_forces.h"

#include "linear_law.h"
#include "parallel.h"

namespace dem {

namespace {

// Force on the first body from the spring and dashpot forces: F_n and F_s
// act opposite to e_i and t_i (Cundall & Strack, Fig. 3).
Vec2 resolve_force(const ContactState& s, const Vec2& e, const Vec2& t) {
  return -(s.normal_force + s.normal_damping) * e - (s.shear_force + s.shear_damping) * t;
}

}  // namespace

void compute_pair_forces(const Particles& particles, std::vector<PairContact>& pairs,
                         std::vector<ContactForce>& forces, const ContactParamTable& params, double dt,
                         int threads) {
  const auto n = static_cast<std::int64_t>(pairs.size());
  DEM_PARALLEL_FOR(threads, n)
  for (std::int64_t c = 0; c < n; ++c) {
    PairContact& contact = pairs[c];
    ContactState& s = contact.state;
    const ParticleId x = contact.first, y = contact.second;
    const Vec2 d = particles.position[y] - particles.position[x];
    const double distance = d.norm();
    const double rx = particles.radius[x], ry = particles.radius[y];
    const double overlap = rx + ry - distance;
    if (overlap <= 0.0 || distance == 0.0) {  // eq. 8
      separate(s);
      forces[c] = ContactForce{};
      continue;
    }
    const Vec2 e = d / distance;                  // eq. 9
    const Vec2 t = clockwise_perpendicular(e);    // eq. 10
    // Relative velocity of P_(x) with respect to P_(y) (eq. 11).
    const Vec2 relative = (particles.velocity[x] - particles.velocity[y]) -
                          (particles.angular_velocity[x] * rx + particles.angular_velocity[y] * ry) * t;
    apply_linear_law(s, {overlap, relative.dot(e), relative.dot(t)},  // eqs. 12-13
                     params(particles.material[x], particles.material[y]), dt);
    s.normal = e;
    s.point = particles.position[x] + (rx - 0.5 * overlap) * e;
    // Sum M = F_s R for each disc (Cundall & Strack, resultant moments).
    const double shear = s.shear_force + s.shear_damping;
    forces[c] = ContactForce{resolve_force(s, e, t), shear * rx, shear * ry};
  }
}

void compute_wall_forces(const Particles& particles, const Walls& walls, std::vector<WallContact>& contacts,
                         std::vector<ContactForce>& forces, const ContactParamTable& params, double dt,
                         int threads) {
  const auto n = static_cast<std::int64_t>(contacts.size());
  DEM_PARALLEL_FOR(threads, n)
  for (std::int64_t c = 0; c < n; ++c) {
    WallContact& contact = contacts[c];
    ContactState& s = contact.state;
    const ParticleId x = contact.particle;
    const WallDef& wall = walls.def[contact.wall];
    const Vec2& centre = particles.position[x];
    const double r = particles.radius[x];
    // The wall point A_(w) on the perpendicular through the disc centre (Fig. 1).
    const Vec2 q = closest_point(wall, centre).point;
    const Vec2 d = q - centre;
    const double distance = d.norm();
    const double overlap = r - distance;
    if (overlap <= 0.0) {
      separate(s);
      forces[c] = ContactForce{};
      continue;
    }
    // e points from the disc to the wall; a centre exactly on the wall line
    // takes the wall's normal towards the particle side, reversed.
    const Vec2 e = distance > 0.0 ? Vec2(d / distance) : Vec2(-wall_normal(wall));
    const Vec2 t = clockwise_perpendicular(e);
    const Vec2 wall_velocity =
        wall_point_velocity(wall, walls.last_velocity[contact.wall], walls.last_angular_velocity[contact.wall], q);
    const Vec2 relative = (particles.velocity[x] - wall_velocity) - particles.angular_velocity[x] * r * t;
    apply_linear_law(s, {overlap, relative.dot(e), relative.dot(t)},
                     params(particles.material[x], wall.material), dt);
    s.normal = e;
    s.point = centre + (r - 0.5 * overlap) * e;  // halfway between A_(D) and A_(w)
    forces[c] = ContactForce{resolve_force(s, e, t), (s.shear_force + s.shear_damping) * r, 0.0};
  }
}

}  // namespace dem
