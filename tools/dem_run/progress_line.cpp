#include "progress_line.h"

#include <cstdio>
#include <string>

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
  last_shown_ = now;

  const AssemblyMeasures measures = world.assembly_measures();
  const double percent =
      stage.cycles > 0 ? 100.0 * static_cast<double>(stage_cycles) / static_cast<double>(stage.cycles) : 0.0;
  char line[256];
  std::snprintf(
      line, sizeof line, "stage %d/%d %s: cycle %llu of %llu (%.0f%%)  kinetic energy %.3g  out-of-balance %.3g",
      stage_index + 1, stage_count, stage.name.c_str(), static_cast<unsigned long long>(stage_cycles),
      static_cast<unsigned long long>(stage.cycles), percent, measures.kinetic_energy, measures.out_of_balance);
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
