#include "broad_phase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "cell_grid.h"
#include "parallel.h"

namespace dem {

namespace {

// The distinct neighbour coordinates of cell coordinate a along an axis of
// m cells (a itself included), ascending. Along a periodic axis they wrap
// around; with fewer than three cells there, some coincide and count once.
struct AxisNeighbours {
  std::array<std::int64_t, 3> at{};
  int count = 0;
};

AxisNeighbours axis_neighbours(std::int64_t a, std::int64_t m, bool wraps) {
  AxisNeighbours n;
  if (wraps && m < 3) {
    for (std::int64_t b = 0; b < m; ++b) n.at[n.count++] = b;
    return n;
  }
  if (wraps && a == m - 1) n.at[n.count++] = 0;  // the next cell, wrapped around
  if (a > 0) n.at[n.count++] = a - 1;
  n.at[n.count++] = a;
  if (a + 1 < m) n.at[n.count++] = a + 1;
  if (wraps && a == 0) n.at[n.count++] = m - 1;  // the cell before, wrapped around
  return n;
}

// The particles in the grid's cell order, so that a cell's candidates are
// read contiguously.
template <int Dim>
struct CellOrdered {
  std::vector<Vec<Dim>> position;
  std::vector<double> radius;
  std::vector<ParticleId> id;
};

// A range [begin, end) of cell-ordered particles to test against one
// particle; from_next: it starts just after that particle (its own cell).
struct Candidates {
  std::int32_t begin = 0, end = 0;
  bool from_next = false;
};

// Every pair of particles in one cell or in two neighbouring cells whose
// gap is below tolerance, each pair once, as keys (first: the lower id's
// slot), appended to `keys` in no particular order. Only cells after c in
// index order are searched: their neighbourhoods are symmetric, so every
// pair of neighbouring cells is visited from its lower one (a half shell).
template <int Dim>
void find_cell_pairs(const CellGrid<Dim>& grid, const CellOrdered<Dim>& ordered, const Periodic<Dim>& periodic,
                     const typename CellGrid<Dim>::Cell& home, std::int64_t c, double tolerance, bool prefilter,
                     std::vector<std::int32_t>& near, std::vector<ContactKey>& keys) {
  const std::int32_t home_begin = grid.cell_start[c];
  const std::int32_t home_end = grid.cell_start[c + 1];
  if (home_begin == home_end) return;

  // Along the first axis a cell's neighbours are consecutive cells: runs of
  // consecutive coordinates are one contiguous range of particles.
  const AxisNeighbours along = axis_neighbours(home[0], grid.counts[0], grid.wraps[0]);
  std::array<std::array<std::int64_t, 2>, 3> runs;  // [first, last] coordinates
  int run_count = 0;
  for (int k = 0; k < along.count; ++k) {
    if (run_count > 0 && runs[run_count - 1][1] + 1 == along.at[k]) {
      runs[run_count - 1][1] = along.at[k];
    } else {
      runs[run_count++] = {along.at[k], along.at[k]};
    }
  }

  // The rows of cells along the first axis around home: every combination
  // of the other axes' neighbour coordinates.
  std::array<AxisNeighbours, Dim> across;
  std::array<std::int64_t, Dim> stride;
  stride[0] = 1;
  for (int d = 1; d < Dim; ++d) {
    across[d] = axis_neighbours(home[d], grid.counts[d], grid.wraps[d]);
    stride[d] = stride[d - 1] * grid.counts[d - 1];
  }
  const std::int64_t home_row = c - home[0];
  constexpr int kRows = Dim == 2 ? 3 : 9;
  std::array<Candidates, 3 * kRows> ranges;
  int range_count = 0;
  std::array<int, Dim> pick{};
  for (bool more = true; more;) {
    std::int64_t row = 0;
    for (int d = 1; d < Dim; ++d) row += across[d].at[pick[d]] * stride[d];
    if (row >= home_row) {
      for (int k = 0; k < run_count; ++k) {
        const auto [lo, hi] = runs[k];
        const std::int32_t end = grid.cell_start[row + hi + 1];
        if (row > home_row || lo > home[0]) {
          ranges[range_count++] = {grid.cell_start[row + lo], end, false};
        } else if (hi >= home[0]) {
          ranges[range_count++] = {0, end, true};  // the rest of home's cell and the cells after it
        }
      }
    }
    more = false;
    for (int d = 1; d < Dim; ++d) {
      if (++pick[d] < across[d].count) {
        more = true;
        break;
      }
      pick[d] = 0;
    }
  }

  std::size_t most = 0;
  for (int k = 0; k < range_count; ++k) {
    most += static_cast<std::size_t>(ranges[k].end - (ranges[k].from_next ? home_begin : ranges[k].begin));
  }
  if (near.size() < most) near.resize(most);
  // Far apart for certain: the squared distance exceeds the squared reach
  // by far more than the exact test's round-off (below) can make up, so the
  // exact test would say no too.
  constexpr double kMargin = 1.0 + 1e-8;
  for (std::int32_t s = home_begin; s < home_end; ++s) {
    const Vec<Dim>& xs = ordered.position[s];
    const double rs = ordered.radius[s];
    // Every candidate is written down and kept only when it may be near,
    // without a branch: whether one is near follows no pattern.
    std::size_t count = 0;
    for (int k = 0; k < range_count; ++k) {
      const Candidates& range = ranges[k];
      for (std::int32_t t = range.from_next ? s + 1 : range.begin; t < range.end; ++t) {
        double distance2 = 0.0;
        for (int d = 0; d < Dim; ++d) {
          const double apart = nearest_image(ordered.position[t][d] - xs[d], periodic.length[d]);
          distance2 += apart * apart;
        }
        const double reach = rs + ordered.radius[t] + tolerance;
        near[count] = t;
        count += static_cast<std::size_t>(!prefilter || !(distance2 > reach * reach * kMargin));
      }
    }
    for (std::size_t k = 0; k < count; ++k) {
      const std::int32_t t = near[k];
      // The exact test, oriented from the lower id as the contact table's
      // rows are, so its round-off is the same whichever cell found the pair.
      const bool s_first = ordered.id[s] < ordered.id[t];
      const std::int32_t a = s_first ? s : t, b = s_first ? t : s;
      const double gap =
          periodic.separation(ordered.position[a], ordered.position[b]).norm() - ordered.radius[a] - ordered.radius[b];
      if (gap < tolerance) keys.push_back({grid.cell_particles[a], grid.cell_particles[b]});
    }
  }
}

}  // namespace

template <int Dim>
std::vector<ContactKey> find_pair_keys(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double tolerance,
                                       int threads) {
  const auto n = static_cast<std::int32_t>(particles.size());
  if (n < 2) return {};
  double max_radius = 0.0, min_radius = 0.0;
  for (double r : particles.radius) {
    max_radius = std::max(max_radius, r);
    min_radius = std::min(min_radius, r);
  }
  const CellGrid<Dim> grid = build_grid(particles, periodic, 2.0 * max_radius + tolerance);
  // The squared pre-filter's bound holds for gaps of non-negative radii and tolerance only.
  const bool prefilter = tolerance >= 0.0 && min_radius >= 0.0;

  CellOrdered<Dim> ordered;
  ordered.position.resize(n);
  ordered.radius.resize(n);
  ordered.id.resize(n);
  for (std::int32_t s = 0; s < n; ++s) {
    const Slot i = grid.cell_particles[s];
    ordered.position[s] = particles.position[i];
    ordered.radius[s] = particles.radius[i];
    ordered.id[s] = particles.id[i];
  }

  // One pass over fixed chunks of cells, each into its own list; the lists
  // are then sorted into the table's order, so the result does not depend
  // on the thread count.
  std::int64_t cells = 1;
  for (int d = 0; d < Dim; ++d) cells *= grid.counts[d];
  constexpr std::int64_t kChunkCells = 1024;
  const std::int64_t chunks = (cells + kChunkCells - 1) / kChunkCells;
  std::vector<std::vector<ContactKey>> found(static_cast<std::size_t>(chunks));
  DEM_PARALLEL_FOR(threads, n)
  for (std::int64_t chunk = 0; chunk < chunks; ++chunk) {
    const std::int64_t begin = chunk * kChunkCells, end = std::min(cells, begin + kChunkCells);
    typename CellGrid<Dim>::Cell cell;
    for (std::int64_t d = 0, rest = begin; d < Dim; ++d) {
      cell[d] = rest % grid.counts[d];
      rest /= grid.counts[d];
    }
    auto& chunk_keys = found[static_cast<std::size_t>(chunk)];
    std::vector<std::int32_t> near;  // scratch: one particle's candidates that may be near
    for (std::int64_t c = begin; c < end; ++c) {
      find_cell_pairs(grid, ordered, periodic, cell, c, tolerance, prefilter, near, chunk_keys);
      for (int d = 0; d < Dim && ++cell[d] == grid.counts[d]; ++d) cell[d] = 0;
    }
  }

  // Into the table's order: by first slot (a counting sort), then by second.
  std::vector<std::int64_t> offsets(static_cast<std::size_t>(n) + 1, 0);
  for (const auto& chunk_keys : found) {
    for (const ContactKey& key : chunk_keys) ++offsets[key.first + 1];
  }
  for (std::int32_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
  std::vector<ContactKey> keys(static_cast<std::size_t>(offsets[n]));
  {
    std::vector<std::int64_t> cursor(offsets.begin(), offsets.end() - 1);
    for (const auto& chunk_keys : found) {
      for (const ContactKey& key : chunk_keys) keys[cursor[key.first]++] = key;
    }
  }
  DEM_PARALLEL_FOR(threads, n)
  for (std::int32_t i = 0; i < n; ++i) std::sort(keys.begin() + offsets[i], keys.begin() + offsets[i + 1]);
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
