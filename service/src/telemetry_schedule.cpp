#include "dem/service/telemetry_schedule.h"

#include <algorithm>
#include <cmath>

namespace dem::service {

namespace {
// Simulated time accumulates a step at a time; a relative slack keeps a
// time that is due up to rounding from slipping a cycle.
constexpr double kSlack = 1e-9;
}  // namespace

bool TelemetrySchedule::due(std::uint64_t cycle, double time) const {
  if (every_cycles_ > 0 && cycle - last_cycle_ >= every_cycles_) return true;
  return every_seconds_ > 0.0 && time - last_time_ >= every_seconds_ * (1.0 - kSlack);
}

std::uint64_t TelemetrySchedule::cycles_until_due(std::uint64_t cycle, double time, double time_step) const {
  std::uint64_t cycles = std::numeric_limits<std::uint64_t>::max();
  if (every_cycles_ > 0)
    cycles = std::min(cycles, last_cycle_ + every_cycles_ - std::min(cycle, last_cycle_ + every_cycles_));
  if (every_seconds_ > 0.0 && time_step > 0.0) {
    const double left = (last_time_ + every_seconds_ * (1.0 - kSlack) - time) / time_step;
    cycles = std::min(cycles, left <= 0.0 ? 0 : static_cast<std::uint64_t>(std::ceil(left)));
  }
  return std::max<std::uint64_t>(cycles, 1);
}

}  // namespace dem::service
