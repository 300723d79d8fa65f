// A one-line progress report on a terminal, rewritten in place with a
// carriage return, so a long run shows it is alive without filling the
// scrollback: the stage, its cycles, the rate in cycles per second and the
// time left to the stage's end (to its cycle cap, "at most", when a stop
// condition may end it sooner). Disabled, it prints nothing.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "dem/programme.h"
#include "dem/world.h"

namespace dem::run {

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}

  // Redraws at most a few times a second: output intervals can be far
  // shorter than a terminal needs.
  template <int Dim>
  void show(int stage_index, int stage_count, const StageDefT<Dim>& stage, std::uint64_t stage_cycles,
            const BasicWorld<Dim>& world);

  // Blanks the line so the summary that follows starts clean.
  void clear();

 private:
  bool enabled_;
  std::size_t width_ = 0;  // of the line on screen, to blank it
  std::chrono::steady_clock::time_point last_shown_{};
  std::uint64_t last_cycle_ = 0;
  double rate_ = 0.0;  // cycles per second, averaged over the last few redraws
};

extern template void ProgressLine::show(int, int, const StageDef&, std::uint64_t, const World&);
extern template void ProgressLine::show(int, int, const StageDef3&, std::uint64_t, const World3&);

}  // namespace dem::run
