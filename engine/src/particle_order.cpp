#include "particle_order.h"

#include <algorithm>
#include <cstdint>

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

}  // namespace

template <int Dim>
std::vector<Slot> spatial_order(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double range) {
  const std::size_t n = particles.size();
  if (n == 0) return {};
  const CellGrid<Dim> grid = build_grid(particles, periodic, range);
  struct Entry {
    std::uint64_t code;
    ParticleId id;
    Slot slot;
  };
  std::vector<Entry> entries(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto cell = grid.cell_of(particles.position[i]);
    std::uint64_t code = 0;
    for (int d = 0; d < Dim; ++d) code |= spread(static_cast<std::uint64_t>(cell[d]), Dim) << d;
    entries[i] = {code, particles.id[i], static_cast<Slot>(i)};
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.code < b.code || (a.code == b.code && a.id < b.id); });
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
