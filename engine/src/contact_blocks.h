// Force sums in parallel that come out bit for bit the same for any number
// of threads. The particle slots are cut into fixed blocks of consecutive
// slots (a compact patch of the assembly, particle_order.h); the cut depends
// on the particle count only. A block's pair rows are those whose first
// particle it holds, its wall rows those of its particles. One task per
// block computes its rows and adds each share straight into its own
// particles' sums, in row order; a share for a particle of another block
// (a cross row) is set aside and added after all blocks are done, in row
// order. So every sum has one fixed order: its own block's rows, then the
// cross rows, whatever thread ran which block.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "contact_table.h"
#include "large_pages.h"

namespace dem {

// Beyond this many particles the arrays the force pass reads no longer fit
// the core's own cache (about 150 bytes a particle against 1 MiB of L2):
// the pass fetches ahead (contact_batch.h) and the law of motion streams
// the copies below. Below it the prefetches are pure overhead (5 % more
// instructions).
inline constexpr std::int64_t kPrefetchParticles = 32768;

// One particle's data as the batched pair pass reads it (contact_batch.h),
// copied side by side from the particle arrays: a row's second particle
// lies anywhere ahead of the first in memory, and from the separate arrays
// its touch test and gather miss five cache lines (position, radius,
// velocity, spin, mass); from these two records, one or two. The touch
// test reads only the first record. In 3D the fourth lane of each holds
// the radius or the mass, which the pass gathers with the vector before
// it (batch_columns.h): so 3D beds of every size use the copies, 2D beds
// only large ones.
template <int Dim>
struct alignas(32) HotPlace {
  Vec<Dim> position;
  double radius;
};
template <int Dim>
struct alignas(64) HotMotion {
  Vec<Dim> velocity;
  double mass;
  Spin<Dim> angular_velocity;
};

// Slots [begin, end) of the particles into the side-by-side copies: by the
// force pass, or by the law of motion while each particle's new values
// are still in the core's cache (motion.cpp, motion_plain.h). In 3D with
// AVX each record is written whole, four lanes at a time. kStream (the law
// of motion on large beds): with streaming stores, which go to memory
// without first reading in the lines they fill, where a plain store reads
// each line it writes (96 bytes a particle more); the pass fetches the
// records ahead when it needs them (contact_batch.h). Call
// finish_streaming before another thread reads them.
template <bool kStream = false, int Dim>
void copy_hot_particles(const Particles<Dim>& p, HotPlace<Dim>* place, HotMotion<Dim>* motion, std::int64_t begin,
                        std::int64_t end) {
#if defined(__AVX__)
  if constexpr (Dim == 3) {
    static_assert(sizeof(HotPlace<3>) == 32 && offsetof(HotPlace<3>, radius) == 24);
    static_assert(sizeof(HotMotion<3>) == 64 && offsetof(HotMotion<3>, mass) == 24 &&
                  offsetof(HotMotion<3>, angular_velocity) == 32);
    const auto put = [](double* to, __m256d value) {
      if constexpr (kStream) {
        _mm256_stream_pd(to, value);
      } else {
        _mm256_store_pd(to, value);
      }
    };
    for (std::int64_t i = begin; i < end; ++i) {
      const Vec3& x = p.position[i];
      const Vec3& v = p.velocity[i];
      const Vec3& w = p.angular_velocity[i];
      double* record = reinterpret_cast<double*>(&motion[i]);
      put(reinterpret_cast<double*>(&place[i]), _mm256_setr_pd(x[0], x[1], x[2], p.radius[i]));
      put(record, _mm256_setr_pd(v[0], v[1], v[2], p.mass[i]));
      put(record + 4, _mm256_setr_pd(w[0], w[1], w[2], 0.0));
    }
    return;
  }
#endif
  for (std::int64_t i = begin; i < end; ++i) {
    place[i].position = p.position[i];
    place[i].radius = p.radius[i];
    motion[i].velocity = p.velocity[i];
    motion[i].mass = p.mass[i];
    motion[i].angular_velocity = p.angular_velocity[i];
  }
}

// Orders the streaming stores before whatever follows (another thread's
// reads after a barrier included).
inline void finish_streaming() {
#if defined(__AVX__)
  _mm_sfence();
#endif
}

template <int Dim>
struct ContactBlocks {
  std::vector<Slot> particle_begin;      // block b holds slots [particle_begin[b], particle_begin[b + 1])
  std::vector<std::int32_t> pair_begin;  // its pair rows [pair_begin[b], pair_begin[b + 1])
  std::vector<std::int32_t> wall_begin;  // its wall rows
  // Cross rows, by the block holding their first particle, ascending:
  // row cross_row[k] sets its second particle's share aside in deferred[cross_slot[k]].
  std::vector<std::int32_t> cross_begin;
  Column<std::int32_t> cross_row;
  Column<std::int32_t> cross_slot;
  // The shares set aside, grouped by the block of the particle they go to
  // (deferred_begin), in row order within each group.
  std::vector<std::int32_t> deferred_begin;
  Column<Slot> deferred_particle;
  Column<Vec<Dim>> deferred_force;
  Column<Spin<Dim>> deferred_moment;
  // The near rows: of the pair rows within the tolerance, those whose gap
  // was below a margin when last sorted out. The others cannot touch until
  // particles have moved that margin, so the batched force pass
  // (contact_batch.h) leaves them out; which rows it reads changes nothing
  // it computes, as apart rows carry no force and no history. Block b's
  // near rows, ascending, are near_rows[pair_begin[b] .. pair_begin[b] +
  // near_count[b]); `near_stale` asks the next pass to sort them out again.
  Column<std::int32_t> near_rows;
  std::vector<std::int32_t> near_count;
  bool near_stale = true;
  // The batched pass's copies of the particles it reads (HotPlace), by
  // slot: in 3D and on 2D beds past kPrefetchParticles, written by the law
  // of motion or at the start of the pass (PERFORMANCE.md, item 28); empty
  // when no batched pass runs.
  Column<HotPlace<Dim>> hot_place;
  Column<HotMotion<Dim>> hot_motion;
  // Whether the law of motion wrote those copies this step, after the
  // particles moved and before anything reordered them: the pass then
  // reads them as they are instead of copying (motion.cpp).
  bool hot_fresh = false;

  int count() const { return static_cast<int>(particle_begin.size()) - 1; }
  int block_of(Slot s) const;
};

// Cuts `particles` slots into a power of two of blocks of about
// `block_size` and sorts the table's rows into them; call after every
// change to the table's keys.
template <int Dim>
void plan_blocks(ContactBlocks<Dim>& blocks, const ContactTable<Dim>& table, std::size_t particles, int block_size);

}  // namespace dem
