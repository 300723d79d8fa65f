// What one step of the calculation cycle works with besides the state it
// changes: the step context (Box2D's b2StepContext). step() makes it once
// and hands it to each phase, so the phases agree on the time step, the
// cycle and the threads, and the inputs of the law of motion and of the
// force pass are made from it and the state in one place each. A plain
// value: a contact report makes one from a const state too.
#pragma once

#include <cstdint>

namespace dem {

struct StepContext {
  double dt = 0.0;             // s, the same for every phase of the step
  std::uint64_t cycle = 0;     // the cycle the step brings the world to (outside a step: the current one)
  int threads = 1;             // for the contact search, the force pass and the law of motion
  bool energy_budget = false;  // book the energy flows (it costs at every contact)
  bool keep_force = false;     // remember each |sum F| for the next step's check
  bool check_step = false;     // Randall's particle-wise check (4.35-4.40) on this step
};

}  // namespace dem
