// The plate loading analyses as CSV files (output.compression; Miyata et
// al. 2002, 3.2-3.3), beside a run's other tables (csv_file.h for number
// formats; docs/CASES.md describes every column):
//
// As the loading goes:
//   compression.csv       stage,cycle,time,settlement,stress,loading_contacts,
//                         bottom_stress,bottom_contacts,contact_ratio
//                         one row per output interval from the loading stage
//                         on (Figs. 26, 29, 32, 33); stresses in Pa,
//                         settlement in m; contact_ratio = loading_contacts /
//                         bottom_contacts (0 while the bottom has none).
//   plate_contacts.csv    2D: snapshot,target_stress,cycle,stress,plate,
//                             particle,x,y,normal_force,shear_force,f,
//                             formed_cycle,formed_in,for_contacts,
//                             for_distribution
//                         3D: the same with z after y
//                         every contact on both plates at each snapshot
//                         stress (Fig. 34 and the force distribution's);
//                         f = normal_force over the plate's mean at that
//                         snapshot; formed_in the state the contact formed
//                         in; for_contacts (0/1) a snapshot of
//                         contacts_at_stress or the loading's start (target
//                         0), for_distribution one pooled into the force
//                         distribution.
//   particles_at_stress.csv  snapshot,target_stress,cycle,stress, then the
//                         columns of particles.csv (csv_writers.h)
//   contacts_at_stress.csv   snapshot,target_stress,cycle,stress, then the
//                         columns of contacts.csv
//                         the whole assembly at each for_contacts snapshot
//                         (Figs. 27-28: force chains, particle rotations).
// At the end:
//   compression_states.csv  state,first_cycle,samples,stress_from,stress_to,
//                         settlement_from,settlement_to,secant_stiffness,
//                         tangent_stiffness,r_squared,loading_contacts_from,
//                         loading_contacts_to,contact_rate
//   stress_drops.csv      state,peak_cycle,trough_cycle,peak_settlement,
//                         peak_stress,trough_stress,relative_drop
//   load_by_state.csv     plate,state,contacts,contact_share,load,
//                         load_share,first_formed_cycle,last_formed_cycle,
//                         stress: the contacts by the state they formed in
//   load_by_formation.csv plate,group,... the same columns: Fig. 30 as the
//                         seed defines it, the contacts in the order they
//                         formed, the first 40 % (initial), the next 30 %
//                         (transition), the last 30 % (final)
//   force_distribution.csv  plate,f_low,f_high,contacts,
//                         probability_density,load_share,load_density,
//                         q_model,mueth       (Figs. 35 and 37)
//   force_tail.csv        plate,snapshots,contacts,mean_force,tail_from,
//                         tail_contacts,decay_rate,decay_rate_error,
//                         excess_cv,q_model_decay_rate,mueth_decay_rate
// The last two only when the case asks for the force distribution.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dem/analysis/compression_analysis.h"
#include "dem/io/csv_file.h"

namespace dem::io {

// The seed's q-model (Miyata eq. 62) has N = 3 neighbours.
inline constexpr int kQModelNeighbours = 3;

template <int Dim>
class CompressionCsvT {
 public:
  // Creates compression.csv, plate_contacts.csv, particles_at_stress.csv and
  // contacts_at_stress.csv; the plates' names label the rows.
  // `resume`: see CsvFile.
  CompressionCsvT(const std::filesystem::path& directory, std::string loading_plate, std::string bottom_plate,
                  const TableSizes* resume = nullptr);

  void write_sample(const dem::analysis::CompressionSample& sample);
  // `cycles` as known when the snapshot was taken: enough for the contacts
  // formed by then.
  void write_snapshot(const dem::analysis::PlateSnapshotT<Dim>& snapshot, const dem::analysis::StateCycles& cycles);
  // Every particle and touching contact of `world`, which must be at the
  // snapshot's moment (a for_contacts snapshot just taken).
  void write_assembly(const dem::analysis::PlateSnapshotT<Dim>& snapshot, const BasicWorld<Dim>& world);
  // The summaries at the end of the run.
  void write_results(const dem::analysis::CompressionResults& results);

  // Every file written so far.
  const std::vector<std::filesystem::path>& files() const { return files_; }
  // The tables written as the run goes, for a checkpoint.
  std::vector<CsvFile*> tables() { return {&samples_, &contacts_, &particles_at_stress_, &contacts_at_stress_}; }

 private:
  void write_plate_rows(const dem::analysis::PlateSnapshotT<Dim>& snapshot, const std::string& plate,
                        const std::vector<dem::analysis::PlateContactT<Dim>>& contacts,
                        const dem::analysis::StateCycles& cycles);

  std::filesystem::path directory_;
  std::string loading_plate_;
  std::string bottom_plate_;
  CsvFile samples_;
  CsvFile contacts_;
  CsvFile particles_at_stress_;
  CsvFile contacts_at_stress_;
  std::vector<std::filesystem::path> files_;
};

// Samples the plates into the analysis and writes what it took now: the
// row of compression.csv and any snapshots, with the whole assembly for
// the for_contacts ones.
template <int Dim>
void record_compression(dem::analysis::CompressionAnalysisT<Dim>& analysis, CompressionCsvT<Dim>& csv,
                        const BasicWorld<Dim>& world, int stage);

using CompressionCsv = CompressionCsvT<2>;
using CompressionCsv3 = CompressionCsvT<3>;

extern template class CompressionCsvT<2>;
extern template class CompressionCsvT<3>;
extern template void record_compression(dem::analysis::CompressionAnalysisT<2>&, CompressionCsvT<2>&,
                                        const BasicWorld<2>&, int);
extern template void record_compression(dem::analysis::CompressionAnalysisT<3>&, CompressionCsvT<3>&,
                                        const BasicWorld<3>&, int);

}  // namespace dem::io
