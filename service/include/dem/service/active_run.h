// The cycle or run_until command the engine thread is working through: a
// one-stage programme of the engine's (WorldSession::begin_run, StageRunT)
// that the runner steps chunk by chunk, answering the commands that arrive
// between chunks in its own loop.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "dem/programme.h"
#include "dem/service/command_queue.h"
#include "dem/service/world_session.h"

namespace dem::service {

// What a cycle or run_until command asks for: `max_cycles`, ended early
// by the engine's stop rule (StopConditions, dem/programme.h) - every
// condition set holds at once, stress and settlement reached from below,
// the kinetic energy from above - checked every until.check_interval
// cycles. A cycle command sets none.
struct RunGoal {
  std::uint64_t max_cycles = 0;
  StopConditions until;
};

class ActiveRun {
 public:
  // Begins the one-stage programme on `world`, which must outlive the run.
  ActiveRun(ReceivedCommand command, const RunGoal& goal, WorldSession& world);

  const ReceivedCommand& command() const { return command_; }
  std::uint64_t done() const { return stepper_->result().cycles_run; }
  std::uint64_t total() const { return total_; }
  bool condition_met() const { return stepper_->result().condition_met; }
  const std::string& condition() const { return condition_; }  // what held, said with the values reached

  // Cycles to run before the next check of the conditions or the end.
  std::uint64_t cycles_to_next_stop() const { return stepper_->cycles_to_next_stop(); }
  // Runs `cycles` (at most cycles_to_next_stop()) and, at a check point,
  // tests the conditions. True when the command is complete (its cycles
  // are done or the conditions hold). Throws what the engine throws.
  bool step(std::uint64_t cycles, const WorldSession& world);

 private:
  void describe(const WorldSession& world);

  ReceivedCommand command_;
  StopConditions until_;
  std::uint64_t total_;
  std::unique_ptr<StageStepper> stepper_;
  std::string condition_;
};

}  // namespace dem::service
