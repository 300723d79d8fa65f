#include "dem/analysis/compression_analysis.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace dem::analysis {

template <int Dim>
CompressionAnalysisT<Dim>::CompressionAnalysisT(const CompressionSettings& settings) : settings_(settings) {
  for (double stress : settings_.contacts_at_stress) targets_.push_back({stress, false, true});
  // Miyata Fig. 28: rotations from "the initial unloaded state", the
  // loading's first sample (every stress is >= 0; contacts_at_stress > 0).
  if (!settings_.contacts_at_stress.empty()) targets_.push_back({0.0, false, true});
  if (const auto& d = settings_.force_distribution) {
    // Evenly spread from stress_from to stress_to, both included.
    for (int k = 0; k < d->snapshots; ++k) {
      const double stress = d->stress_from + (d->stress_to - d->stress_from) * k / (d->snapshots - 1);
      targets_.push_back({stress, true, false});
    }
  }
  std::stable_sort(targets_.begin(), targets_.end(),
                   [](const Target& a, const Target& b) { return a.stress < b.stress; });
  // A stress asked for twice is one snapshot serving both.
  std::vector<Target> merged;
  for (const Target& t : targets_) {
    if (!merged.empty() && merged.back().stress == t.stress) {
      merged.back().for_distribution = merged.back().for_distribution || t.for_distribution;
      merged.back().for_contacts = merged.back().for_contacts || t.for_contacts;
    } else {
      merged.push_back(t);
    }
  }
  targets_ = std::move(merged);
}

template <int Dim>
std::vector<const PlateSnapshotT<Dim>*> CompressionAnalysisT<Dim>::add(const BasicWorld<Dim>& world, int stage) {
  if (stage < settings_.loading_stage) return {};
  if (!samples_.empty() && samples_.back().cycle == world.cycle_count()) return {};
  const std::vector<WallMeasureT<Dim>> measures = world.wall_measures();
  const PlateReading loading = read_plate(world, measures, settings_.loading_plate);
  const PlateReading bottom = read_plate(world, measures, settings_.bottom_plate);
  CompressionSample sample;
  sample.stage = stage;
  sample.cycle = world.cycle_count();
  sample.time = world.time();
  sample.settlement = loading.settlement;
  sample.stress = loading.stress;
  sample.loading_contacts = loading.contacts;
  sample.bottom_stress = bottom.stress;
  sample.bottom_contacts = bottom.contacts;
  samples_.push_back(sample);

  const std::size_t first_new = snapshots_.size();
  std::vector<ContactRecordT<Dim>> contacts;
  for (; next_target_ < targets_.size() && sample.stress >= targets_[next_target_].stress; ++next_target_) {
    if (contacts.empty()) contacts = world.contacts();
    PlateSnapshotT<Dim> snapshot;
    snapshot.index = static_cast<int>(snapshots_.size());
    snapshot.target_stress = targets_[next_target_].stress;
    snapshot.for_distribution = targets_[next_target_].for_distribution;
    snapshot.for_contacts = targets_[next_target_].for_contacts;
    snapshot.sample = sample;
    snapshot.loading = plate_contacts<Dim>(contacts, settings_.loading_plate);
    snapshot.bottom = plate_contacts<Dim>(contacts, settings_.bottom_plate);
    snapshots_.push_back(std::move(snapshot));
  }
  std::vector<const PlateSnapshotT<Dim>*> taken;
  for (std::size_t k = first_new; k < snapshots_.size(); ++k) taken.push_back(&snapshots_[k]);
  return taken;
}

template <int Dim>
PlateForceDistribution CompressionAnalysisT<Dim>::distribution(bool loading_plate) const {
  const ForceDistributionSettings& d = *settings_.force_distribution;
  PlateForceDistribution result;
  double force_sum = 0.0;
  for (const PlateSnapshotT<Dim>& snapshot : snapshots_) {
    if (!snapshot.for_distribution) continue;
    const std::vector<double> forces = normal_forces<Dim>(loading_plate ? snapshot.loading : snapshot.bottom);
    // Miyata 3.3(2): each force over the mean force on the plate at that stress.
    const std::vector<double> f = normalised_forces(forces);
    result.snapshots += 1;
    result.f.insert(result.f.end(), f.begin(), f.end());
    force_sum += std::accumulate(forces.begin(), forces.end(), 0.0);
  }
  result.contacts = static_cast<int>(result.f.size());
  result.mean_force = result.contacts > 0 ? force_sum / result.contacts : 0.0;
  result.classes = force_classes(result.f, d.bin_width);
  result.tail = fit_exponential_tail(result.f, d.tail_from);
  // The snapshots of one window mostly share their contacts, whose forces
  // grow together: the independent forces are about one snapshot's, so the
  // standard error counts those.
  if (result.snapshots > 1) result.tail.decay_rate_error *= std::sqrt(static_cast<double>(result.snapshots));
  return result;
}

template <int Dim>
CompressionResults CompressionAnalysisT<Dim>::results(const BasicWorld<Dim>& world) const {
  CompressionResults r;
  r.state_cycles = state_cycles(samples_, settings_.transition_stress, settings_.final_stress);
  r.states = fit_states(samples_, r.state_cycles);
  r.drops = find_stress_drops(samples_, settings_.stress_drop_fraction, r.state_cycles);
  if (settings_.force_distribution) r.force_distribution = {distribution(true), distribution(false)};
  const std::vector<ContactRecordT<Dim>> contacts = world.contacts();
  const auto loading = plate_contacts<Dim>(contacts, settings_.loading_plate);
  const auto bottom = plate_contacts<Dim>(contacts, settings_.bottom_plate);
  r.load_by_state = {load_by_state<Dim>(loading, r.state_cycles), load_by_state<Dim>(bottom, r.state_cycles)};
  r.load_by_formation = {load_by_formation_order<Dim>(loading), load_by_formation_order<Dim>(bottom)};
  if (!samples_.empty()) r.last = samples_.back();
  return r;
}

template <int Dim>
void CompressionAnalysisT<Dim>::restore(CompressionStateT<Dim> state) {
  if (state.snapshots.size() > targets_.size())
    throw std::runtime_error("the plate loading analyses' state has more snapshots than targets");
  samples_ = std::move(state.samples);
  snapshots_ = std::move(state.snapshots);
  next_target_ = snapshots_.size();  // a snapshot per target reached, in order
  for (std::size_t k = 0; k < next_target_; ++k) snapshots_[k].for_contacts = targets_[k].for_contacts;
}

template class CompressionAnalysisT<2>;
template class CompressionAnalysisT<3>;

}  // namespace dem::analysis
