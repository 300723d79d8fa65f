// Where the time of the calculation cycle goes: wall-clock seconds spent in
// each phase of step(), accumulated since the world was built.
#pragma once

#include <cstdint>

namespace dem {

struct StepProfile {
  double find_contacts = 0.0;   // broad phase and contact-table rebuilds, s
  double contact_forces = 0.0;  // force-displacement law at every contact and the force sums, s
  double motion = 0.0;          // law of motion, s
  double walls = 0.0;           // wall motion, s
  std::uint64_t cycles = 0;
  std::uint64_t contact_rebuilds = 0;
  // The contact table at the last rebuild: rows (pairs within the
  // tolerance) and the rows whose force pass crosses particle blocks.
  std::uint64_t pair_rows = 0;
  std::uint64_t wall_rows = 0;
  std::uint64_t crossing_rows = 0;
  // Sortings of the near rows (contact_blocks.h) and how many rows the
  // last one kept.
  std::uint64_t near_sortings = 0;
  std::uint64_t near_rows = 0;
};

}  // namespace dem
