#include "cell_grid.h"

#include <algorithm>

namespace dem {

template <int Dim>
typename CellGrid<Dim>::Cell CellGrid<Dim>::cell_of(const Vec<Dim>& x) const {
  Cell c;
  for (int d = 0; d < Dim; ++d) {
    c[d] = std::clamp<std::int64_t>(static_cast<std::int64_t>((x[d] - origin[d]) / cell_size[d]), 0, counts[d] - 1);
  }
  return c;
}

template <int Dim>
CellGrid<Dim> build_grid(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double range) {
  const std::size_t n = particles.size();
  CellGrid<Dim> grid;
  Vec<Dim> lo = particles.position[0], hi = particles.position[0];
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(particles.position[i]);
    hi = hi.cwiseMax(particles.position[i]);
  }
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
