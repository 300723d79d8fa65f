// The cycle or run_until command the engine thread is working through:
// how far it has got, and (run_until) the conditions that end it early.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "dem/service/command_queue.h"
#include "dem/service/world_session.h"

namespace dem::service {

// What a cycle or run_until command asks for.
struct RunGoal {
  std::uint64_t max_cycles = 0;
  std::optional<WallId> wall;            // the plate for stress and settlement
  std::optional<double> stress;          // Pa: reached from the side it starts on
  std::optional<double> settlement;      // m: likewise
  std::optional<double> kinetic_energy;  // J: stop below
  std::uint64_t check_interval = 1;      // cycles between checks
};

class ActiveRun {
 public:
  // Records where stress and settlement start, which fixes the direction
  // from which their targets are "reached".
  ActiveRun(ReceivedCommand command, RunGoal goal, const WorldSession& world);

  const ReceivedCommand& command() const { return command_; }
  std::uint64_t done() const { return done_; }
  std::uint64_t total() const { return goal_.max_cycles; }
  bool condition_met() const { return condition_met_; }
  const std::string& condition() const { return condition_; }  // which condition held

  // Cycles to run before the next check of the conditions or the end.
  std::uint64_t cycles_to_next_stop() const;
  // Counts cycles just run; at a check point, tests the conditions. True
  // when the command is complete (its cycles are done or a condition holds).
  bool advance(std::uint64_t cycles, const WorldSession& world);

 private:
  bool check(const WorldSession& world);

  ReceivedCommand command_;
  RunGoal goal_;
  std::uint64_t done_ = 0;
  bool stress_rising_ = true;
  bool settlement_rising_ = true;
  bool condition_met_ = false;
  std::string condition_;
};

}  // namespace dem::service
