// The CSV tables of one run: the time series (walls, assembly, probes, the
// measures of the case's regions, the controlled box) as the
// run goes, and the contact and particle snapshots at its end, with the
// columns of the run's dimension; and the plate loading analyses when the
// case asks for them (output.compression); and the ParaView files every
// output.vtk_interval cycles (io/vtk_series.h) and at the end.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "dem/analysis/compression_analysis.h"
#include "dem/io/case_definition.h"
#include "dem/io/checkpoint_store.h"
#include "dem/io/compression_csv.h"
#include "dem/io/csv_writers.h"
#include "dem/io/regions_csv.h"
#include "dem/io/vtk_series.h"
#include "dem/world.h"

namespace dem::run {

template <int Dim>
class RunRecorder {
 public:
  // Creates the directory and the time-series files (probes.csv only when
  // the case has probes; the compression files only when it asks for them).
  // `resume`: a checkpoint's; the tables are cut back to it and appended
  // to, the analyses carry on from its state. `stiffness_varies`: some
  // contact law's stiffness depends on the overlap (the Hertz laws), so
  // Randall's running time-step check applies (run_recorder.cpp).
  RunRecorder(const std::filesystem::path& directory, const io::OutputSettings& output, const BasicWorld<Dim>& world,
              bool stiffness_varies, const io::ResumePoint* resume = nullptr);

  // The tables' lengths (their rows flushed) and the analyses' state, for a checkpoint.
  void fill(io::ResumePoint& point);

  // Writes a row for the world's current cycle unless one was written
  // already, so a stage's last cycle and the next stage's first are one
  // row; `stage` is the index of the stage running.
  void record(const BasicWorld<Dim>& world, int stage);

  // Writes contacts.csv (unless the case turned it off), particles.csv,
  // the compression summaries and the last ParaView step.
  void finish(const BasicWorld<Dim>& world);

  // Every file written so far, for the summary.
  const std::vector<std::filesystem::path>& files() const { return files_; }

 private:
  std::filesystem::path directory_;
  bool contacts_file_;
  io::WallsCsvT<Dim> walls_;
  io::AssemblyCsv assembly_;
  std::optional<io::ProbesCsv> probes_;
  std::optional<io::RegionsCsvT<Dim>> regions_;  // when the case names regions
  std::optional<io::BoxCsvT<Dim>> box_;          // from the first row with a box control
  std::optional<analysis::CompressionAnalysisT<Dim>> compression_;
  std::optional<io::CompressionCsvT<Dim>> compression_csv_;
  std::optional<io::VtkSeries> vtk_;
  std::optional<std::uint64_t> last_cycle_;
  std::vector<std::filesystem::path> files_;
  // Randall's time-step check, over consecutive rows (run_recorder.cpp says why).
  bool check_time_step_;
  static constexpr std::uint64_t kSustainedCycles = 100;
  int rows_above_ = 0;
  std::uint64_t first_above_ = 0;
  double largest_ratio_ = 0.0;
  bool warned_time_step_ = false;
};

extern template class RunRecorder<2>;
extern template class RunRecorder<3>;

}  // namespace dem::run
