// One row of the force pass: the contact's geometry (contact_geometry.h),
// the relative velocity at the contact point (Cundall & Strack eqs. 11-13),
// the contact law's step and forces (contact_history.h), and the shares of
// force and moment the two bodies receive. One body serves particle-particle
// and particle-wall rows (the second body is a policy), and the same body
// advances a row (the force pass) and reads it (contact reports), so a
// report shows what the pass applied.
#pragma once

#include <type_traits>

#include "contact_forces.h"
#include "contact_geometry.h"
#include "contact_history.h"
#include "contact_params.h"
#include "pass_inputs.h"
#include "tangential.h"

namespace dem {

// What a pass does to a row: advance its history (the force pass), or read
// it as it stands (re-evaluating the sums after an edit; reports).
enum class Pass { kAdvance, kEvaluate };

// One row's contact this cycle: the share of force and moment each body
// receives, and what a report shows.
template <int Dim>
struct RowResult {
  bool touching = false;
  Vec<Dim> force = Vec<Dim>::Zero();  // on the first particle; the second body gets -force
  Spin<Dim> moment_first = Space<Dim>::zero_spin();
  Spin<Dim> moment_second = Space<Dim>::zero_spin();  // pairs only
  ContactGeometry<Dim> geometry;
  ContactForces<Dim> forces;
  bool sliding = false;
  Vec<Dim> wall_velocity = Vec<Dim>::Zero();  // wall rows: the wall's velocity at the contact point
};

template <int Dim>
DEM_INLINE ContactKinematics<Dim> kinematics(double overlap, const Vec<Dim>& relative, const Vec<Dim>& e) {
  return {overlap, relative.dot(e), tangential_velocity(relative, e), e};  // eqs. 12-13
}

// The work of last cycle's contact forces, settled now. A force of cycle N
// acts from N - 1/2 to N + 1/2 while the bodies move at the mean of the
// relative velocity it was computed from and the next one, so
// F_N . (v_(N-1/2) + v_(N+1/2)) / 2 dt is what the kinetic energy paid:
// for the dashpots (eqs. 26-27) it is dissipated; for the tangential spring
// it is stored, or lost to sliding.
template <int Dim>
void settle_contact_work(DashpotWork<Dim>& w, const Vec<Dim>& relative, double dt, ContactEnergy& energy) {
  const Vec<Dim> mean = 0.5 * (w.relative_velocity + relative);
  energy.damping -= w.force.dot(mean) * dt;
  energy.tangential_work += w.tangential.dot(mean) * dt;
  w = DashpotWork<Dim>{};
}

// Records this cycle's dashpot force and tangential spring force (on the
// first body) and the relative velocity they came from.
template <int Dim>
void remember_work(DashpotWork<Dim>& w, const ContactForces<Dim>& f, const Vec<Dim>& e, const Vec<Dim>& relative) {
  w.force = -f.normal_damping * e - shear_vector(f.shear_damping, e);
  w.tangential = shear_vector(f.shear, e);
  w.relative_velocity = relative;
}

// Relative velocity of the first body's contact point with respect to the
// second's (Cundall & Strack eq. 11): round bodies in BALL's form, other
// shapes through their lever arms.
template <typename Shape, int Dim>
Vec<Dim> contact_velocity(const Particles<Dim>& p, Slot x, const Vec<Dim>& second_velocity,
                          const Spin<Dim>& second_spin, double second_radius, const ContactGeometry<Dim>& g) {
  if constexpr (Shape::round) {
    return relative_contact_velocity(p.velocity[x], p.angular_velocity[x], p.radius[x], second_velocity, second_spin,
                                     second_radius, g.normal);
  } else {
    return (p.velocity[x] + cross(p.angular_velocity[x], g.arm_first)) -
           (second_velocity + cross(second_spin, g.arm_second));
  }
}

// The contact's force on the first body and its moments on both: F_s R for
// round bodies (Cundall & Strack, resultant moments), arm x F otherwise.
// F_n and F_s act opposite to e_i and t_i (Fig. 3).
template <typename Shape, int Dim>
void resolve(RowResult<Dim>& out, const ContactForces<Dim>& f, const ContactGeometry<Dim>& g, double r_first,
             double r_second) {
  const ShearForce<Dim> shear = f.shear + f.shear_damping;
  out.force = -(f.normal + f.normal_damping) * g.normal - shear_vector(shear, g.normal);
  if constexpr (Shape::round) {
    out.moment_first = shear_moment(shear, r_first, g.normal);
    out.moment_second = shear_moment(shear, r_second, g.normal);
  } else {
    out.moment_first = cross(g.arm_first, out.force);
    out.moment_second = cross(g.arm_second, Vec<Dim>(-out.force));
  }
}

// The rows a pass reads, and writes when it advances them.
template <Pass kPass, int Dim>
using RowsOf = std::conditional_t<kPass == Pass::kAdvance, ContactRows<Dim>&, const ContactRows<Dim>&>;

// The second body of a row: what a particle-particle row and a
// particle-wall row differ in. Where the bodies touch, the second's
// velocity at the contact point, its part of the effective mass and the
// parameters of the pair, and what it adds to the row's result. Each is a
// policy chosen with the table (pairs or walls), so contact_row below is
// written once and compiled for each without a branch or a call.

// Another particle (Cundall & Strack eqs. 8-19).
template <int Dim>
struct ParticleBody {
  static constexpr bool kWall = false;
  Slot y;

  ParticleBody(const PassInputs<Dim>&, std::int32_t second) : y(second) {}

  // A shaped pair starts its search from where the last one ended
  // (contact_geometry.h), and the force pass keeps where this one ends.
  template <Pass kPass, bool kApartGeometry, typename Shape>
  ContactGeometry<Dim> geometry(const PassInputs<Dim>& in, RowsOf<kPass, Dim> rows, std::size_t r, Slot x) const {
    ContactSearch search;
    if constexpr (!Shape::round) search = rows.search[r];
    const ContactGeometry<Dim> g = Shape::template pair<kApartGeometry>(in, x, y, search);
    if constexpr (kPass == Pass::kAdvance && !Shape::round) rows.search[r] = search;
    return g;
  }
  template <typename Shape>
  Vec<Dim> relative_velocity(const PassInputs<Dim>& in, Slot x, const ContactGeometry<Dim>& g) const {
    const Particles<Dim>& p = in.particles;
    return contact_velocity<Shape>(p, x, p.velocity[y], p.angular_velocity[y], p.radius[y], g);
  }
  double effective_mass(const Particles<Dim>& p, Slot x) const {
    const double mx = p.mass[x], my = p.mass[y];
    return mx * my / (mx + my);  // Randall 4.5-4.6
  }
  const ContactParams& params(const PassInputs<Dim>& in, Slot x) const {
    return in.pair_params(in.particles.material[x], in.particles.material[y]);
  }
  double radius(const Particles<Dim>& p) const { return p.radius[y]; }
  template <Pass kPass, bool kEnergy>
  void finish(RowResult<Dim>&, double, ContactEnergy&) const {}
};

// A wall: infinitely heavy, moving as commanded; it takes no moment.
template <int Dim>
struct WallBody {
  static constexpr bool kWall = true;
  std::int32_t w;
  const WallDefT<Dim>& wall;
  Vec<Dim> velocity = Vec<Dim>::Zero();  // the wall's, at the contact point

  WallBody(const PassInputs<Dim>& in, std::int32_t second) : w(second), wall(in.walls.def[second]) {}

  template <Pass kPass, bool kApartGeometry, typename Shape>
  ContactGeometry<Dim> geometry(const PassInputs<Dim>& in, RowsOf<kPass, Dim>, std::size_t, Slot x) const {
    return Shape::wall(in, wall, x);
  }
  template <typename Shape>
  Vec<Dim> relative_velocity(const PassInputs<Dim>& in, Slot x, const ContactGeometry<Dim>& g) {
    velocity = wall_point_velocity(wall, in.walls.last_velocity[w], in.walls.last_angular_velocity[w], g.point);
    return contact_velocity<Shape>(in.particles, x, velocity, Space<Dim>::zero_spin(), 0.0, g);
  }
  double effective_mass(const Particles<Dim>& p, Slot x) const { return p.mass[x]; }
  const ContactParams& params(const PassInputs<Dim>& in, Slot x) const {
    return in.params(in.particles.material[x], wall.material.value());
  }
  double radius(const Particles<Dim>&) const { return 0.0; }
  template <Pass kPass, bool kEnergy>
  void finish(RowResult<Dim>& out, double dt, ContactEnergy& energy) const {
    out.wall_velocity = velocity;
    out.moment_second = Space<Dim>::zero_spin();
    if constexpr (kPass == Pass::kAdvance && kEnergy) {
      energy.wall_work += out.force.dot(velocity) * dt;  // the wall's motion does work through the contact
    }
  }
};

// One row, pair or wall (Body): the geometry, the relative velocity
// (eqs. 11-13), the history brought over the step when the pass advances
// it (the work of last cycle's forces settled, a separation ended, the
// shear carried into the new tangent plane), the law's forces, the history
// and the work stored, and the two bodies' shares.
template <Pass kPass, bool kEnergy, typename Law, typename Shape, typename Body, int Dim>
RowResult<Dim> contact_row_from(const PassInputs<Dim>& in, RowsOf<kPass, Dim> rows, std::size_t r, Body& second,
                                const ContactGeometry<Dim>& g, ContactEnergy& energy);

template <Pass kPass, bool kEnergy, typename Law, typename Shape, typename Body, int Dim>
RowResult<Dim> contact_row(const PassInputs<Dim>& in, RowsOf<kPass, Dim> rows, std::size_t r, ContactEnergy& energy) {
  Body second(in, rows.second[r]);
  const ContactGeometry<Dim> g = second.template geometry<kPass, kEnergy, Shape>(in, rows, r, rows.first[r]);
  return contact_row_from<kPass, kEnergy, Law, Shape, Body, Dim>(in, rows, r, second, g, energy);
}

// The rest of a row from its geometry, found beforehand (for ellipsoid
// pairs, a run of rows' searches at once: ellipsoid_rows.h).
template <Pass kPass, bool kEnergy, typename Law, typename Shape, typename Body, int Dim>
RowResult<Dim> contact_row_from(const PassInputs<Dim>& in, RowsOf<kPass, Dim> rows, std::size_t r, Body& second,
                                const ContactGeometry<Dim>& g, ContactEnergy& energy) {
  const Particles<Dim>& p = in.particles;
  const Slot x = rows.first[r];
  RowResult<Dim> out;
  ContactHistory<Dim> h = load_history<Law>(rows, r);
  if (g.overlap <= 0.0 && (!h.touching || kPass == Pass::kEvaluate)) return out;  // eq. 8: apart
  if (kPass == Pass::kEvaluate && !h.touching) return out;
  const Vec<Dim> relative = second.template relative_velocity<Shape>(in, x, g);
  if constexpr (kPass == Pass::kAdvance) {
    if constexpr (kEnergy) {
      if (h.touching) settle_contact_work(rows.dashpot[r], relative, in.dt, energy);
    }
    if (g.overlap <= 0.0) {
      separate(rows, r);
      return out;
    }
    if (h.touching) {
      carry_shear(h.shear, g.normal);
    } else {
      rows.formed_cycle[r] = in.cycle;
    }
  }
  const PairProperties pair{g.effective_radius, second.effective_mass(p, x)};
  const ContactKinematics<Dim> k = kinematics(g.overlap, relative, g.normal);
  const ContactParams& params = second.params(in, x);
  if constexpr (kPass == Pass::kAdvance) Law::advance(h, k, pair, params, in.dt);
  const ContactForces<Dim> f = Law::forces(h, k, pair, params);
  if constexpr (kPass == Pass::kAdvance) {
    store_history<Law>(rows, r, h);
    if constexpr (kEnergy) remember_work(rows.dashpot[r], f, g.normal, relative);
  }
  out.touching = true;
  out.geometry = g;
  out.forces = f;
  out.sliding = h.sliding;
  resolve<Shape>(out, f, g, p.radius[x], second.radius(p));
  second.template finish<kPass, kEnergy>(out, in.dt, energy);
  return out;
}

}  // namespace dem
