#include "rolling_resistance.h"

#include <cmath>
#include <vector>

#include "contact_forces.h"
#include "dem/law_traits.h"
#include "tangential.h"
#include "world_state.h"

namespace dem {

namespace {

// A touching row as the pass needs it.
struct RollingRow {
  bool wall;
  std::size_t row;
  std::int32_t first, second;  // ids' values: second a particle's, or the wall's
  Vec3 normal;                 // e_i (z = 0 in 2D)
  double overlap, normal_force;
};

template <int Dim>
std::vector<RollingRow> touching_rows(const WorldState<Dim>& s) {
  std::vector<RollingRow> rows;
  visit_touching_rows<Dim>(s, [&](const RowReport<Dim>& r) {
    Vec3 normal = Vec3::Zero();
    normal.head<Dim>() = r.record.normal;
    rows.push_back({r.wall, r.row, r.record.first.value(),
                    r.wall ? r.record.second_wall.value() : r.record.second_particle.value(), normal, r.record.overlap,
                    r.record.normal_force});
  });
  return rows;
}

// The tangent-plane part of a relative rotation (3D): twisting about the
// normal meets no resistance. In 2D every rotation is about the normal to
// the plane, which rolls the discs.
double rolling_part(double w, const Vec3&) { return w; }
Vec3 rolling_part(const Vec3& w, const Vec3& e) { return w - w.dot(e) * e; }

template <int Dim>
Spin<Dim> scaled_to(const Spin<Dim>& m, double limit) {
  const double size = magnitude(m);
  return size > limit && size > 0.0 ? Spin<Dim>(m * (limit / size)) : m;
}

double dot_spin(double a, double b) { return a * b; }
double dot_spin(const Vec3& a, const Vec3& b) { return a.dot(b); }

}  // namespace

template <int Dim>
bool needs_rolling_resistance(const WorldState<Dim>& s) {
  for (const ContactModelDef& model : s.contact_models) {
    if (model.rolling.friction > 0.0) return true;
  }
  return false;
}

template <int Dim>
void apply_rolling_resistance(WorldState<Dim>& s) {
  Particles<Dim>& p = s.particles;
  const double dt = s.time_step;
  const bool pair_hertz = is_hertz(s.pair_law), wall_hertz = is_hertz(s.wall_law);
  for (const RollingRow& c : touching_rows(s)) {
    ContactRows<Dim>& rows = c.wall ? s.contacts.walls : s.contacts.pairs;
    Spin<Dim>& torque = rows.rolling[c.row];
    const Slot x = p.slot[static_cast<std::size_t>(c.first)];
    const Slot y = c.wall ? -1 : p.slot[static_cast<std::size_t>(c.second)];
    const std::int32_t other = c.wall ? s.walls.def[c.second].material.value() : p.material[y];
    const ContactParams& params = s.params(p.material[x], other);
    if (params.rolling_friction <= 0.0) {
      torque = Space<Dim>::zero_spin();
      continue;
    }
    // Rolling radius, the normal stiffness the spring scales with, and the
    // rotational inertia of the pair about the contact.
    const double rx = p.radius[x], ry = c.wall ? 0.0 : p.radius[y];
    const double rolling_radius = c.wall ? rx : rx * ry / (rx + ry);
    const bool hertz = c.wall ? wall_hertz : pair_hertz;
    const double normal_stiffness =
        hertz ? 2.0 * params.contact_modulus * std::sqrt(rolling_radius * c.overlap) : params.normal_stiffness;
    const double stiffness =
        2.25 * normal_stiffness * params.rolling_friction * params.rolling_friction * rolling_radius * rolling_radius;
    const double inverse_inertia =
        1.0 / (p.inertia[x] + p.mass[x] * rx * rx) + (c.wall ? 0.0 : 1.0 / (p.inertia[y] + p.mass[y] * ry * ry));
    const Spin<Dim> other_spin = c.wall ? s.walls.last_angular_velocity[c.second] : p.angular_velocity[y];
    Spin<Dim> spin;
    if constexpr (Dim == 2) {
      spin = rolling_part(p.angular_velocity[x] - other_spin, c.normal);
    } else {
      spin = rolling_part(Vec3(p.angular_velocity[x] - other_spin), c.normal);
      // The torque kept in the tangent plane as the contact turns, its
      // magnitude kept (as the tangential spring's, carry_shear).
      carry_shear(torque, c.normal);
    }
    const Spin<Dim> turn = spin * dt;
    // The spring's torque of the last pass acted while the bodies turned by
    // `turn`: the work done on it (with the tangential springs', so the
    // budget's friction holds what it does not give back).
    if (s.energy_budget) s.tangential_work -= dot_spin(torque, turn);
    const double limit = params.rolling_friction * rolling_radius * std::max(0.0, c.normal_force);
    const Spin<Dim> elastic = torque - stiffness * turn;
    const bool rolling = magnitude(elastic) >= limit;
    torque = scaled_to<Dim>(elastic, limit);
    Spin<Dim> damping = Space<Dim>::zero_spin();
    if (!rolling && params.rolling_damping_ratio > 0.0 && inverse_inertia > 0.0) {
      damping = -params.rolling_damping_ratio * 2.0 * std::sqrt(stiffness / inverse_inertia) * spin;
      // The resistance as a whole never exceeds the cap: a ball set rolling
      // fast would otherwise meet a dashpot torque far above mu_r R_r F_n
      // in the steps before its spring reaches the cap.
      damping = scaled_to<Dim>(Spin<Dim>(torque + damping), limit) - torque;
      if (s.energy_budget) s.energy.contact_damping -= dot_spin(damping, turn);
    }
    p.moment[x] += torque + damping;
    if (!c.wall) p.moment[y] -= torque + damping;
  }
}

template <int Dim>
void add_rolling_moments(WorldState<Dim>& s) {
  Particles<Dim>& p = s.particles;
  for (const RollingRow& c : touching_rows(s)) {
    const ContactRows<Dim>& rows = c.wall ? s.contacts.walls : s.contacts.pairs;
    const Spin<Dim>& torque = rows.rolling[c.row];
    const Slot x = p.slot[static_cast<std::size_t>(c.first)];
    p.moment[x] += torque;
    if (!c.wall) p.moment[p.slot[static_cast<std::size_t>(c.second)]] -= torque;
  }
}

template bool needs_rolling_resistance(const WorldState<2>&);
template bool needs_rolling_resistance(const WorldState<3>&);
template void apply_rolling_resistance(WorldState<2>&);
template void apply_rolling_resistance(WorldState<3>&);
template void add_rolling_moments(WorldState<2>&);
template void add_rolling_moments(WorldState<3>&);

}  // namespace dem
