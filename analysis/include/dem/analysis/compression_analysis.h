// The plate loading analyses of a run (output.compression; Miyata et al.
// 2002, 3.2-3.3), gathered as it goes and summed up at its end, with no
// files: dem_run writes them (compression_csv.h), the validation checks
// them, and the service can publish them. From the loading stage on, each
// call to add() keeps a sample of the plates and takes the plates' contact
// snapshots whose stress the loading plate has just reached.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "dem/analysis/compression_settings.h"
#include "dem/analysis/force_distribution.h"
#include "dem/analysis/loading_states.h"
#include "dem/analysis/plate_contacts.h"
#include "dem/analysis/stress_drops.h"
#include "dem/world.h"

namespace dem::analysis {

// The contacts on both plates when the loading plate's stress first reached
// a target (Fig. 34; the force distribution's snapshots too).
template <int Dim>
struct PlateSnapshotT {
  int index = 0;                  // in the order taken
  double target_stress = 0.0;     // Pa
  bool for_distribution = false;  // one of the force distribution's snapshots
  // One of contacts_at_stress, or the loading's start (target 0, taken
  // with them): the whole assembly is written at this moment too (Figs.
  // 27-28), by whoever writes the snapshot (io::record_compression); the
  // analysis keeps only the plates' contacts.
  bool for_contacts = false;
  CompressionSample sample;  // the plates when it was taken
  std::vector<PlateContactT<Dim>> loading;
  std::vector<PlateContactT<Dim>> bottom;
};

// f = F/<F> on one plate, pooled over the force distribution's snapshots
// (each normalised by its own mean). The tail's standard error counts the
// contacts of one snapshot, not of all: the snapshots share most contacts.
struct PlateForceDistribution {
  int snapshots = 0;
  int contacts = 0;
  double mean_force = 0.0;  // N, over every pooled contact
  std::vector<double> f;
  std::vector<ForceClass> classes;
  TailFit tail;
};

struct CompressionResults {
  StateCycles state_cycles;
  std::array<StateFit, 3> states;
  std::vector<StressDrop> drops;
  // The loading plate's, then the bottom plate's; when asked for.
  std::optional<std::array<PlateForceDistribution, 2>> force_distribution;
  // At the end of the run, the loading plate's then the bottom plate's: the
  // contacts grouped by the state they formed in, and (Fig. 30 as the seed
  // defines it) by the order they formed in, 40/30/30 %.
  std::array<std::array<StateLoad, 3>, 2> load_by_state;
  std::array<std::array<StateLoad, 3>, 2> load_by_formation;
  CompressionSample last;  // the plates at the end of the run
};

// Everything an analysis has gathered, which a checkpoint keeps (io turns
// it into text: dem/io/compression_state.h); the next target follows from
// how many snapshots there are, one per target reached.
template <int Dim>
struct CompressionStateT {
  std::vector<CompressionSample> samples;
  std::vector<PlateSnapshotT<Dim>> snapshots;
};

template <int Dim>
class CompressionAnalysisT {
 public:
  explicit CompressionAnalysisT(const CompressionSettings& settings);

  // Samples the plates once per cycle (a second call at the same cycle does
  // nothing), from the loading stage on; returns the snapshots taken now.
  // With contacts_at_stress, the first sample of the loading is a snapshot
  // too: the unloaded state (target 0) the sample starts from (Fig. 28).
  std::vector<const PlateSnapshotT<Dim>*> add(const BasicWorld<Dim>& world, int stage);

  // The summary of the loading so far, with the world's contacts as they are now.
  CompressionResults results(const BasicWorld<Dim>& world) const;

  const CompressionSettings& settings() const { return settings_; }

  // Everything gathered so far, for a checkpoint; restore() makes a fresh
  // analysis of the same settings carry on from it, and throws
  // std::runtime_error for a state with more snapshots than its targets.
  CompressionStateT<Dim> state() const { return {samples_, snapshots_}; }
  void restore(CompressionStateT<Dim> state);
  const std::vector<CompressionSample>& samples() const { return samples_; }
  const std::vector<PlateSnapshotT<Dim>>& snapshots() const { return snapshots_; }

 private:
  struct Target {
    double stress = 0.0;
    bool for_distribution = false;
    bool for_contacts = false;
  };

  PlateForceDistribution distribution(bool loading_plate) const;

  CompressionSettings settings_;
  std::vector<Target> targets_;  // in order of stress
  std::size_t next_target_ = 0;
  std::vector<CompressionSample> samples_;
  std::vector<PlateSnapshotT<Dim>> snapshots_;
};

using CompressionAnalysis = CompressionAnalysisT<2>;
using CompressionAnalysis3 = CompressionAnalysisT<3>;

extern template class CompressionAnalysisT<2>;
extern template class CompressionAnalysisT<3>;

}  // namespace dem::analysis
