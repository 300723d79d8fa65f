// Work done now and then during a run (assessing its health, copying its
// state) at a pace that bounds its cost: after a piece of work that took
// t, the next is due no sooner than spacing * t later, so it takes at most
// about 1/spacing of the run's time whatever the world's size.
#pragma once

#include <chrono>

namespace dem::io {

class Pacing {
 public:
  using Clock = std::chrono::steady_clock;

  explicit Pacing(int spacing = 20) : spacing_(spacing) {}

  bool due(Clock::time_point now = Clock::now()) const { return now >= next_; }

  // Runs `work` and schedules the next.
  template <typename Work>
  void run(Work&& work) {
    const auto start = Clock::now();
    work();
    const auto end = Clock::now();
    next_ = end + spacing_ * (end - start);
  }

 private:
  int spacing_;
  Clock::time_point next_{};
};

}  // namespace dem::io
