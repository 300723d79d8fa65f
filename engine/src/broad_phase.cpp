#include "broad_phase.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "parallel.h"

namespace dem {

namespace {

struct CellGrid {
  Vec2 origin;
  double cell_size = 1.0;
  std::int64_t columns = 1, rows = 1;
  std::vector<std::int32_t> cell_start;  // CSR: particles of cell c are cell_particles[start[c]..start[c+1])
  std::vector<std::int32_t> cell_particles;

  std::int64_t column_of(double x) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((x - origin.x()) / cell_size), 0, columns - 1);
  }
  std::int64_t row_of(double y) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>((y - origin.y()) / cell_size), 0, rows - 1);
  }
};

CellGrid build_grid(const Particles& particles, double tolerance) {
  const std::size_t n = particles.size();
  CellGrid grid;
  Vec2 lo = particles.position[0], hi = particles.position[0];
  double max_radius = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(particles.position[i]);
    hi = hi.cwiseMax(particles.position[i]);
    max_radius = std::max(max_radius, particles.radius[i]);
  }
  // Any touching-or-near pair lies in neighbouring cells.
  grid.cell_size = 2.0 * max_radius + tolerance;
  const Vec2 extent = hi - lo;
  // A few particles flung far away must not blow the grid up: keep at most
  // about 4 cells per particle by growing the cells.
  const double max_cells = 4.0 * static_cast<double>(n) + 16.0;
  while ((extent.x() / grid.cell_size + 1.0) * (extent.y() / grid.cell_size + 1.0) > max_cells) {
    grid.cell_size *= 2.0;
  }
  grid.origin = lo;
  grid.columns = static_cast<std::int64_t>(extent.x() / grid.cell_size) + 1;
  grid.rows = static_cast<std::int64_t>(extent.y() / grid.cell_size) + 1;

  const std::int64_t cells = grid.columns * grid.rows;
  std::vector<std::int32_t> cell_of(n);
  grid.cell_start.assign(cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& x = particles.position[i];
    cell_of[i] = static_cast<std::int32_t>(grid.row_of(x.y()) * grid.columns + grid.column_of(x.x()));
    ++grid.cell_start[cell_of[i] + 1];
  }
  for (std::int64_t c = 0; c < cells; ++c) grid.cell_start[c + 1] += grid.cell_start[c];
  grid.cell_particles.resize(n);
  std::vector<std::int32_t> cursor(grid.cell_start.begin(), grid.cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) grid.cell_particles[cursor[cell_of[i]]++] = static_cast<std::int32_t>(i);
  return grid;
}

// Calls visit(j) for every j > i in the 3x3 cells around particle i whose gap is below tolerance.
template <typename Visit>
void for_each_near(const CellGrid& grid, const Particles& particles, std::int32_t i, double tolerance,
                   Visit visit) {
  const Vec2& xi = particles.position[i];
  const std::int64_t ci = grid.column_of(xi.x()), ri = grid.row_of(xi.y());
  for (std::int64_t r = std::max<std::int64_t>(ri - 1, 0); r <= std::min(ri + 1, grid.rows - 1); ++r) {
    for (std::int64_t c = std::max<std::int64_t>(ci - 1, 0); c <= std::min(ci + 1, grid.columns - 1); ++c) {
      const std::int64_t cell = r * grid.columns + c;
      for (std::int32_t k = grid.cell_start[cell]; k < grid.cell_start[cell + 1]; ++k) {
        const std::int32_t j = grid.cell_particles[k];
        if (j <= i) continue;
        const double gap = (particles.position[j] - xi).norm() - particles.radius[i] - particles.radius[j];
        if (gap < tolerance) visit(j);
      }
    }
  }
}

}  // namespace

std::vector<Candidate> find_pair_candidates(const Particles& particles, double tolerance, int threads) {
  const auto n = static_cast<std::int32_t>(particles.size());
  if (n < 2) return {};
  const CellGrid grid = build_grid(particles, tolerance);

  // Two passes (count, then fill) give every particle a fixed slot range, so
  // the list is identical for any thread count.
  std::vector<std::int32_t> offsets(n + 1, 0);
  DEM_PARALLEL_FOR(threads, n)
  for (std::int32_t i = 0; i < n; ++i) {
    std::int32_t count = 0;
    for_each_near(grid, particles, i, tolerance, [&](std::int32_t) { ++count; });
    offsets[i + 1] = count;
  }
  for (std::int32_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
  std::vector<Candidate> candidates(offsets[n]);
  DEM_PARALLEL_FOR(threads, n)
  for (std::int32_t i = 0; i < n; ++i) {
    std::int32_t slot = offsets[i];
    for_each_near(grid, particles, i, tolerance, [&](std::int32_t j) { candidates[slot++] = {i, j}; });
    std::sort(candidates.begin() + offsets[i], candidates.begin() + offsets[i + 1],
              [](const Candidate& a, const Candidate& b) { return a.second < b.second; });
  }
  return candidates;
}

std::vector<Candidate> find_wall_candidates(const Particles& particles, const Walls& walls, double tolerance) {
  std::vector<Candidate> candidates;
  const auto n = static_cast<std::int32_t>(particles.size());
  for (std::int32_t i = 0; i < n; ++i) {
    for (WallId w = 0; w < walls.size(); ++w) {
      const SegmentPoint q = closest_point(walls.def[w], particles.position[i]);
      if ((particles.position[i] - q.point).norm() - particles.radius[i] < tolerance) candidates.push_back({i, w});
    }
  }
  return candidates;
}

}  // namespace dem
