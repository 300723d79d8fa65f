// The force pass over the pair rows of round particles, in batches. In a
// dense assembly about half the rows of the neighbour list touch, in no
// order a branch predictor could learn, and each touching row is a long
// chain of dependent roots and divisions. So a batch of rows is taken in
// three sweeps: which rows touch (squared distances, no branches; the
// touching ones are packed together), the contact law on the packed rows
// (one straight loop over arrays, which the compiler turns into vector
// instructions, so several contacts share each chain), then the shares
// added into the sums in row order. The law and the geometry are the same
// functions as there, and the shares are added one by one as there, so
// the pass comes out bit for bit as the row-by-row pass (contact_forces.cpp)
// and the reports compute each row: a world gives the same bits whichever
// pass its material mix, its law or its energy budget choose. (Summing a
// particle's run of rows apart and adding it once, as this pass did until
// its parameters could differ by row, ran no faster: 0.99-1.00 side by
// side, docs/PERFORMANCE.md.)
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "batch_columns.h"
#include "contact_blocks.h"
#include "contact_row.h"
#include "fetch_ahead.h"
#include "parameter_sets.h"

#if defined(__AVX512F__) && defined(__AVX512VL__)
#include <immintrin.h>
#endif

namespace dem {

// The batched pass serves round particles whose law is branch-free enough
// (Law::kBatchable), of any materials, without the energy budget's
// bookkeeping (contact_forces.cpp chooses).
template <typename Shape>
constexpr bool kBatchableShape = Shape::round;

// kSets: how the law loop reads each row's parameter set, found by the
// row's two materials (parameter_sets.h); the law's arithmetic is the same
// whichever way, so equal sets give equal bits. kPrefetch: a large bed's (kPrefetchParticles, contact_blocks.h): a
// row's second particle, which lies anywhere ahead of the first in memory, is fetched some rows early so that its
// misses overlap. kHot: the particles are read from the pass's side-by-side copies (HotPlace, HotMotion in
// contact_blocks.h), filled beforehand by the law of motion or by
// copy_hot_particles; otherwise from the particle arrays.
template <typename Law, int Dim, SetChoice kSets, bool kPrefetch, bool kHot = kPrefetch>
void batched_pair_block(const PassInputs<Dim>& in, Particles<Dim>& p, ContactRows<Dim>& rows,
                        ContactBlocks<Dim>& blocks, int b) {
  // Rows per batch: 128 ran 1.018 (10k) and 1.025 (100k) against 64, 256 as
  // 128, 32 at 0.92 (docs/PERFORMANCE.md).
  constexpr int kBatch = 128;
  constexpr int kAhead = 16;  // rows ahead to fetch (2D)
  // Particles ahead of the batch's first ones whose records and sums are
  // fetched in order (3D, large beds): a row's second particle lies a
  // median 14 slots ahead of its first, nearly nine in ten within 1,024.
  // Fetched as one sweep ahead of the rows, those come as a stream instead
  // of a miss per row; the rest are fetched row by row (docs/PERFORMANCE.md,
  // item 19).
  constexpr Slot kWindow = 1024;
  const LoopSets<kSets> sets(*in.pair_sets);
  const std::int32_t* set_of = in.pair_sets->set_of.data();
  const std::int32_t materials = in.params.count();
  const std::int32_t* material = p.material.data();
  const double dt = in.dt;
  // The packed rows of one batch, structure of arrays.
  alignas(64) double dx[Dim][kBatch], v1[Dim][kBatch], v2[Dim][kBatch];
  alignas(64) double w1[3][kBatch], w2[3][kBatch], shear[3][kBatch];
  alignas(64) double distance2[kBatch], rx[kBatch], ry[kBatch], mx[kBatch], my[kBatch], normal_force[kBatch];
  alignas(64) double force[Dim][kBatch], lever[3][kBatch], overlap[kBatch];
  // Flags travel as doubles: one byte-sized array would make the compiler
  // take 32 contacts per vector step, far more than the registers hold.
  alignas(64) double was_touching[kBatch], sliding[kBatch];
  std::int32_t row[kBatch];
  Slot first_of[kBatch], second_of[kBatch];
  // The row's set number (kSets other than kOne), a double like the flags:
  // 32-bit numbers would make the compiler take 16 contacts per vector step.
  alignas(64) double parameter_set[kBatch];
  // The unpacked batch, before the touching rows are packed.
  alignas(64) double place1[Dim][kBatch], place2[Dim][kBatch], separation[Dim][kBatch], radius1[kBatch],
      radius2[kBatch], batch_distance2[kBatch], batch_touch[kBatch], batch_near[kBatch];
  alignas(64) std::int32_t batch_row[kBatch];
  alignas(64) Slot batch_first[kBatch], batch_second[kBatch];

  // Plain pointers: the flag bytes stored below could alias any vector's
  // own pointer, so reading through the vectors would reload them all.
  const Slot* first = rows.first.data();
  const std::int32_t* second = rows.second.data();
  std::uint8_t* row_flags = rows.flags.data();
  ShearForce<Dim>* row_shear = rows.shear.data();
  double* row_normal_force = rows.normal_force.data();
  std::uint64_t* formed_cycle = rows.formed_cycle.data();
  const Vec<Dim>* position = p.position.data();
  const Vec<Dim>* velocity = p.velocity.data();
  const Spin<Dim>* angular_velocity = p.angular_velocity.data();
  const double* radius = p.radius.data();
  const double* mass = p.mass.data();
  Vec<Dim>* particle_force = p.force.data();
  Spin<Dim>* particle_moment = p.moment.data();
  const std::int32_t* cross_row = blocks.cross_row.data();
  const std::int32_t* cross_slot = blocks.cross_slot.data();
  Vec<Dim>* deferred_force = blocks.deferred_force.data();
  Spin<Dim>* deferred_moment = blocks.deferred_moment.data();
  const HotPlace<Dim>* hot_place = blocks.hot_place.data();
  const HotMotion<Dim>* hot_motion = blocks.hot_motion.data();
  auto position_of = [&](Slot i) -> const Vec<Dim>& {
    if constexpr (kHot)
      return hot_place[i].position;
    else
      return position[i];
  };
  auto radius_of = [&](Slot i) {
    if constexpr (kHot)
      return hot_place[i].radius;
    else
      return radius[i];
  };
  auto velocity_of = [&](Slot i) -> const Vec<Dim>& {
    if constexpr (kHot)
      return hot_motion[i].velocity;
    else
      return velocity[i];
  };
  auto angular_velocity_of = [&](Slot i) -> const Spin<Dim>& {
    if constexpr (kHot)
      return hot_motion[i].angular_velocity;
    else
      return angular_velocity[i];
  };
  auto mass_of = [&](Slot i) {
    if constexpr (kHot)
      return hot_motion[i].mass;
    else
      return mass[i];
  };
  // The 3D pass gathers by columns (batch_columns.h): each quantity's
  // first component and the stride between particles, in doubles; from
  // the copies, four lanes (the radius after the position, the mass after
  // the velocity).
  constexpr int kPlaceStride = kHot ? sizeof(HotPlace<Dim>) / sizeof(double) : Dim;
  constexpr int kLanes = kHot ? 4 : 3;
  constexpr int kMotionStride = kHot ? sizeof(HotMotion<Dim>) / sizeof(double) : Dim;
  const double* place_column = kHot ? reinterpret_cast<const double*>(hot_place) : position->data();
  const double* velocity_column = kHot ? reinterpret_cast<const double*>(hot_motion) : velocity->data();
  const double* spin_column = kHot ? velocity_column + offsetof(HotMotion<Dim>, angular_velocity) / sizeof(double)
                                   : reinterpret_cast<const double*>(angular_velocity);
  const Periodic<Dim> periodic = in.periodic;
  const std::uint64_t cycle = in.cycle;

  std::int32_t cross = blocks.cross_begin[b];
  const std::int32_t cross_end = blocks.cross_begin[b + 1];
  // The block's rows crossing blocks set aside nothing until they touch:
  // zeroed here in one sweep, so that a touching row finds whether it
  // crosses from its second slot alone (about 0.8 crossing rows a particle
  // against 2.4 touching; the search of the row list per touching row cost
  // 3 % of the pass's instructions).
  for (std::int32_t k = cross; k < cross_end; ++k) {
    deferred_force[cross_slot[k]] = Vec<Dim>::Zero();
    deferred_moment[cross_slot[k]] = Space<Dim>::zero_spin();
  }
  const Slot block_first = blocks.particle_begin[b];
  const auto block_size = static_cast<std::uint32_t>(blocks.particle_begin[b + 1] - block_first);
  // The rows to test: the near rows, or, when they are to be sorted out
  // again, every row of the block, keeping those within the margin.
  const std::int32_t begin = blocks.pair_begin[b], end = blocks.pair_begin[b + 1];
  const bool sort_out = blocks.near_stale;
  std::int32_t* near = blocks.near_rows.data() + begin;
  const std::int32_t listed = sort_out ? end - begin : blocks.near_count[b];
  const double margin = in.near_margin;
  std::int32_t kept = 0;
  const Slot block_end = block_first + static_cast<Slot>(block_size);
  const auto particle_count = static_cast<Slot>(p.size());
  Slot window_end = block_first;  // the particles fetched so far: [block_first, window_end)
  for (std::int32_t k0 = 0; k0 < listed; k0 += kBatch) {
    const std::int32_t k1 = std::min(listed, k0 + kBatch);
    // 1. Which rows touch (eq. 8): pack them; a row that stopped touching
    // loses its history.
    int count = 0;
    if constexpr (Dim == 3) {
      // The batch's rows, their particles' places by columns, then the
      // distances in one vector loop, then the touching rows packed.
      const int n = k1 - k0;
      for (int i = 0; i < n; ++i) {
        const std::int32_t r = sort_out ? begin + k0 + i : near[k0 + i];
        batch_row[i] = r;
        batch_first[i] = first[r];
        batch_second[i] = second[r];
        if constexpr (kPrefetch) {  // the same row of the next batch: its misses overlap this batch's work
          const std::int32_t k = k0 + i;
          if (k + kBatch < listed) {
            const std::int32_t row_ahead = sort_out ? begin + k + kBatch : near[k + kBatch];
            const Slot ahead = second[row_ahead];
            fetch_line<Keep::kOnce>(&row_shear[row_ahead]);
            fetch_line(place_column + kPlaceStride * ahead);
            fetch_line(velocity_column + kMotionStride * ahead);
            if constexpr (!kHot) fetch_line(spin_column + kMotionStride * ahead);
          }
        }
      }
      if constexpr (kPrefetch && kHot) {
        // The next batch's rows: read once a step, so kept out of the
        // shared cache, where they would push out the records and sums
        // that the rows after them and the law of motion read again.
        if (k1 < listed) {
          const std::int32_t k2 = std::min(listed, k1 + kBatch);
          const std::int32_t row_lo = sort_out ? begin + k1 : near[k1];
          const std::int32_t row_hi = (sort_out ? begin + k2 - 1 : near[k2 - 1]) + 1;
          if (!sort_out) fetch_lines<Keep::kOnce>(near + k1, near + k2);
          fetch_lines<Keep::kOnce>(first + row_lo, first + row_hi);
          fetch_lines<Keep::kOnce>(second + row_lo, second + row_hi);
          fetch_lines<Keep::kOnce>(row_flags + row_lo, row_flags + row_hi);
        }
        const Slot window_to = std::min(particle_count, batch_first[n - 1] + kWindow);
        if (window_to > window_end) {
          fetch_lines<Keep::kReused>(hot_place + window_end, hot_place + window_to);
          fetch_lines<Keep::kReused>(hot_motion + window_end, hot_motion + window_to);
          const Slot sums_to = std::min(window_to, block_end);  // (others' sums are set aside)
          if (sums_to > window_end) {
            fetch_lines<Keep::kReused>(particle_force + window_end, particle_force + sums_to);
            fetch_lines<Keep::kReused>(particle_moment + window_end, particle_moment + sums_to);
          }
          window_end = window_to;
        }
        // The crossing rows' list, which step 3 reads a few entries a batch:
        // too sparse for the hardware to fetch ahead, and each of its lines
        // missed on the way to a branch.
        if (cross + 32 < cross_end) fetch_line<Keep::kOnce>(cross_row + cross + 32);
      }
      gather_columns<kPlaceStride, kLanes>(place_column, batch_first, n, place1[0], place1[1], place1[2], radius1);
      gather_columns<kPlaceStride, kLanes>(place_column, batch_second, n, place2[0], place2[1], place2[2], radius2);
      if constexpr (!kHot) {
        for (int i = 0; i < n; ++i) {
          radius1[i] = radius[batch_first[i]];
          radius2[i] = radius[batch_second[i]];
        }
      }
      for (int i = 0; i < n; ++i) {
        Vec3 d;
        for (int c = 0; c < 3; ++c) {
          d[c] = nearest_image(place2[c][i] - place1[c][i], periodic.length[c]);
          separation[c][i] = d[c];
        }
        const double d2 = d.squaredNorm();
        const double reach = radius1[i] + radius2[i];
        batch_distance2[i] = d2;
        batch_touch[i] = d2 < reach * reach ? 1.0 : 0.0;
        batch_near[i] = d2 < (reach + margin) * (reach + margin) ? 1.0 : 0.0;
      }
      int i = 0;
#if defined(__AVX512F__) && defined(__AVX512VL__)
      // Eight rows at a time, the touching rows' columns packed by compress
      // instructions: the same bits as the loop below, which copies each
      // number of each row on its own (docs/PERFORMANCE.md, item 26).
      for (; i + 8 <= n; i += 8) {
        const __mmask8 touch = _mm512_cmp_pd_mask(_mm512_load_pd(batch_touch + i), _mm512_setzero_pd(), _CMP_NEQ_OQ);
        unsigned touched = 0;  // the rows that touched at the last pass, a bit each
        for (int k = 0; k < 8; ++k) touched |= static_cast<unsigned>(row_flags[batch_row[i + k]] & kTouching) << k;
        for (unsigned apart = touched & ~static_cast<unsigned>(touch) & 0xffu; apart != 0; apart &= apart - 1) {
          separate(rows, batch_row[i + std::countr_zero(apart)]);
        }
        const auto pack = [&](const double* from, double* to) {
          _mm512_storeu_pd(to + count, _mm512_maskz_compress_pd(touch, _mm512_load_pd(from + i)));
        };
        const auto pack_slots = [&](const std::int32_t* from, std::int32_t* to, __mmask8 mask, int at) {
          const __m256i slots = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(from + i));
          _mm256_storeu_si256(reinterpret_cast<__m256i*>(to + at), _mm256_maskz_compress_epi32(mask, slots));
        };
        for (int c = 0; c < 3; ++c) pack(separation[c], dx[c]);
        pack(batch_distance2, distance2);
        pack(radius1, rx);
        pack(radius2, ry);
        _mm512_storeu_pd(
            was_touching + count,
            _mm512_maskz_compress_pd(touch, _mm512_maskz_mov_pd(static_cast<__mmask8>(touched), _mm512_set1_pd(1.0))));
        pack_slots(batch_row, row, touch, count);
        pack_slots(batch_first, first_of, touch, count);
        pack_slots(batch_second, second_of, touch, count);
        count += std::popcount(static_cast<unsigned>(touch));
        if (sort_out) {  // (kept <= k: the list is rewritten behind the reading)
          const __mmask8 within = _mm512_cmp_pd_mask(_mm512_load_pd(batch_near + i), _mm512_setzero_pd(), _CMP_NEQ_OQ);
          pack_slots(batch_row, near, within, kept);
          kept += std::popcount(static_cast<unsigned>(within));
        }
      }
#endif
      for (; i < n; ++i) {
        const std::int32_t r = batch_row[i];
        for (int c = 0; c < 3; ++c) dx[c][count] = separation[c][i];
        distance2[count] = batch_distance2[i];
        row[count] = r;
        first_of[count] = batch_first[i];
        second_of[count] = batch_second[i];
        rx[count] = radius1[i];
        ry[count] = radius2[i];
        const bool touched = (row_flags[r] & kTouching) != 0;
        was_touching[count] = touched ? 1.0 : 0.0;
        const bool touch = batch_touch[i] != 0.0;
        if (touched & !touch) separate(rows, r);
        count += touch;
        if (sort_out) {  // (kept <= k: the list is rewritten behind the reading)
          near[kept] = r;
          kept += batch_near[i] != 0.0;
        }
      }
    } else {
      for (std::int32_t k = k0; k < k1; ++k) {
        const std::int32_t r = sort_out ? begin + k : near[k];
        const Slot x = first[r], y = second[r];
        if constexpr (kPrefetch) {
          if (k + kAhead < listed) {
            const Slot ahead = second[sort_out ? begin + k + kAhead : near[k + kAhead]];
            if constexpr (kHot) {
              fetch_line(&hot_place[ahead]);
              fetch_line(&hot_motion[ahead]);
            } else {
              fetch_line(&position[ahead]);
              fetch_line(&velocity[ahead]);
              fetch_line(&angular_velocity[ahead]);
            }
          }
        }
        const Vec<Dim> d = periodic.separation(position_of(x), position_of(y));
        const double reach = radius_of(x) + radius_of(y);
        const double d2 = d.squaredNorm();
        for (int c = 0; c < Dim; ++c) dx[c][count] = d[c];
        distance2[count] = d2;
        row[count] = r;
        first_of[count] = x;
        second_of[count] = y;
        const bool touched = (row_flags[r] & kTouching) != 0;
        was_touching[count] = touched ? 1.0 : 0.0;
        const bool touch = d2 < reach * reach;
        // Whether a row touches follows no pattern: no branch on it, only on
        // the rare row that has just stopped touching.
        if (touched & !touch) separate(rows, r);
        count += touch;
        if (sort_out) {  // (kept <= k: the list is rewritten behind the reading)
          near[kept] = r;
          kept += d2 < (reach + margin) * (reach + margin);
        }
      }
    }
    // Gather what the law needs of each packed row's two particles.
    if constexpr (Dim == 3) {
      // (Without the copies the masses are read below.)
      gather_columns<kMotionStride, kLanes>(velocity_column, first_of, count, v1[0], v1[1], v1[2], mx);
      gather_columns<kMotionStride, kLanes>(velocity_column, second_of, count, v2[0], v2[1], v2[2], my);
      gather_columns<kMotionStride>(spin_column, first_of, count, w1[0], w1[1], w1[2]);
      gather_columns<kMotionStride>(spin_column, second_of, count, w2[0], w2[1], w2[2]);
      gather_columns<3>(row_shear->data(), row, count, shear[0], shear[1], shear[2]);
    }
    for (int j = 0; j < count; ++j) {
      const std::int32_t r = row[j];
      const Slot x = first_of[j], y = second_of[j];
      if constexpr (Dim == 2 || !kHot) {
        mx[j] = mass_of(x);
        my[j] = mass_of(y);
      }
      if constexpr (Dim == 2) {
        rx[j] = radius_of(x);
        ry[j] = radius_of(y);
        for (int k = 0; k < Dim; ++k) {
          v1[k][j] = velocity_of(x)[k];
          v2[k][j] = velocity_of(y)[k];
        }
        w1[0][j] = angular_velocity_of(x);
        w2[0][j] = angular_velocity_of(y);
        shear[0][j] = row_shear[r];
      }
      if constexpr (Law::kNormalHistory) normal_force[j] = row_normal_force[r];
      if constexpr (kSets != SetChoice::kOne) parameter_set[j] = set_of[material[x] * materials + material[y]];
    }
    // 2. The contact law on the packed rows (Cundall & Strack eqs. 9-19).
    for (int j = 0; j < count; ++j) {
      Vec<Dim> d, va, vb;
      for (int k = 0; k < Dim; ++k) {
        d[k] = dx[k][j];
        va[k] = v1[k][j];
        vb[k] = v2[k][j];
      }
      const Spin<Dim> wa = column_entry<Dim>(w1, j), wb = column_entry<Dim>(w2, j);
      ContactHistory<Dim> h;
      h.shear = column_entry<Dim>(shear, j);
      h.touching = was_touching[j] != 0.0;
      if constexpr (Law::kNormalHistory) h.normal_force = normal_force[j];
      const ContactGeometry<Dim> g = RoundShape::geometry<Dim>(d, distance2[j], rx[j], ry[j], Vec<Dim>::Zero());
      const Vec<Dim> relative = relative_contact_velocity(va, wa, rx[j], vb, wb, ry[j], g.normal);
      carry_shear(h.shear, g.normal);  // a row that did not touch has no shear to carry
      const PairProperties pair{g.effective_radius, mx[j] * my[j] / (mx[j] + my[j])};  // Randall 4.5-4.6
      const ContactKinematics<Dim> kin = kinematics(g.overlap, relative, g.normal);
      const auto& params = sets[kSets == SetChoice::kOne ? 0.0 : parameter_set[j]];
      Law::advance(h, kin, pair, params, dt);
      const ContactForces<Dim> f = Law::forces(h, kin, pair, params);
      const ShearForce<Dim> total = f.shear + f.shear_damping;
      const Vec<Dim> on_first = -(f.normal + f.normal_damping) * g.normal - shear_vector(total, g.normal);
      const Spin<Dim> turn = shear_lever(total, g.normal);
      for (int k = 0; k < Dim; ++k) force[k][j] = on_first[k];
      set_column_entry<Dim>(lever, j, turn);
      set_column_entry<Dim>(shear, j, h.shear);
      sliding[j] = h.sliding ? 1.0 : 0.0;
      overlap[j] = g.overlap;
      if constexpr (Law::kNormalHistory) normal_force[j] = h.normal_force;
    }
    // 3. History back to the rows, shares into the sums in row order; the
    // second particle's share of a row crossing blocks is set aside.
    for (int j = 0; j < count; ++j) {
      const std::int32_t r = row[j];
      const Slot x = first_of[j], y = second_of[j];
      if (overlap[j] <= 0.0) {  // the root rounded up to the reach: apart after all
        if (was_touching[j] != 0.0) separate(rows, r);
        continue;
      }
      row_shear[r] = column_entry<Dim>(shear, j);
      if constexpr (Law::kNormalHistory) row_normal_force[r] = normal_force[j];
      if (was_touching[j] == 0.0) formed_cycle[r] = cycle;
      row_flags[r] = sliding[j] != 0.0 ? kTouching | kSliding : kTouching;
      Vec<Dim> on_first;
      for (int k = 0; k < Dim; ++k) on_first[k] = force[k][j];
      const Spin<Dim> turn = column_entry<Dim>(lever, j);
      particle_force[x] += on_first;
      particle_moment[x] += rx[j] * turn;
      if (static_cast<std::uint32_t>(y - block_first) >= block_size) {  // a crossing row (contact_blocks.h)
        while (cross_row[cross] != r) ++cross;
        deferred_force[cross_slot[cross]] = -on_first;
        deferred_moment[cross_slot[cross]] = ry[j] * turn;
        ++cross;
      } else {
        particle_force[y] -= on_first;
        particle_moment[y] += ry[j] * turn;
      }
    }
  }
  if (sort_out) blocks.near_count[b] = kept;
}

}  // namespace dem
