// What a case asks of the plate loading analyses (output.compression in
// idl/dem/case.proto; Miyata et al. 2002, 3.2-3.3), in the engine's terms:
// walls by id, stresses in Pa, the defaults filled in.
#pragma once

#include <optional>
#include <vector>

#include "dem/ids.h"

namespace dem::analysis {

// The distribution of the normalised contact force f = F/<F> on each plate
// (Figs. 35 and 37), pooled from `snapshots` contact snapshots at stresses
// of the loading plate spread evenly from stress_from to stress_to.
struct ForceDistributionSettings {
  double stress_from = 400e3;  // Pa (the seed's window, 400-600 kPa)
  double stress_to = 600e3;    // Pa
  int snapshots = 10;
  double bin_width = 0.25;  // width of the classes of f
  double tail_from = 1.0;   // the exponential tail is fitted above this f
};

struct CompressionSettings {
  WallId loading_plate = kInvalidId;
  WallId bottom_plate = kInvalidId;
  // The analyses start with this stage: the first that places the loading
  // plate on the sample, or the first stage.
  int loading_stage = 0;
  // The three states of the stress-settlement curve (3.2(3)): initial below
  // transition_stress, final from final_stress on.
  double transition_stress = 50e3;         // Pa
  double final_stress = 250e3;             // Pa
  std::vector<double> contacts_at_stress;  // Pa: plate contact snapshots (Fig. 34)
  std::optional<ForceDistributionSettings> force_distribution;
  // A fall of the loading plate's stress from a peak to the next trough by
  // more than this fraction of the peak is a stress drop (Fig. 26).
  double stress_drop_fraction = 0.02;
};

}  // namespace dem::analysis
