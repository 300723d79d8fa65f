// When telemetry is due: every N cycles and/or every T seconds of
// simulated time, counted from the last publication.
#pragma once

#include <cstdint>
#include <limits>

namespace dem::service {

class TelemetrySchedule {
 public:
  TelemetrySchedule(std::uint64_t every_cycles, double every_seconds)
      : every_cycles_(every_cycles), every_seconds_(every_seconds) {}

  // Telemetry was just published at this point; the next is counted from here.
  void published(std::uint64_t cycle, double time) {
    last_cycle_ = cycle;
    last_time_ = time;
  }
  bool due(std::uint64_t cycle, double time) const;
  // How many cycles can run before telemetry is due (at least 1; the
  // largest value when the schedule is off).
  std::uint64_t cycles_until_due(std::uint64_t cycle, double time, double time_step) const;

 private:
  std::uint64_t every_cycles_;
  double every_seconds_;
  std::uint64_t last_cycle_ = 0;
  double last_time_ = 0.0;
};

}  // namespace dem::service
