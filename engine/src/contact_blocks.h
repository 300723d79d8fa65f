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
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "contact_table.h"
#include "inline.h"
#include "large_pages.h"
#include "particle_fields.h"
#include "particles.h"

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

// Each field's place in the copies comes from the field list
// (particle_fields.h: HotLane): the first double of the field in its
// record. The members the pass reads by name lie where the list puts them.
template <HotRecord kRecord, int Dim>
using HotRecordOf = std::conditional_t<kRecord == HotRecord::kPlace, HotPlace<Dim>, HotMotion<Dim>>;

template <typename T>
constexpr int lane_width() {
  if constexpr (std::is_arithmetic_v<T>) {
    return 1;
  } else {
    return static_cast<int>(T::SizeAtCompileTime);
  }
}

// The first double of the field `name` in its record, -1 if it has none.
template <int Dim>
constexpr int hot_lane(std::string_view name) {
  int lane = -1;
  for_each_particle_field<Dim>([&](const ParticleFieldInfo& info, auto, auto, auto hot) {
    if (decltype(hot)::record != HotRecord::kNone && std::string_view(info.name) == name) lane = decltype(hot)::lane;
  });
  return lane;
}

// The fields of a record lie apart and inside it.
template <int Dim, HotRecord kRecord>
constexpr bool hot_lanes_fit() {
  constexpr int kWidth = sizeof(HotRecordOf<kRecord, Dim>) / sizeof(double);
  bool used[kWidth] = {};
  bool fit = true;
  for_each_particle_field<Dim>([&](const ParticleFieldInfo&, auto column, auto, auto hot) {
    using Hot = decltype(hot);
    if constexpr (Hot::record == kRecord) {
      using Value = std::remove_cvref_t<decltype(column(std::declval<const Particles<Dim>&>())[0])>;
      for (int k = Hot::lane; k < Hot::lane + lane_width<Value>(); ++k) {
        if (k >= kWidth || used[k]) {
          fit = false;
        } else {
          used[k] = true;
        }
      }
    }
  });
  return fit;
}

template <int Dim>
constexpr bool hot_lanes_match() {
  constexpr auto at = [](std::size_t offset) { return static_cast<int>(offset / sizeof(double)); };
  return hot_lanes_fit<Dim, HotRecord::kPlace>() && hot_lanes_fit<Dim, HotRecord::kMotion>() &&
         hot_lane<Dim>("position") == at(offsetof(HotPlace<Dim>, position)) &&
         hot_lane<Dim>("radius") == at(offsetof(HotPlace<Dim>, radius)) &&
         hot_lane<Dim>("velocity") == at(offsetof(HotMotion<Dim>, velocity)) &&
         hot_lane<Dim>("mass") == at(offsetof(HotMotion<Dim>, mass)) &&
         hot_lane<Dim>("angular_velocity") == at(offsetof(HotMotion<Dim>, angular_velocity));
}
static_assert(hot_lanes_match<2>() && hot_lanes_match<3>(),
              "the side-by-side copies (HotPlace, HotMotion) and the field list's HotLanes disagree");

// The doubles of one field at their lanes.
template <typename T>
DEM_INLINE void put_lanes(double* lanes, const T& value) {
  if constexpr (std::is_arithmetic_v<T>) {
    lanes[0] = value;
  } else {
    for (int k = 0; k < lane_width<T>(); ++k) lanes[k] = value[k];
  }
}

// Slot i's fields of record kRecord at their lanes of `record`.
template <HotRecord kRecord, int Dim>
DEM_INLINE void put_hot_fields(const Particles<Dim>& p, std::int64_t i, double* record) {
  for_each_particle_field<Dim>([&](const ParticleFieldInfo&, auto column, auto, auto hot) DEM_INLINE_LAMBDA {
    using Hot = decltype(hot);
    if constexpr (Hot::record == kRecord) put_lanes(record + Hot::lane, column(p)[i]);
  });
}

// Slots [begin, end) of the particles into the side-by-side copies: by the
// force pass, or by the law of motion while each particle's new values
// are still in the core's cache (motion.cpp, motion_plain.h). In 3D with
// AVX each record is written whole, four lanes at a time (its unused lanes
// zero). kStream (the law of motion on large beds): with streaming stores,
// which go to memory without first reading in the lines they fill, where a
// plain store reads each line it writes (96 bytes a particle more); the
// pass fetches the records ahead when it needs them (contact_batch.h). Call
// finish_streaming before another thread reads them.
template <bool kStream = false, int Dim>
void copy_hot_particles(const Particles<Dim>& p, HotPlace<Dim>* place, HotMotion<Dim>* motion, std::int64_t begin,
                        std::int64_t end) {
#if defined(__AVX__)
  if constexpr (Dim == 3) {
    static_assert(sizeof(HotPlace<3>) == 32 && sizeof(HotMotion<3>) == 64);
    const auto put = [](double* to, const double* lanes) DEM_INLINE_LAMBDA {
      const __m256d value = _mm256_setr_pd(lanes[0], lanes[1], lanes[2], lanes[3]);
      if constexpr (kStream) {
        _mm256_stream_pd(to, value);
      } else {
        _mm256_store_pd(to, value);
      }
    };
    for (std::int64_t i = begin; i < end; ++i) {
      double place_lanes[4] = {}, motion_lanes[8] = {};
      put_hot_fields<HotRecord::kPlace>(p, i, place_lanes);
      put_hot_fields<HotRecord::kMotion>(p, i, motion_lanes);
      double* record = reinterpret_cast<double*>(&motion[i]);
      put(reinterpret_cast<double*>(&place[i]), place_lanes);
      put(record, motion_lanes);
      put(record + 4, motion_lanes + 4);
    }
    return;
  }
#endif
  for (std::int64_t i = begin; i < end; ++i) {
    put_hot_fields<HotRecord::kPlace>(p, i, reinterpret_cast<double*>(&place[i]));
    put_hot_fields<HotRecord::kMotion>(p, i, reinterpret_cast<double*>(&motion[i]));
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
