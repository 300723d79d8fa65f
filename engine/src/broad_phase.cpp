#include "broad_phase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "parallel.h"

namespace dem {

namespace {

template <int Dim>
struct CellGrid {
  using Cell = std::array<std::int64_t, Dim>;
  Vec<Dim> origin;
  Vec<Dim> cell_size;  // along each axis; periodic axes are tiled exactly
  Cell counts{};       // cells along each axis
  std::array<bool, Dim> wraps{};
  std::vector<std::int32_t> cell_start;  // CSR: particles of cell c are cell_particles[start[c]..start[c+1])
  std::vector<std::int32_t> cell_particles;

  Cell cell_of(const Vec<Dim>& x) const {
    Cell c;
    for (int d = 0; d < Dim; ++d) {
      c[d] = std::clamp<std::int64_t>(static_cast<std::int64_t>((x[d] - origin[d]) / cell_size[d]), 0, counts[d] - 1);
    }
    return c;
  }
  std::int64_t index(const Cell& c) const {
    std::int64_t i = 0;
    for (int d = Dim - 1; d >= 0; --d) i = i * counts[d] + c[d];
    return i;
  }
};

template <int Dim>
CellGrid<Dim> build_grid(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double tolerance) {
  const std::size_t n = particles.size();
  CellGrid<Dim> grid;
  Vec<Dim> lo = particles.position[0], hi = particles.position[0];
  double max_radius = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(particles.position[i]);
    hi = hi.cwiseMax(particles.position[i]);
    max_radius = std::max(max_radius, particles.radius[i]);
  }
  for (int d = 0; d < Dim; ++d) {
    grid.wraps[d] = periodic.repeats(d);
    if (grid.wraps[d]) {
      lo[d] = periodic.min[d];
      hi[d] = periodic.min[d] + periodic.length[d];
    }
  }
  // Any touching-or-near pair lies in neighbouring cells.
  double size = 2.0 * max_radius + tolerance;
  const Vec<Dim> extent = hi - lo;
  // A few particles flung far away must not blow the grid up: keep at most
  // about 4 cells per particle by growing the cells.
  const double max_cells = 4.0 * static_cast<double>(n) + 16.0;
  auto cell_count = [&] {
    double cells = 1.0;
    for (int d = 0; d < Dim; ++d) cells *= extent[d] / size + 1.0;
    return cells;
  };
  while (cell_count() > max_cells) size *= 2.0;
  grid.origin = lo;
  std::int64_t cells = 1;
  for (int d = 0; d < Dim; ++d) {
    if (grid.wraps[d]) {
      // A whole number of cells, each at least `size`, tiles the period.
      grid.counts[d] = std::max<std::int64_t>(1, static_cast<std::int64_t>(extent[d] / size));
      grid.cell_size[d] = extent[d] / static_cast<double>(grid.counts[d]);
    } else {
      grid.counts[d] = static_cast<std::int64_t>(extent[d] / size) + 1;
      grid.cell_size[d] = size;
    }
    cells *= grid.counts[d];
  }

  std::vector<std::int64_t> cell_of(n);
  grid.cell_start.assign(cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = grid.index(grid.cell_of(particles.position[i]));
    ++grid.cell_start[cell_of[i] + 1];
  }
  for (std::int64_t c = 0; c < cells; ++c) grid.cell_start[c + 1] += grid.cell_start[c];
  grid.cell_particles.resize(n);
  std::vector<std::int32_t> cursor(grid.cell_start.begin(), grid.cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) grid.cell_particles[cursor[cell_of[i]]++] = static_cast<std::int32_t>(i);
  return grid;
}

// Calls visit(j) for every j > i in the 3^Dim cells around particle i whose
// gap is below tolerance. Along a periodic axis the cells wrap around; with
// fewer than three cells there, some neighbours coincide and are visited once.
template <int Dim, typename Visit>
void for_each_near(const CellGrid<Dim>& grid, const Particles<Dim>& particles, const Periodic<Dim>& periodic,
                   std::int32_t i, double tolerance, Visit visit) {
  const Vec<Dim>& xi = particles.position[i];
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
    for (std::int32_t slot = grid.cell_start[c]; slot < grid.cell_start[c + 1]; ++slot) {
      const std::int32_t j = grid.cell_particles[slot];
      if (j <= i) continue;
      const double gap =
          periodic.separation(xi, particles.position[j]).norm() - particles.radius[i] - particles.radius[j];
      if (gap < tolerance) visit(j);
    }
  }
}

}  // namespace

template <int Dim>
std::vector<Candidate> find_pair_candidates(const Particles<Dim>& particles, const Periodic<Dim>& periodic,
                                            double tolerance, int threads) {
  const auto n = static_cast<std::int32_t>(particles.size());
  if (n < 2) return {};
  const CellGrid<Dim> grid = build_grid(particles, periodic, tolerance);

  // Two passes (count, then fill) give every particle a fixed slot range, so
  // the list is identical for any thread count.
  std::vector<std::int32_t> offsets(n + 1, 0);
  DEM_PARALLEL_FOR(threads, n)
  for (std::int32_t i = 0; i < n; ++i) {
    std::int32_t count = 0;
    for_each_near(grid, particles, periodic, i, tolerance, [&](std::int32_t) { ++count; });
    offsets[i + 1] = count;
  }
  for (std::int32_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
  std::vector<Candidate> candidates(offsets[n]);
  DEM_PARALLEL_FOR(threads, n)
  for (std::int32_t i = 0; i < n; ++i) {
    std::int32_t slot = offsets[i];
    for_each_near(grid, particles, periodic, i, tolerance, [&](std::int32_t j) { candidates[slot++] = {i, j}; });
    std::sort(candidates.begin() + offsets[i], candidates.begin() + offsets[i + 1],
              [](const Candidate& a, const Candidate& b) { return a.second < b.second; });
  }
  return candidates;
}

template <int Dim>
std::vector<Candidate> find_wall_candidates(const Particles<Dim>& particles, const Walls<Dim>& walls,
                                            double tolerance) {
  std::vector<Candidate> candidates;
  const auto n = static_cast<std::int32_t>(particles.size());
  for (std::int32_t i = 0; i < n; ++i) {
    for (WallId w = 0; w < walls.size(); ++w) {
      const auto q = closest_point(walls.def[w], particles.position[i]);
      if ((particles.position[i] - q.point).norm() - particles.radius[i] < tolerance) candidates.push_back({i, w});
    }
  }
  return candidates;
}

template std::vector<Candidate> find_pair_candidates(const Particles<2>&, const Periodic<2>&, double, int);
template std::vector<Candidate> find_pair_candidates(const Particles<3>&, const Periodic<3>&, double, int);
template std::vector<Candidate> find_wall_candidates(const Particles<2>&, const Walls<2>&, double);
template std::vector<Candidate> find_wall_candidates(const Particles<3>&, const Walls<3>&, double);

}  // namespace dem
