// What the rows of one force pass read: the particles, walls and periodic
// cell, the contact parameters, the step, and what the pass works out once
// for all its rows.
#pragma once

#include <cstdint>

#include "contact_params.h"
#include "ellipsoid.h"
#include "parameter_sets.h"
#include "particles.h"
#include "periodic.h"
#include "walls.h"

namespace dem {

// What the rows of one pass read.
template <int Dim>
struct PassInputs {
  const Particles<Dim>& particles;
  const Walls<Dim>& walls;
  const Periodic<Dim>& periodic;
  const ContactParamTable& params;
  // The distinct sets the rows of the pair table and of the wall table
  // resolve to (parameter_sets.h), for the batched passes; null in the
  // row-by-row passes, whose rows look theirs up in the table.
  const RowSets* pair_sets;
  const RowSets* wall_sets;
  double dt;
  std::uint64_t cycle;
  double near_margin;  // the gap within which a pair row counts as near (contact_blocks.h)
  // Ellipsoid worlds: each body's matrices for this pass, by slot.
  const EllipsoidFrame* ellipsoid_frames = nullptr;

  const ContactParams& pair_params(std::int32_t a, std::int32_t b) const { return params(a, b); }
};

}  // namespace dem
