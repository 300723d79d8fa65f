// The server's files in its output directory, per loaded case
// (<output>/<case>/): walls.csv and assembly.csv at the telemetry interval
// while it runs (the same tables as dem_run, io/csv_writers.h; a one-shot
// run writes them at the case's output interval), contacts.csv and
// particles.csv when the case is replaced or the server stops, and
// stages.csv, a row per stage of a programme (one-shot or run_programme);
// when the case asks for them (output.compression), the plate loading
// analyses of a programme, the same files as dem_run writes
// (io/compression_csv.h); the measures of the case's regions (regions.csv)
// and of its controlled box (box.csv) at every row (io/regions_csv.h);
// and while a programme runs, its ParaView files
// (io/vtk_series.h) every vtk_interval cycles - the case's
// output.vtk_interval unless the server was given one - and at its end.
// A file that
// cannot be written is logged and recording stops; the simulation goes on
// (a one-shot run then fails: failed()).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "dem/analysis/compression_analysis.h"
#include "dem/analysis/compression_settings.h"
#include "dem/io/case_definition.h"
#include "dem/io/checkpoint_store.h"
#include "dem/io/compression_csv.h"
#include "dem/io/csv_file.h"
#include "dem/io/csv_writers.h"
#include "dem/io/regions_csv.h"
#include "dem/io/vtk_series.h"
#include "dem/programme.h"
#include "dem/service/world_session.h"
#include "dem/world.h"

namespace dem::service {

class OutputRecorder {
 public:
  // `vtk_interval`, when set, replaces every case's output.vtk_interval.
  OutputRecorder(std::filesystem::path output_directory, bool enabled,
                 std::optional<std::uint64_t> vtk_interval = std::nullopt);

  // Before a load that starts its tables afresh (not a resume): the case's
  // directory may hold an earlier run's output, which start() would cut.
  // A directory this recorder started in is its own to start again; any
  // other holding files is refused (OutputInUse) unless `overwrite`, when
  // its contents go first (checkpoints included, so a later --resume never
  // mixes two runs).
  void claim(const std::string& case_name, bool overwrite);
  struct OutputInUse : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

  // After a load; `resume`: a checkpoint's, whose tables are cut back to
  // it and appended to, and whose analyses carry on (io/checkpoint_store.h).
  template <int Dim>
  void start(const std::string& case_name, const BasicWorld<Dim>& world,
             std::optional<dem::analysis::CompressionSettings> compression = std::nullopt,
             std::uint64_t vtk_interval = 0, const io::ResumePoint* resume = nullptr,
             const std::vector<io::MeasurementRegion>& regions = {});
  // The tables' lengths (rows flushed) and the analyses' state, for a checkpoint.
  void fill(io::ResumePoint& point);
  // A row of the time series, unless this cycle has one already (a load
  // and its first telemetry, a stage's end and the next stage's start);
  // with the stage of a programme running, a sample of the plate loading
  // analyses and the ParaView step when one is due too.
  template <int Dim>
  void record(const BasicWorld<Dim>& world, std::optional<std::size_t> stage = std::nullopt);
  // A stage of a one-shot run's programme has ended, at `cycle` and `time`.
  void record_stage(std::size_t stage, const std::string& name, const StageResult& result, std::uint64_t cycle,
                    double time);
  template <int Dim>
  void finish(const BasicWorld<Dim>& world);  // before a new load and at shutdown

  // The same for a session's world, whatever its dimension; `output`: the
  // case's output settings, of which the tables take the plate loading
  // analyses, the ParaView interval and the regions.
  void start(const std::string& case_name, const WorldSession& world, const io::OutputSettings& output,
             const io::ResumePoint* resume = nullptr) {
    on_world(world, [&](const auto& w) {
      start(case_name, w, output.compression, output.vtk_interval, resume, output.regions);
    });
  }
  void record(const WorldSession& world, std::optional<std::size_t> stage = std::nullopt) {
    on_world(world, [&](const auto& w) { record(w, stage); });
  }
  void finish(const WorldSession& world) {
    on_world(world, [&](const auto& w) { finish(w); });
  }

  // <output>/<case>/ of the case loaded last: its tables and a one-shot
  // run's final snapshot (also when the tables are off).
  const std::filesystem::path& case_directory() const { return directory_; }
  // A file of the server's own there (a snapshot beside the tables), or
  // FileAccessError when that directory leads out of the output directory
  // or holds a link (io::own_directory, checked by start(): the tables are
  // then not written either).
  std::filesystem::path own_file(std::string_view name) const;
  const std::optional<std::string>& directory_problem() const { return directory_problem_; }
  static std::filesystem::path case_directory_of(const std::filesystem::path& output, const std::string& case_name);
  // A table could not be written (the error was logged).
  bool failed() const { return failed_; }

 private:
  // The plate loading analyses and their files, made at the first sample.
  template <int Dim>
  struct Compression {
    dem::analysis::CompressionAnalysisT<Dim> analysis;
    io::CompressionCsvT<Dim> csv;
  };
  template <int Dim>
  std::unique_ptr<Compression<Dim>>& compression();
  template <int Dim>
  void make_compression(const BasicWorld<Dim>& world);

  // A row of regions.csv and box.csv when `write`; otherwise (a resume)
  // reopens those the checkpoint names.
  template <int Dim>
  void record_regions(const BasicWorld<Dim>& world, bool write);
  void fail(const std::exception& error);
  void close();

  std::filesystem::path output_directory_;
  bool enabled_;
  bool failed_ = false;
  std::filesystem::path directory_;
  std::set<std::filesystem::path> started_;  // the case directories start() wrote in
  std::optional<std::string> directory_problem_;
  std::unique_ptr<io::WallsCsvT<2>> walls2_;
  std::unique_ptr<io::WallsCsvT<3>> walls3_;
  std::unique_ptr<io::AssemblyCsv> assembly_;
  std::unique_ptr<io::CsvFile> stages_;
  std::optional<dem::analysis::CompressionSettings> compression_settings_;
  std::optional<std::uint64_t> vtk_override_;
  std::uint64_t vtk_interval_ = 0;
  std::unique_ptr<io::VtkSeries> vtk_;  // made at a programme's first row
  std::unique_ptr<Compression<2>> compression2_;
  std::unique_ptr<Compression<3>> compression3_;
  // The case's regions (regions.csv) and its box control (box.csv), made
  // at the first row that has them (or reopened at a resume).
  std::vector<io::MeasurementRegion> regions_;
  std::unique_ptr<io::RegionsCsvT<2>> regions2_;
  std::unique_ptr<io::RegionsCsvT<3>> regions3_;
  std::unique_ptr<io::BoxCsvT<2>> box2_;
  std::unique_ptr<io::BoxCsvT<3>> box3_;
  std::optional<std::uint64_t> last_cycle_;
  std::optional<io::ResumePoint> resume_;  // while the tables it names are not all reopened
};

}  // namespace dem::service
