#include "dem/service/health_watch.h"

namespace dem::service {

HealthWatch::HealthWatch(const WorldSession& world) : last_good_(world) {}

std::optional<StepHealth> HealthWatch::check(WorldSession& world, bool always) {
  if (!always && !pacing_.due()) return std::nullopt;
  StepHealth health;
  pacing_.run([&] {
    health = world.assess_health();
    if (health.ok() && !health.energy_suspect) last_good_ = StateCheckpoint(world);
  });
  if (health.ok()) return std::nullopt;
  return health;
}

}  // namespace dem::service
