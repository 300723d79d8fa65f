#include "cell_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dem {

namespace {

// floor(t) clamped to [0, last] - what truncating and clamping gives for
// every finite t - without converting a value the integer cannot hold: a
// position that blew up (NaN, infinite, beyond 2^63 cells) lands in a cell
// at the edge instead of being undefined behaviour, and the health check
// stops the run (dem/health.h).
std::int64_t clamped_cell(double t, std::int64_t last) {
  if (!(t >= 1.0)) return 0;  // below 1, or NaN
  if (!(t < static_cast<double>(last))) return last;
  return static_cast<std::int64_t>(t);
}

}  // namespace

template <int Dim>
typename CellGrid<Dim>::Cell CellGrid<Dim>::cell_of(const Vec<Dim>& x) const {
  Cell c;
  for (int d = 0; d < Dim; ++d) c[d] = clamped_cell((x[d] - origin[d]) / cell_size[d], counts[d] - 1);
  return c;
}

// More cells along one axis than this cannot be: the grid has at most about
// 4 per particle (below), and particle counts fit in 32 bits.
constexpr std::int64_t kMaxAxisCells = std::int64_t{1} << 40;

template <int Dim>
CellGrid<Dim> build_grid(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double range) {
  const std::size_t n = particles.size();
  CellGrid<Dim> grid;
  // Over the finite positions: one that blew up would make the extent NaN.
  Vec<Dim> lo = Vec<Dim>::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t i = 0; i < n; ++i) {
    if (!particles.position[i].allFinite()) continue;
    lo = lo.cwiseMin(particles.position[i]);
    hi = hi.cwiseMax(particles.position[i]);
  }
  if (!(lo.array() <= hi.array()).all()) lo = hi = Vec<Dim>::Zero();
  for (int d = 0; d < Dim; ++d) {
    grid.wraps[d] = periodic.repeats(d);
    if (grid.wraps[d]) {
      lo[d] = periodic.min[d];
      hi[d] = periodic.min[d] + periodic.length[d];
    }
  }
  double size = range;
  const Vec<Dim> extent = hi - lo;
  // A few particles flung far away must not blow the grid up: keep at most
  // about 4 cells per particle by growing the cells.
  const double max_cells = 4.0 * static_cast<double>(n) + 16.0;
  auto cell_count = [&] {
    double cells = 1.0;
    for (int d = 0; d < Dim; ++d) cells *= extent[d] / size + 1.0;
    return cells;
  };
  // Finite positions far apart can still overflow the extent to infinity:
  // the cells then grow to infinity too, and there is one.
  while (cell_count() > max_cells && std::isfinite(size)) size *= 2.0;
  grid.origin = lo;
  std::int64_t cells = 1;
  for (int d = 0; d < Dim; ++d) {
    if (grid.wraps[d]) {
      // A whole number of cells, each at least `size`, tiles the period.
      grid.counts[d] = std::max<std::int64_t>(1, clamped_cell(extent[d] / size, kMaxAxisCells));
      grid.cell_size[d] = extent[d] / static_cast<double>(grid.counts[d]);
    } else {
      grid.counts[d] = clamped_cell(extent[d] / size, kMaxAxisCells) + 1;
      grid.cell_size[d] = size;
    }
    cells *= grid.counts[d];
  }

  std::vector<std::int64_t> cell_of(n);
  grid.cell_start.assign(static_cast<std::size_t>(cells) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = grid.index(grid.cell_of(particles.position[i]));
    ++grid.cell_start[static_cast<std::size_t>(cell_of[i]) + 1];
  }
  for (std::int64_t c = 0; c < cells; ++c) grid.cell_start[c + 1] += grid.cell_start[c];
  grid.cell_particles.resize(n);
  std::vector<std::int32_t> cursor(grid.cell_start.begin(), grid.cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) grid.cell_particles[cursor[cell_of[i]]++] = static_cast<std::int32_t>(i);
  return grid;
}

template struct CellGrid<2>;
template struct CellGrid<3>;
template CellGrid<2> build_grid(const Particles<2>&, const Periodic<2>&, double);
template CellGrid<3> build_grid(const Particles<3>&, const Periodic<3>&, double);

}  // namespace dem
