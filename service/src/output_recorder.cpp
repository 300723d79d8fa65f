#include "dem/service/output_recorder.h"

#include <spdlog/spdlog.h>

namespace dem::service {

namespace {

// A case name as one safe directory name.
std::string directory_name(const std::string& case_name) {
  std::string name;
  for (const char c : case_name) name += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  return name.empty() ? "unnamed" : name;
}

}  // namespace

OutputRecorder::OutputRecorder(std::filesystem::path output_directory, bool enabled,
                               std::optional<std::uint64_t> vtk_interval)
    : output_directory_(std::move(output_directory)), enabled_(enabled), vtk_override_(vtk_interval) {}

template <int Dim>
std::unique_ptr<OutputRecorder::Compression<Dim>>& OutputRecorder::compression() {
  if constexpr (Dim == 2) {
    return compression2_;
  } else {
    return compression3_;
  }
}

template <int Dim>
void OutputRecorder::start(const std::string& case_name, const BasicWorld<Dim>& world,
                           std::optional<io::CompressionSettings> compression, std::uint64_t vtk_interval,
                           const std::vector<io::MeasurementRegion>& regions) {
  close();
  directory_ = output_directory_ / directory_name(case_name);
  compression_settings_ = std::move(compression);
  regions_ = regions;
  vtk_interval_ = vtk_override_.value_or(vtk_interval);
  if (!enabled_) return;
  try {
    if constexpr (Dim == 2) {
      walls2_ = std::make_unique<io::WallsCsvT<2>>(directory_);
    } else {
      walls3_ = std::make_unique<io::WallsCsvT<3>>(directory_);
    }
    assembly_ = std::make_unique<io::AssemblyCsv>(directory_);
    record(world);
  } catch (const std::exception& error) {
    fail(error);
  }
}

template <int Dim>
void OutputRecorder::record(const BasicWorld<Dim>& world, std::optional<std::size_t> stage) {
  if (!assembly_) return;
  try {
    if (stage && compression_settings_) {
      std::unique_ptr<Compression<Dim>>& c = compression<Dim>();
      if (!c) {
        c.reset(new Compression<Dim>{io::CompressionAnalysisT<Dim>(*compression_settings_),
                                     io::CompressionCsvT<Dim>(directory_,
                                                              world.wall(compression_settings_->loading_plate).name,
                                                              world.wall(compression_settings_->bottom_plate).name)});
      }
      io::record_compression(c->analysis, c->csv, world, static_cast<int>(*stage));
    }
    if (stage && vtk_interval_ > 0) {
      if (!vtk_) vtk_ = std::make_unique<io::VtkSeries>(directory_, vtk_interval_);
      vtk_->record(world);
    }
  } catch (const std::exception& error) {
    fail(error);
    return;
  }
  if (last_cycle_ == world.cycle_count()) return;
  last_cycle_ = world.cycle_count();
  try {
    if constexpr (Dim == 2) {
      walls2_->write(world);
    } else {
      walls3_->write(world);
    }
    assembly_->write(world);
    record_regions(world);
  } catch (const std::exception& error) {
    fail(error);
  }
}

template <int Dim>
void OutputRecorder::record_regions(const BasicWorld<Dim>& world) {
  auto& regions = [&]() -> std::unique_ptr<io::RegionsCsvT<Dim>>& {
    if constexpr (Dim == 2) {
      return regions2_;
    } else {
      return regions3_;
    }
  }();
  auto& box = [&]() -> std::unique_ptr<io::BoxCsvT<Dim>>& {
    if constexpr (Dim == 2) {
      return box2_;
    } else {
      return box3_;
    }
  }();
  if (!regions_.empty()) {
    if (!regions) {
      std::vector<analysis::RegionT<Dim>> defined;
      for (const io::MeasurementRegion& r : regions_) defined.push_back(io::region_for<Dim>(r));
      regions = std::make_unique<io::RegionsCsvT<Dim>>(directory_, std::move(defined));
    }
    regions->write(world);
  }
  if (world.box_control()) {
    if (!box) box = std::make_unique<io::BoxCsvT<Dim>>(directory_);
    box->write(world);
  }
}

void OutputRecorder::record_stage(std::size_t stage, const std::string& name, const StageResult& result,
                                  std::uint64_t cycle, double time) {
  if (!assembly_) return;
  try {
    if (!stages_) {
      stages_ = std::make_unique<io::CsvFile>(directory_, "stages.csv",
                                              "stage,name,cycles_run,condition_met,cycle,time");
    }
    stages_->write_row(stage + 1, name, result.cycles_run, result.condition_met, cycle, time);
    stages_->flush();
  } catch (const std::exception& error) {
    fail(error);
  }
}

template <int Dim>
void OutputRecorder::finish(const BasicWorld<Dim>& world) {
  if (!assembly_) return;
  try {
    io::write_contacts_csv(directory_, world);
    io::write_particles_csv(directory_, world);
    spdlog::info("wrote {}/{{walls,assembly,contacts,particles}}.csv", directory_.string());
    if (const std::unique_ptr<Compression<Dim>>& c = compression<Dim>()) {
      c->csv.write_results(c->analysis.results(world));
      spdlog::info("wrote the plate loading analyses in {} (compression.csv, compression_states.csv, ...)",
                   directory_.string());
    }
    if (vtk_) {
      vtk_->record(world, true);
      spdlog::info("wrote {} ParaView steps in {} (particles.pvd, contacts.pvd, walls.pvd)", vtk_->steps(),
                   directory_.string());
    }
  } catch (const std::exception& error) {
    fail(error);
  }
  close();
}

void OutputRecorder::fail(const std::exception& error) {
  spdlog::error("output recording stopped: {}", error.what());
  failed_ = true;
  close();
}

void OutputRecorder::close() {
  walls2_.reset();
  walls3_.reset();
  assembly_.reset();
  stages_.reset();
  compression2_.reset();
  compression3_.reset();
  regions2_.reset();
  regions3_.reset();
  box2_.reset();
  box3_.reset();
  vtk_.reset();
  last_cycle_.reset();
}

template void OutputRecorder::start(const std::string&, const BasicWorld<2>&, std::optional<io::CompressionSettings>,
                                    std::uint64_t, const std::vector<io::MeasurementRegion>&);
template void OutputRecorder::start(const std::string&, const BasicWorld<3>&, std::optional<io::CompressionSettings>,
                                    std::uint64_t, const std::vector<io::MeasurementRegion>&);
template void OutputRecorder::record(const BasicWorld<2>&, std::optional<std::size_t>);
template void OutputRecorder::record(const BasicWorld<3>&, std::optional<std::size_t>);
template void OutputRecorder::finish(const BasicWorld<2>&);
template void OutputRecorder::finish(const BasicWorld<3>&);

}  // namespace dem::service
