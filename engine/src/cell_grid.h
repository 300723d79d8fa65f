// A uniform grid of cells at least one interaction range wide over the
// particles (tiling periodic axes exactly): any pair closer than the range
// lies in neighbouring cells. The broad phase searches it; the particle
// order walks it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "particles.h"
#include "periodic.h"

namespace dem {

template <int Dim>
struct CellGrid {
  using Cell = std::array<std::int64_t, Dim>;
  Vec<Dim> origin = Vec<Dim>::Zero();
  Vec<Dim> cell_size = Vec<Dim>::Ones();  // along each axis; periodic axes are tiled exactly
  Cell counts{};                          // cells along each axis
  std::array<bool, Dim> wraps{};
  // CSR: the particles (slots) of cell c are cell_particles[cell_start[c] .. cell_start[c + 1]).
  std::vector<std::int32_t> cell_start;
  std::vector<std::int32_t> cell_particles;

  Cell cell_of(const Vec<Dim>& x) const;
  std::int64_t index(const Cell& c) const {
    std::int64_t i = 0;
    for (int d = Dim - 1; d >= 0; --d) i = i * counts[d] + c[d];
    return i;
  }
};

// Cells at least `range` wide (grown when a few particles far away would
// make too many), filled with every particle.
template <int Dim>
CellGrid<Dim> build_grid(const Particles<Dim>& particles, const Periodic<Dim>& periodic, double range);

}  // namespace dem
