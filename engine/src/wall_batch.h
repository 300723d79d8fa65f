// The force pass over the wall rows of round particles against segments
// (2D) and rectangles (3D), in batches, as contact_batch.h takes the pair
// rows. A wall row through the general row body (contact_row.h) cost about
// five pair rows (10k plate benchmark: 48 ns against 9.5; docs/PERFORMANCE.md),
// each one chain of roots and divisions, with the closest point out of line
// twice. Here a batch of rows is taken in three sweeps: the geometry's
// distance and whether each row touches, with what the law reads of the
// touching rows packed together; the law on the packed rows, one straight
// loop over arrays that the compiler vectorises; then the history back to
// the rows and the shares into the particles' and walls' sums in row
// order, exactly as the row-by-row pass adds them. The geometry and the law
// are the same functions as there, so the rows come out bit for bit as the
// row-by-row pass and the reports compute them.
#pragma once

#include <algorithm>
#include <cstdint>

#include "batch_columns.h"
#include "contact_blocks.h"
#include "contact_row.h"
#include "parameter_sets.h"
#include "walls.h"

namespace dem {

// What one block's wall rows add to each wall.
template <int Dim>
struct WallSum {
  Vec<Dim> force = Vec<Dim>::Zero();
  Spin<Dim> moment = Space<Dim>::zero_spin();
  double normal_force = 0.0;
  int contacts = 0;
  Eccentricity<Dim> normal_force_arm = zero_eccentricity<Dim>();
};

// One touching row's share of its wall's sum: the force on the wall, its
// moment about P, the compressive normal force and that force times where
// it acts in the wall's coordinates (`coordinates`, of the contact point).
// Both passes add through here, so each sum gets the same terms.
template <int Dim>
DEM_INLINE void add_wall_share(WallSum<Dim>& sum, const WallDefT<Dim>& wall, const Vec<Dim>& point,
                               const Vec<Dim>& on_particle, const Eccentricity<Dim>& coordinates) {
  const Vec<Dim> on_wall = -on_particle;
  // Compressive normal force: the particle pushes the wall away from its particle side.
  const double normal = -on_wall.dot(wall_normal(wall));
  sum.force += on_wall;
  sum.moment += cross(Vec<Dim>(point - wall.point), on_wall);
  sum.normal_force += normal;
  sum.normal_force_arm += normal * coordinates;
  ++sum.contacts;
}

// Whether every wall is a segment or a rectangle: walls of triangle faces
// keep the row-by-row pass.
template <int Dim>
bool planar_walls(const Walls<Dim>& walls) {
  if constexpr (Dim == 3) {
    return std::none_of(walls.def.begin(), walls.def.end(), [](const WallDefT<3>& w) { return !w.triangles.empty(); });
  }
  return true;
}

// Block b's wall rows, for round particles whose law is Law::kBatchable,
// without the energy budget, when the walls are planar (contact_forces.cpp
// chooses); each wall's share into sums[wall]. kSets: how the law loop
// reads each row's parameter set, found by its particle's and its wall's
// materials (parameter_sets.h).
template <typename Law, int Dim, SetChoice kSets>
void batched_wall_block(const PassInputs<Dim>& in, Particles<Dim>& p, ContactRows<Dim>& rows,
                        const ContactBlocks<Dim>& blocks, int b, WallSum<Dim>* sums) {
  constexpr int kBatch = 64;
  const LoopSets<kSets> sets(*in.wall_sets);
  const std::int32_t* set_of = in.wall_sets->set_of.data();
  const std::int32_t materials = in.params.count();
  const std::int32_t* particle_material = p.material.data();
  const double dt = in.dt;
  const std::uint64_t cycle = in.cycle;
  const Walls<Dim>& walls = in.walls;
  // The packed touching rows of one batch, structure of arrays: the row's
  // particle and wall, then what the law loop makes of them.
  alignas(64) double separation[Dim][kBatch], distance[kBatch], overlap[kBatch], radius[kBatch], mass[kBatch];
  alignas(64) double centre[Dim][kBatch], velocity[Dim][kBatch], spin[3][kBatch], shear[3][kBatch];
  alignas(64) double normal_force[kBatch], was_touching[kBatch];
  alignas(64) double wall_point[Dim][kBatch], wall_velocity[Dim][kBatch], wall_spin[3][kBatch], away[Dim][kBatch];
  alignas(64) double point[Dim][kBatch], force[Dim][kBatch], moment[3][kBatch], sliding[kBatch];
  std::int32_t row[kBatch], wall_of[kBatch];
  Slot particle[kBatch];
  // The row's set number (kSets other than kOne), a double like the flags:
  // 32-bit numbers would make the compiler take 16 contacts per vector step.
  alignas(64) double parameter_set[kBatch];

  // Plain pointers: the flag bytes stored below could alias any vector's
  // own pointer (contact_batch.h).
  const Slot* first = rows.first.data();
  const std::int32_t* second = rows.second.data();
  std::uint8_t* row_flags = rows.flags.data();
  ShearForce<Dim>* row_shear = rows.shear.data();
  double* row_normal_force = rows.normal_force.data();
  std::uint64_t* formed_cycle = rows.formed_cycle.data();
  const Vec<Dim>* position = p.position.data();
  const Vec<Dim>* particle_velocity = p.velocity.data();
  const Spin<Dim>* angular_velocity = p.angular_velocity.data();
  const double* particle_radius = p.radius.data();
  const double* particle_mass = p.mass.data();
  Vec<Dim>* particle_force = p.force.data();
  Spin<Dim>* particle_moment = p.moment.data();
  const WallDefT<Dim>* wall_def = walls.def.data();

  const std::int32_t begin = blocks.wall_begin[b], end = blocks.wall_begin[b + 1];
  for (std::int32_t r0 = begin; r0 < end; r0 += kBatch) {
    const std::int32_t r1 = std::min(end, r0 + kBatch);
    // 1. Which rows touch (RoundShape::wall, Cundall & Strack eq. 8): the
    // wall point A_(w) nearest the centre and the overlap; a row that
    // stopped touching loses its history. Each row's values are written at
    // the next packed place, which only a touching row keeps.
    int count = 0;
    for (std::int32_t r = r0; r < r1; ++r) {
      const Slot x = first[r];
      const std::int32_t w = second[r];
      const WallDefT<Dim>& wall = wall_def[w];
      const Vec<Dim>& c = position[x];
      const double rx = particle_radius[x];
      const Vec<Dim> d = closest_planar_point(wall, c).point - c;
      const double dist = d.norm();
      const double gap_overlap = rx - dist;
      const bool touch = gap_overlap > 0.0;
      const bool touched = (row_flags[r] & kTouching) != 0;
      if (touched & !touch) separate(rows, r);
      row[count] = r;
      particle[count] = x;
      wall_of[count] = w;
      const Vec<Dim> reversed_normal = -wall_normal(wall);
      const Vec<Dim>& wv = walls.last_velocity[w];
      for (int k = 0; k < Dim; ++k) {
        separation[k][count] = d[k];
        centre[k][count] = c[k];
        velocity[k][count] = particle_velocity[x][k];
        wall_point[k][count] = wall.point[k];
        wall_velocity[k][count] = wv[k];
        away[k][count] = reversed_normal[k];
      }
      if constexpr (Dim == 3) {
        for (int k = 0; k < 3; ++k) {
          spin[k][count] = angular_velocity[x][k];
          wall_spin[k][count] = walls.last_angular_velocity[w][k];
          shear[k][count] = row_shear[r][k];
        }
      } else {
        spin[0][count] = angular_velocity[x];
        wall_spin[0][count] = walls.last_angular_velocity[w];
        shear[0][count] = row_shear[r];
      }
      distance[count] = dist;
      overlap[count] = gap_overlap;
      radius[count] = rx;
      mass[count] = particle_mass[x];
      if constexpr (Law::kNormalHistory) normal_force[count] = row_normal_force[r];
      was_touching[count] = touched ? 1.0 : 0.0;
      if constexpr (kSets != SetChoice::kOne) {
        parameter_set[count] = set_of[particle_material[x] * materials + wall.material.value()];
      }
      count += touch;
    }
    // 2. The contact law on the packed rows: the rest of RoundShape::wall's
    // geometry, the relative velocity (eqs. 11-13), the law (eqs. 9-19),
    // the force on the particle and its moment, as contact_row computes them.
    for (int j = 0; j < count; ++j) {
      Vec<Dim> d, c, v, reversed_normal, wall_origin, wv;
      for (int k = 0; k < Dim; ++k) {
        d[k] = separation[k][j];
        c[k] = centre[k][j];
        v[k] = velocity[k][j];
        reversed_normal[k] = away[k][j];
        wall_origin[k] = wall_point[k][j];
        wv[k] = wall_velocity[k][j];
      }
      const Spin<Dim> w = column_entry<Dim>(spin, j), ww = column_entry<Dim>(wall_spin, j);
      ContactHistory<Dim> h;
      h.shear = column_entry<Dim>(shear, j);
      h.touching = was_touching[j] != 0.0;
      if constexpr (Law::kNormalHistory) h.normal_force = normal_force[j];
      const double rx = radius[j], dist = distance[j], ov = overlap[j];
      // e from the particle to the wall; a centre exactly on the wall takes
      // the wall's normal reversed (RoundShape::wall).
      Vec<Dim> e;
      for (int k = 0; k < Dim; ++k) e[k] = dist > 0.0 ? d[k] / dist : reversed_normal[k];
      const Vec<Dim> at = c + (rx - 0.5 * ov) * e;  // halfway between A_(D) and A_(w)
      // The wall's velocity at the contact point (wall_point_velocity).
      const Vec<Dim> wall_at = wv + cross(ww, Vec<Dim>(at - wall_origin));
      const Vec<Dim> relative = relative_contact_velocity(v, w, rx, wall_at, Space<Dim>::zero_spin(), 0.0, e);
      carry_shear(h.shear, e);                 // a row that did not touch has no shear to carry
      const PairProperties pair{rx, mass[j]};  // a wall is infinitely large and heavy
      const ContactKinematics<Dim> kin = kinematics(ov, relative, e);
      const auto& params = sets[kSets == SetChoice::kOne ? 0.0 : parameter_set[j]];
      Law::advance(h, kin, pair, params, dt);
      const ContactForces<Dim> f = Law::forces(h, kin, pair, params);
      const ShearForce<Dim> total = f.shear + f.shear_damping;
      const Vec<Dim> on_particle = -(f.normal + f.normal_damping) * e - shear_vector(total, e);
      const Spin<Dim> turn = shear_moment(total, rx, e);
      for (int k = 0; k < Dim; ++k) {
        force[k][j] = on_particle[k];
        point[k][j] = at[k];
      }
      set_column_entry<Dim>(moment, j, turn);
      set_column_entry<Dim>(shear, j, h.shear);
      sliding[j] = h.sliding ? 1.0 : 0.0;
      if constexpr (Law::kNormalHistory) normal_force[j] = h.normal_force;
    }
    // 3. History back to the rows, shares into the sums in row order.
    for (int j = 0; j < count; ++j) {
      const std::int32_t r = row[j];
      const Slot x = particle[j];
      const std::int32_t w = wall_of[j];
      row_shear[r] = column_entry<Dim>(shear, j);
      if constexpr (Law::kNormalHistory) row_normal_force[r] = normal_force[j];
      if (was_touching[j] == 0.0) formed_cycle[r] = cycle;
      row_flags[r] = sliding[j] != 0.0 ? kTouching | kSliding : kTouching;
      Vec<Dim> on_particle, at;
      for (int k = 0; k < Dim; ++k) {
        on_particle[k] = force[k][j];
        at[k] = point[k][j];
      }
      const Spin<Dim> turn = column_entry<Dim>(moment, j);
      particle_force[x] += on_particle;
      particle_moment[x] += turn;
      const WallDefT<Dim>& wall = wall_def[w];
      add_wall_share(sums[w], wall, at, on_particle, closest_planar_point(wall, at).coordinates);
    }
  }
}

}  // namespace dem
