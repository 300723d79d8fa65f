#include "progress_line.h"

#include <cstdio>
#include <string>

#include "dem/cli/duration.h"
#include "run_summary.h"

namespace dem::run {
namespace {

constexpr auto kRedrawInterval = std::chrono::milliseconds(200);

}  // namespace

template <int Dim>
void ProgressLine::show(int stage_index, int stage_count, const StageDefT<Dim>& stage, std::uint64_t stage_cycles,
                        const BasicWorld<Dim>& world) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_shown_ < kRedrawInterval) return;
  const std::uint64_t cycle = world.cycle_count();
  if (last_shown_ != std::chrono::steady_clock::time_point{} && cycle >= last_cycle_) {
    const double seconds = std::chrono::duration<double>(now - last_shown_).count();
    const double rate = static_cast<double>(cycle - last_cycle_) / seconds;
    // A few redraws' worth of memory: steady enough to read, quick to follow a change of pace.
    rate_ = rate_ > 0.0 ? 0.7 * rate_ + 0.3 * rate : rate;
  }
  last_shown_ = now;
  last_cycle_ = cycle;

  const AssemblyMeasures measures = world.assembly_measures();
  const double percent =
      stage.cycles > 0 ? 100.0 * static_cast<double>(stage_cycles) / static_cast<double>(stage.cycles) : 0.0;
  std::string pace;
  if (rate_ > 0.0) {
    char text[96];
    const double left = static_cast<double>(stage.cycles > stage_cycles ? stage.cycles - stage_cycles : 0) / rate_;
    std::snprintf(text, sizeof text, "  %.0f cycles/s, %s%s left", rate_,
                  has_stop_condition(stage.until) ? "at most " : "", cli::duration_text(left).c_str());
    pace = text;
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "stage %d/%d %s: cycle %llu of %llu (%.0f%%)%s  kinetic energy %.3g  out-of-balance %.3g",
                stage_index + 1, stage_count, stage.name.c_str(), static_cast<unsigned long long>(stage_cycles),
                static_cast<unsigned long long>(stage.cycles), percent, pace.c_str(), measures.kinetic_energy,
                measures.out_of_balance);
  const std::string text = line;
  // Pad over the previous, possibly longer, line.
  std::fprintf(stderr, "\r%s%*s", text.c_str(), static_cast<int>(width_ > text.size() ? width_ - text.size() : 0), "");
  std::fflush(stderr);
  width_ = text.size();
}

template void ProgressLine::show(int, int, const StageDef&, std::uint64_t, const World&);
template void ProgressLine::show(int, int, const StageDef3&, std::uint64_t, const World3&);

void ProgressLine::clear() {
  if (!enabled_ || width_ == 0) return;
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(width_), "");
  std::fflush(stderr);
  width_ = 0;
}

}  // namespace dem::run
