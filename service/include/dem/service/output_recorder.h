// The server's files in its output directory, per loaded case
// (<output>/<case>/): walls.csv and assembly.csv at the telemetry interval
// while it runs (the same tables as dem_run, io/csv_writers.h), contacts.csv
// and particles.csv when the case is replaced or the server stops. A file
// that cannot be written is logged and recording stops; the simulation goes on.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "dem/io/csv_writers.h"
#include "dem/world.h"

namespace dem::service {

class OutputRecorder {
 public:
  OutputRecorder(std::filesystem::path output_directory, bool enabled);

  template <int Dim>
  void start(const std::string& case_name, const BasicWorld<Dim>& world);  // after a load
  template <int Dim>
  void record(const BasicWorld<Dim>& world);  // at the telemetry interval
  template <int Dim>
  void finish(const BasicWorld<Dim>& world);  // before a new load and at shutdown

 private:
  void fail(const std::exception& error);
  void close();

  std::filesystem::path output_directory_;
  bool enabled_;
  std::filesystem::path directory_;
  std::unique_ptr<io::WallsCsvT<2>> walls2_;
  std::unique_ptr<io::WallsCsvT<3>> walls3_;
  std::unique_ptr<io::AssemblyCsv> assembly_;
};

}  // namespace dem::service
