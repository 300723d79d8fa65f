#include "broad_phase.h"

#include <algorithm>
#include <array>
#include <cstdint>

#include "cell_grid.h"
#include "parallel.h"

namespace dem {

namespace {

// Calls visit(j) for every particle j with a higher id than i's in the
// 3^Dim cells around i whose gap to i is below tolerance. Along a periodic
// axis the cells wrap around; with fewer than three cells there, some
// neighbours coincide and are visited once.
template <int Dim, typename Visit>
void for_each_near(const CellGrid<Dim>& grid, const Particles<Dim>& particles, const Periodic<Dim>& periodic, Slot i,
                   double tolerance, Visit visit) {
  const Vec<Dim>& xi = particles.position[i];
  const ParticleId id = particles.id[i];
  const auto home = grid.cell_of(xi);
  constexpr int kNeighbourCells = Dim == 2 ? 9 : 27;
  std::array<std::int64_t, kNeighbourCells> neighbours;
  int count = 0;
  for (int k = 0; k < kNeighbourCells; ++k) {
    typename CellGrid<Dim>::Cell cell;
    bool inside = true;
    for (int d = 0, code = k; d < Dim; ++d, code /= 3) {
      cell[d] = home[d] + code % 3 - 1;
      if (grid.wraps[d]) {
        cell[d] = (cell[d] + grid.counts[d]) % grid.counts[d];
      } else {
        inside = inside && cell[d] >= 0 && cell[d] < grid.counts[d];
      }
    }
    if (!inside) continue;
    const std::int64_t c = grid.index(cell);
    if (std::find(neighbours.begin(), neighbours.begin() + count, c) == neighbours.begin() + count) {
      neighbours[count++] = c;
    }
  }
  for (int k = 0; k < count; ++k) {
    const std::int64_t c = neighbours[k];
    for (std::int32_t s = grid.cell_start[c]; s < grid.cell_start[c + 1]; ++s) {
      const Slot j = grid.cell_particles[s];
      if (particles.id[j] <= id) continue;
      const double gap =
          periodic.separation(xi, particles.position[j]).norm() - particles.radius[i] - particles.radius[j];
      if (gap < tolerance) visit(j);
    }
  }
}

}  // namespace

template <int Dim>
std::vector<ContactKey> find_pair_keys(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double tolerance,
                                       int threads) {
  const auto n = static_cast<std::int32_t>(particles.size());
  if (n < 2) return {};
  double max_radius = 0.0;
  for (double r : particles.radius) max_radius = std::max(max_radius, r);
  const CellGrid<Dim> grid = build_grid(particles, periodic, 2.0 * max_radius + tolerance);

  // Two passes (count, then fill) give every particle a fixed range of the
  // list, so the list is identical for any thread count.
  std::vector<std::int64_t> offsets(static_cast<std::size_t>(n) + 1, 0);
  DEM_PARALLEL_FOR(threads, n)
  for (std::int32_t i = 0; i < n; ++i) {
    std::int64_t count = 0;
    for_each_near(grid, particles, periodic, i, tolerance, [&](Slot) { ++count; });
    offsets[i + 1] = count;
  }
  for (std::int32_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
  std::vector<ContactKey> keys(static_cast<std::size_t>(offsets[n]));
  DEM_PARALLEL_FOR(threads, n)
  for (std::int32_t i = 0; i < n; ++i) {
    std::int64_t k = offsets[i];
    for_each_near(grid, particles, periodic, i, tolerance, [&](Slot j) { keys[k++] = {i, j}; });
    std::sort(keys.begin() + offsets[i], keys.begin() + offsets[i + 1]);
  }
  return keys;
}

template <int Dim>
std::vector<ContactKey> find_wall_keys(const Particles<Dim>& particles, const Walls<Dim>& walls, double tolerance) {
  std::vector<ContactKey> keys;
  const auto n = static_cast<std::int32_t>(particles.size());
  for (Slot i = 0; i < n; ++i) {
    for (std::int32_t w = 0; w < walls.size(); ++w) {
      if (walls.def[w].removed) continue;
      const auto q = closest_point(walls.def[w], particles.position[i]);
      if ((particles.position[i] - q.point).norm() - particles.radius[i] < tolerance) keys.push_back({i, w});
    }
  }
  return keys;
}

template std::vector<ContactKey> find_pair_keys(const Particles<2>&, const Periodic<2>&, double, int);
template std::vector<ContactKey> find_pair_keys(const Particles<3>&, const Periodic<3>&, double, int);
template std::vector<ContactKey> find_wall_keys(const Particles<2>&, const Walls<2>&, double);
template std::vector<ContactKey> find_wall_keys(const Particles<3>&, const Walls<3>&, double);

}  // namespace dem
