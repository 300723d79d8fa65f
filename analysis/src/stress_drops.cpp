#include "dem/analysis/stress_drops.h"

namespace dem::analysis {

std::vector<StressDrop> find_stress_drops(std::span<const CompressionSample> samples, double fraction,
                                          const StateCycles& cycles) {
  std::vector<StressDrop> drops;
  if (samples.empty()) return drops;
  bool falling = false;
  const CompressionSample* peak = &samples.front();
  const CompressionSample* trough = &samples.front();
  const auto record = [&] {
    drops.push_back(
        {peak->cycle, trough->cycle, peak->settlement, peak->stress, trough->stress, state_at(peak->cycle, cycles)});
  };
  for (const CompressionSample& s : samples) {
    if (!falling) {
      if (s.stress > peak->stress) {
        peak = &s;
      } else if (s.stress < peak->stress * (1.0 - fraction)) {
        falling = true;
        trough = &s;
      }
    } else if (s.stress < trough->stress) {
      trough = &s;
    } else if (s.stress > trough->stress + fraction * peak->stress) {
      record();
      falling = false;
      peak = &s;
    }
  }
  if (falling) record();
  return drops;
}

}  // namespace dem::analysis
