// Where the time of the calculation cycle goes: wall-clock seconds spent in
// each phase of step(), accumulated since the world was built.
#pragma once

#include <cstdint>

namespace dem {

struct StepProfile {
  double find_contacts = 0.0;   // broad phase and contact-table rebuilds, s
  double contact_forces = 0.0;  // force-displacement law at every contact, s
  double force_sums = 0.0;      // per-particle and per-wall gathers, s
  double motion = 0.0;          // law of motion, s
  double walls = 0.0;           // wall motion, s
  std::uint64_t cycles = 0;
  std::uint64_t contact_rebuilds = 0;
};

}  // namespace dem
