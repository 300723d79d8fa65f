// dem_run's side of the engine's health status (dem/health.h): the world
// assessed at a pace that costs about 1/100 of the run (an assessment and
// the copy of the state after it take some cycles' time: io/pacing.h), and
// every stage's end; a copy of the state kept after each healthy assessment, so
// an unhealthy run leaves its last good state as last_good.snapshot.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "dem/health.h"
#include "dem/io/pacing.h"
#include "dem/snapshot.h"
#include "dem/world.h"

namespace dem::run {

// An unhealthy run, after its last good state was written; main exits 1.
class RunFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <int Dim>
class RunHealth {
 public:
  explicit RunHealth(const BasicWorld<Dim>& world) : monitor_(world), last_good_(world.snapshot()) {}

  // The problem, if the world is unhealthy; assessed when due or `always`.
  std::optional<StepHealth> check(const BasicWorld<Dim>& world, bool always = false) {
    if (!always && !pacing_.due()) return std::nullopt;
    StepHealth health;
    pacing_.run([&] {
      health = monitor_.assess(world);
      if (health.ok() && !health.energy_suspect) last_good_ = world.snapshot();
    });
    if (health.ok()) return std::nullopt;
    return health;
  }

  // A blow-up's motion (HealthMonitorT::motion_suspect): a pass over the
  // particles, for every output row; check(world, true) then says what.
  bool suspect(const BasicWorld<Dim>& world) const { return monitor_.motion_suspect(world); }

  const WorldSnapshotT<Dim>& last_good() const { return last_good_; }

 private:
  HealthMonitorT<Dim> monitor_;
  WorldSnapshotT<Dim> last_good_;
  io::Pacing pacing_{100};
};

}  // namespace dem::run
