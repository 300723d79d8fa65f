// The engine's health status (dem/health.h) as the server acts on it, the
// same for a cycle or run_until command, a run_programme command and the
// one-shot mode: the world assessed at a pace that costs about 1/100 of
// the run (and whenever asked), its state copied after a healthy
// assessment, so an unhealthy run can be stopped with the last good state
// kept (docs/RELIABILITY.md).
#pragma once

#include <optional>

#include "dem/health.h"
#include "dem/io/pacing.h"
#include "dem/service/world_session.h"
#include "dem/service/world_snapshots.h"

namespace dem::service {

class HealthWatch {
 public:
  // Takes the world as it is now for the first good state.
  explicit HealthWatch(const WorldSession& world);

  // The problem, if the world is unhealthy; assessed when due or `always`.
  std::optional<StepHealth> check(WorldSession& world, bool always = false);

  const StateCheckpoint& last_good() const { return last_good_; }

 private:
  StateCheckpoint last_good_;
  io::Pacing pacing_{100};  // about 1/100 of the run, beside the StateCache refresh's 1/40
};

}  // namespace dem::service
