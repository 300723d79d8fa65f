// dem_vtk SNAPSHOT... --out DIR: ParaView files from snapshot files (dem_server's
// final.snapshot, demctl snapshot save, ...): particles.pvd, contacts.pvd and
// walls.pvd in DIR with one step per snapshot, in the order given (ParaView
// orders a series by time). The same files dem_run --vtk-interval writes
// (io/vtk_files.h describes every array).
// Exit codes: 0 done; 1 an output that cannot be written; 2 bad arguments;
// 3 a file that is not a readable snapshot (the message names it).
#include <CLI/CLI.hpp>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "dem/io/snapshot_file.h"
#include "dem/io/vtk_series.h"
#include "dem/version.h"

namespace {

constexpr int kFailure = 1;
constexpr int kBadArguments = 2;
constexpr int kBadSnapshot = 3;

template <int Dim>
void add_step(dem::io::VtkSeries& series, const dem::proto::Snapshot& message, const std::filesystem::path& file) {
  try {
    series.write(dem::io::snapshot_from_proto<Dim>(message));
  } catch (const dem::io::SnapshotError& error) {
    throw dem::io::SnapshotError(file.string() + ": " + error.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes ParaView files (VTK XML .vtp and .pvd time series) from dem snapshot files."};
  app.set_version_flag("--version", "dem_vtk " DEM_VERSION);
  std::vector<std::filesystem::path> snapshots;
  std::filesystem::path out;
  app.add_option("SNAPSHOT", snapshots, "snapshot files (dem.proto.Snapshot), one step each")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("-o,--out", out, "directory for particles.pvd, contacts.pvd, walls.pvd and vtk/ (created)")
      ->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kBadArguments;
  }

  std::optional<dem::io::VtkSeries> series;
  std::optional<unsigned> dimension;
  try {
    series.emplace(out, 1);
    for (const auto& file : snapshots) {
      const dem::proto::Snapshot message =
          dem::io::parse_snapshot_message(dem::io::read_snapshot_bytes(file), file.string());
      if (dimension && *dimension != message.dimension()) {
        std::cerr << "error: " << file.string() << ": a " << message.dimension() << "D snapshot among " << *dimension
                  << "D ones: one series holds one dimension\n";
        return kBadSnapshot;
      }
      dimension = message.dimension();
      if (message.dimension() == 3) {
        add_step<3>(*series, message, file);
      } else {
        add_step<2>(*series, message, file);
      }
    }
  } catch (const dem::io::SnapshotError& error) {
    std::cerr << "error: " << error.what() << '\n';
    return kBadSnapshot;
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << '\n';
    return kFailure;
  }
  std::cout << "wrote " << series->steps() << (series->steps() == 1 ? " step:" : " steps:");
  for (const auto& file : series->collections()) std::cout << ' ' << file.string();
  std::cout << '\n';
  return 0;
}
