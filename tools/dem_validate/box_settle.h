// Box settle: spheres settle under gravity in a 3D box of five rectangular
// walls until at rest (cases/validation/box_settle.case.txtpb). The side
// walls are frictionless, so the floor must carry the whole weight, and the
// energy budget must close: what gravity put in is held or was dissipated.
#pragma once

#include <filesystem>

#include "dem/measures.h"

namespace dem::validation {

struct BoxSettleResult {
  int particles = 0;
  std::uint64_t cycles = 0;
  bool at_rest = false;              // the case's stop condition was met
  double weight = 0.0;               // N
  double floor_force = 0.0;          // N, vertical force of the particles on the floor
  double side_walls_vertical = 0.0;  // N, what the side walls carry vertically
  EnergyBudget energy;
};

// Runs the case (a 3D case whose first wall is the floor, normal +z).
BoxSettleResult box_settle(const std::filesystem::path& case_file);

}  // namespace dem::validation
