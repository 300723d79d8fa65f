#include "particle_order.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "cell_grid.h"

namespace dem {

namespace {

// Spreads the low 21 bits of v three apart (3D) or the low 32 two apart (2D).
std::uint64_t spread(std::uint64_t v, int dim) {
  if (dim == 3) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  }
  v &= 0xffffffffULL;
  v = (v | v << 16) & 0x0000ffff0000ffffULL;
  v = (v | v << 8) & 0x00ff00ff00ff00ffULL;
  v = (v | v << 4) & 0x0f0f0f0f0f0f0f0fULL;
  v = (v | v << 2) & 0x3333333333333333ULL;
  v = (v | v << 1) & 0x5555555555555555ULL;
  return v;
}

// Bisections stop at this many particles; inside, the Morton curve orders
// the cells (half a block of spheres, world_state.h).
constexpr std::ptrdiff_t kLeafParticles = 2048;

template <int Dim>
struct Entry {
  typename CellGrid<Dim>::Cell cell;
  std::uint64_t code;  // along the Morton curve
  ParticleId id;
  Slot slot;
};

// Along the Morton curve, a cell's particles in id order.
template <int Dim>
bool along_curve(const Entry<Dim>& a, const Entry<Dim>& b) {
  return a.code < b.code || (a.code == b.code && a.id < b.id);
}

// Splits entries [begin, end), which lie in the cells [lo, hi] (inclusive),
// into two halves by count, across the axis whose cut is smallest: the
// area of the cross-section, twice over for an axis the box spans whole
// and that repeats (the cut is then made at the period's seam too). The
// halves follow a total order (cell along the axis, curve, id), so they
// depend on positions and ids only.
template <int Dim>
void bisect(const CellGrid<Dim>& grid, Entry<Dim>* begin, Entry<Dim>* end, typename CellGrid<Dim>::Cell lo,
            typename CellGrid<Dim>::Cell hi) {
  if (end - begin <= kLeafParticles) {
    std::sort(begin, end, along_curve<Dim>);
    return;
  }
  int axis = 0;
  double least = std::numeric_limits<double>::infinity();
  for (int a = 0; a < Dim; ++a) {
    double area = 1.0;
    for (int k = 0; k < Dim; ++k) {
      if (k != a) area *= static_cast<double>(hi[k] - lo[k] + 1) * grid.cell_size[k];
    }
    if (grid.wraps[a] && lo[a] == 0 && hi[a] == grid.counts[a] - 1) area *= 2.0;
    if (area < least) {
      least = area;
      axis = a;
    }
  }
  Entry<Dim>* mid = begin + (end - begin) / 2;
  std::nth_element(begin, mid, end, [axis](const Entry<Dim>& a, const Entry<Dim>& b) {
    if (a.cell[axis] != b.cell[axis]) return a.cell[axis] < b.cell[axis];
    return along_curve(a, b);
  });
  auto left_hi = hi, right_lo = lo;
  left_hi[axis] = right_lo[axis] = mid->cell[axis];
  bisect(grid, begin, mid, lo, left_hi);
  bisect(grid, mid, end, right_lo, hi);
}

}  // namespace

template <int Dim>
std::vector<Slot> spatial_order(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double range) {
  const std::size_t n = particles.size();
  if (n == 0) return {};
  const CellGrid<Dim> grid = build_grid(particles, periodic, range);
  std::vector<Entry<Dim>> entries(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto cell = grid.cell_of(particles.position[i]);
    std::uint64_t code = 0;
    for (int d = 0; d < Dim; ++d) code |= spread(static_cast<std::uint64_t>(cell[d]), Dim) << d;
    entries[i] = {cell, code, particles.id[i], static_cast<Slot>(i)};
  }
  typename CellGrid<Dim>::Cell lo{}, hi{};
  for (int d = 0; d < Dim; ++d) hi[d] = grid.counts[d] - 1;
  bisect(grid, entries.data(), entries.data() + n, lo, hi);
  std::vector<Slot> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = entries[k].slot;
  return order;
}

template <int Dim>
void reorder_particles(Particles<Dim>& particles, ContactTable<Dim>& contacts, const std::vector<Slot>& order) {
  particles.for_each_slot_array([&](auto& values) { gather(values, order); });
  particles.index_ids();
  std::vector<Slot> renamed(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) renamed[static_cast<std::size_t>(order[k])] = static_cast<Slot>(k);
  rename_slots(contacts.pairs, renamed, true);
  rename_slots(contacts.walls, renamed, false);
}

template std::vector<Slot> spatial_order(const Particles<2>&, const Periodic<2>&, double);
template std::vector<Slot> spatial_order(const Particles<3>&, const Periodic<3>&, double);
template void reorder_particles(Particles<2>&, ContactTable<2>&, const std::vector<Slot>&);
template void reorder_particles(Particles<3>&, ContactTable<3>&, const std::vector<Slot>&);

}  // namespace dem
