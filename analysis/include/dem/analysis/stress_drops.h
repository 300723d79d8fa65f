// Intermittent stress releases of the loading plate (Miyata et al. 2002,
// 3.2(3), Fig. 26: seen with circular particles, not with rectangular
// ones): falls of the stress from a peak to the next trough by more than a
// fraction of the peak.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "dem/analysis/loading_states.h"

namespace dem::analysis {

struct StressDrop {
  std::uint64_t peak_cycle = 0;
  std::uint64_t trough_cycle = 0;
  double peak_settlement = 0.0;                 // m
  double peak_stress = 0.0;                     // Pa
  double trough_stress = 0.0;                   // Pa
  LoadingState state = LoadingState::kInitial;  // at the peak
  double relative() const { return peak_stress > 0.0 ? (peak_stress - trough_stress) / peak_stress : 0.0; }
};

// A zig-zag over the samples with the reversal threshold `fraction` of the
// peak: the stress turns from rising to falling once it lies that far below
// its running peak, and back once it lies that far (of the same peak) above
// its running trough; each fall is one drop, from the peak to the trough.
// So a release interrupted by a small recovery counts once, and wiggles
// smaller than the threshold never count. Each drop is labelled with the
// state of its peak: the seed's releases are those of the final state,
// while before the plate rests on several particles its stress jumps as
// single contacts come and go.
std::vector<StressDrop> find_stress_drops(std::span<const CompressionSample> samples, double fraction,
                                          const StateCycles& cycles);

}  // namespace dem::analysis
