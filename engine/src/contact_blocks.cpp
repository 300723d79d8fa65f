#include "contact_blocks.h"

#include <algorithm>
#include <numbers>

namespace dem {

template <int Dim>
int ContactBlocks<Dim>::block_of(Slot s) const {
  const auto it = std::upper_bound(particle_begin.begin(), particle_begin.end(), s);
  return static_cast<int>(it - particle_begin.begin()) - 1;
}

namespace {

// For rows sorted by their first slot: the first row of each block.
std::vector<std::int32_t> row_begins(const Column<Slot>& first, const std::vector<Slot>& particle_begin) {
  std::vector<std::int32_t> begins(particle_begin.size());
  for (std::size_t b = 0; b < particle_begin.size(); ++b) {
    begins[b] =
        static_cast<std::int32_t>(std::lower_bound(first.begin(), first.end(), particle_begin[b]) - first.begin());
  }
  return begins;
}

}  // namespace

template <int Dim>
void plan_blocks(ContactBlocks<Dim>& blocks, const ContactTable<Dim>& table, std::size_t particles, int block_size) {
  const auto n = static_cast<std::int64_t>(particles);
  // A power of two of blocks, the nearest to n / block_size (within a
  // factor of the square root of two): each block is then one of the
  // particle order's last halves, a compact box (particle_order.h), and so
  // is each thread's run of blocks. Against 24 blocks on the 100k bed, 16
  // or 32 ran 1.017 (docs/PERFORMANCE.md, item 22).
  const double per_size = static_cast<double>(n) / static_cast<double>(block_size);
  std::int64_t count = 1;
  while (static_cast<double>(2 * count) <= per_size * std::numbers::sqrt2) count *= 2;
  blocks.particle_begin.resize(static_cast<std::size_t>(count) + 1);
  for (std::int64_t b = 0; b <= count; ++b) blocks.particle_begin[b] = static_cast<Slot>(b * n / count);
  blocks.pair_begin = row_begins(table.pairs.first, blocks.particle_begin);
  blocks.wall_begin = row_begins(table.walls.first, blocks.particle_begin);

  // Which block each slot belongs to, for the rows' second particles.
  std::vector<std::int32_t> block(particles);
  for (std::int64_t b = 0; b < count; ++b) {
    std::fill(block.begin() + blocks.particle_begin[b], block.begin() + blocks.particle_begin[b + 1],
              static_cast<std::int32_t>(b));
  }
  const ContactRows<Dim>& rows = table.pairs;
  blocks.deferred_begin.assign(static_cast<std::size_t>(count) + 1, 0);
  blocks.cross_begin.assign(static_cast<std::size_t>(count) + 1, 0);
  for (std::int64_t b = 0; b < count; ++b) {
    for (std::int32_t r = blocks.pair_begin[b]; r < blocks.pair_begin[b + 1]; ++r) {
      const std::int32_t target = block[static_cast<std::size_t>(rows.second[r])];
      if (target == b) continue;
      ++blocks.deferred_begin[target + 1];
      ++blocks.cross_begin[b + 1];
    }
  }
  for (std::int64_t b = 0; b < count; ++b) {
    blocks.deferred_begin[b + 1] += blocks.deferred_begin[b];
    blocks.cross_begin[b + 1] += blocks.cross_begin[b];
  }
  const std::int32_t crossing = blocks.cross_begin[count];
  blocks.cross_row.resize(crossing);
  blocks.cross_slot.resize(crossing);
  blocks.deferred_particle.resize(crossing);
  blocks.deferred_force.assign(crossing, Vec<Dim>::Zero());
  blocks.deferred_moment.assign(crossing, Space<Dim>::zero_spin());
  blocks.near_rows.resize(rows.size());
  blocks.near_count.assign(static_cast<std::size_t>(count), 0);
  blocks.near_stale = true;
  std::vector<std::int32_t> cursor(blocks.deferred_begin.begin(), blocks.deferred_begin.end() - 1);
  std::int32_t k = 0;
  // Rows in ascending order: each target's group fills in row order.
  for (std::int64_t b = 0; b < count; ++b) {
    for (std::int32_t r = blocks.pair_begin[b]; r < blocks.pair_begin[b + 1]; ++r) {
      const Slot second = rows.second[r];
      const std::int32_t target = block[static_cast<std::size_t>(second)];
      if (target == b) continue;
      const std::int32_t slot = cursor[target]++;
      blocks.cross_row[k] = r;
      blocks.cross_slot[k] = slot;
      blocks.deferred_particle[slot] = second;
      ++k;
    }
  }
}

template struct ContactBlocks<2>;
template struct ContactBlocks<3>;
template void plan_blocks(ContactBlocks<2>&, const ContactTable<2>&, std::size_t, int);
template void plan_blocks(ContactBlocks<3>&, const ContactTable<3>&, std::size_t, int);

}  // namespace dem
