#include "dem/service/output_recorder.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <vector>

#include "dem/io/compression_state.h"
#include "dem/io/earlier_run.h"
#include "dem/io/file_access.h"

namespace dem::service {

namespace {

// A case name as one safe directory name.
std::string directory_name(const std::string& case_name) {
  std::string name;
  for (const char c : case_name) name += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  return name.empty() ? "unnamed" : name;
}

}  // namespace

std::filesystem::path OutputRecorder::case_directory_of(const std::filesystem::path& output,
                                                        const std::string& case_name) {
  return output / directory_name(case_name);
}

void OutputRecorder::claim(const std::string& case_name, bool overwrite) {
  const std::filesystem::path directory = case_directory_of(output_directory_, case_name);
  std::error_code error;
  if (started_.contains(directory) || !std::filesystem::is_directory(directory, error)) return;
  // A link in its place or in it is start()'s to refuse (io::own_directory):
  // nothing is then written there, so nothing is cut.
  try {
    io::own_directory(output_directory_, directory.filename());
  } catch (const io::FileAccessError&) {
    return;
  }
  const std::vector<std::string> names = io::earlier_run_entries(directory, io::RunEntries::kEvery);
  if (names.empty()) return;
  if (!overwrite) {
    throw OutputInUse(directory.string() + " holds the output of an earlier run (" + io::some_names(names) +
                      "), which a new run would cut: continue it with --resume (dem_server --case FILE --resume), "
                      "start the server with --overwrite to replace it, or give another --out");
  }
  io::remove_entries(directory, names);
  spdlog::warn("--overwrite: removed the {} files of an earlier run in {}", names.size(), directory.string());
}

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
void OutputRecorder::make_compression(const BasicWorld<Dim>& world) {
  const io::TableSizes* tables = resume_ ? &resume_->tables : nullptr;
  compression<Dim>().reset(
      new Compression<Dim>{dem::analysis::CompressionAnalysisT<Dim>(*compression_settings_),
                           io::CompressionCsvT<Dim>(directory_, world.wall(compression_settings_->loading_plate).name,
                                                    world.wall(compression_settings_->bottom_plate).name, tables)});
  if (resume_ && !resume_->analysis.empty())
    compression<Dim>()->analysis.restore(io::compression_state_from_text<Dim>(resume_->analysis));
}

template <int Dim>
void OutputRecorder::start(const std::string& case_name, const BasicWorld<Dim>& world,
                           std::optional<dem::analysis::CompressionSettings> compression, std::uint64_t vtk_interval,
                           const io::ResumePoint* resume, const std::vector<io::MeasurementRegion>& regions) {
  close();
  directory_ = case_directory_of(output_directory_, case_name);
  compression_settings_ = std::move(compression);
  regions_ = regions;
  vtk_interval_ = vtk_override_.value_or(vtk_interval);
  if (resume) resume_ = *resume;
  directory_problem_.reset();
  started_.insert(directory_);
  try {
    io::own_directory(output_directory_, directory_.filename());
  } catch (const io::FileAccessError& error) {
    directory_problem_ = error.what();
    if (enabled_) fail(error);
    return;
  }
  if (!enabled_) return;
  try {
    const io::TableSizes* tables = resume ? &resume->tables : nullptr;
    if constexpr (Dim == 2) {
      walls2_ = std::make_unique<io::WallsCsvT<2>>(directory_, tables);
    } else {
      walls3_ = std::make_unique<io::WallsCsvT<3>>(directory_, tables);
    }
    assembly_ = std::make_unique<io::AssemblyCsv>(directory_, tables);
    if (resume) {
      // The checkpoint's row is in the tables already; the analyses (if
      // they had begun) and stages.csv carry on.
      last_cycle_ = resume->cycle;
      if (compression_settings_ && resume->tables.contains("compression.csv")) make_compression(world);
      record_regions(world, false);
      if (resume->tables.contains("stages.csv")) {
        stages_ = std::make_unique<io::CsvFile>(directory_, "stages.csv",
                                                "stage,name,cycles_run,condition_met,cycle,time", tables);
      }
    } else {
      record(world);
    }
  } catch (const std::exception& error) {
    fail(error);
  }
}

std::filesystem::path OutputRecorder::own_file(std::string_view name) const {
  if (directory_problem_) throw io::FileAccessError(*directory_problem_);
  return directory_ / name;
}

void OutputRecorder::fill(io::ResumePoint& point) {
  point.tables.clear();
  point.analysis.clear();
  std::vector<io::CsvFile*> tables;
  if (walls2_) tables.push_back(&walls2_->file());
  if (walls3_) tables.push_back(&walls3_->file());
  if (assembly_) tables.push_back(&assembly_->file());
  if (stages_) tables.push_back(stages_.get());
  if (regions2_) tables.push_back(&regions2_->file());
  if (regions3_) tables.push_back(&regions3_->file());
  if (box2_) tables.push_back(&box2_->file());
  if (box3_) tables.push_back(&box3_->file());
  const auto add_compression = [&](auto& c) {
    if (!c) return;
    for (io::CsvFile* table : c->csv.tables()) tables.push_back(table);
    point.analysis = io::compression_state_text(c->analysis.state());
  };
  add_compression(compression2_);
  add_compression(compression3_);
  // A resumed run's series not made again yet still has the checkpoint's steps.
  point.vtk_steps.clear();
  if (vtk_) {
    point.vtk_steps = vtk_->step_list();
  } else if (resume_) {
    point.vtk_steps = resume_->vtk_steps;
  }
  for (io::CsvFile* table : tables) {
    table->flush();
    point.tables[table->path().filename().string()] = table->bytes();
  }
}

template <int Dim>
void OutputRecorder::record(const BasicWorld<Dim>& world, std::optional<std::size_t> stage) {
  if (!assembly_) return;
  try {
    if (stage && compression_settings_) {
      std::unique_ptr<Compression<Dim>>& c = compression<Dim>();
      if (!c) make_compression(world);
      io::record_compression(c->analysis, c->csv, world, static_cast<int>(*stage));
    }
    if (stage && vtk_interval_ > 0) {
      if (!vtk_) {
        // A resumed run keeps the steps before its checkpoint, as it keeps the tables' rows.
        vtk_ = resume_ ? std::make_unique<io::VtkSeries>(directory_, vtk_interval_, resume_->vtk_steps)
                       : std::make_unique<io::VtkSeries>(directory_, vtk_interval_);
      }
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
    record_regions(world, true);
  } catch (const std::exception& error) {
    fail(error);
  }
}

template <int Dim>
void OutputRecorder::record_regions(const BasicWorld<Dim>& world, bool write) {
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
  const io::TableSizes* tables = resume_ ? &resume_->tables : nullptr;
  // Without a row to write (a resume), only the tables the checkpoint
  // names open - appended to by the rows that follow; otherwise each opens
  // at its first row.
  const auto listed = [&](std::string_view name) { return tables != nullptr && tables->contains(name); };
  if (!regions_.empty() && !regions && (write || listed("regions.csv"))) {
    std::vector<analysis::RegionT<Dim>> defined;
    for (const io::MeasurementRegion& r : regions_) defined.push_back(io::region_for<Dim>(r));
    regions = std::make_unique<io::RegionsCsvT<Dim>>(directory_, std::move(defined), tables);
  }
  const bool boxed = static_cast<bool>(world.box_control());
  if (!box && (write ? boxed : listed("box.csv"))) box = std::make_unique<io::BoxCsvT<Dim>>(directory_, tables);
  if (!write) return;
  if (regions) regions->write(world);
  if (box && boxed) box->write(world);
}

void OutputRecorder::record_stage(std::size_t stage, const std::string& name, const StageResult& result,
                                  std::uint64_t cycle, double time) {
  if (!assembly_) return;
  try {
    if (!stages_) {
      stages_ =
          std::make_unique<io::CsvFile>(directory_, "stages.csv", "stage,name,cycles_run,condition_met,cycle,time");
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
  resume_.reset();
}

template void OutputRecorder::start(const std::string&, const BasicWorld<2>&,
                                    std::optional<dem::analysis::CompressionSettings>, std::uint64_t,
                                    const io::ResumePoint*, const std::vector<io::MeasurementRegion>&);
template void OutputRecorder::start(const std::string&, const BasicWorld<3>&,
                                    std::optional<dem::analysis::CompressionSettings>, std::uint64_t,
                                    const io::ResumePoint*, const std::vector<io::MeasurementRegion>&);
template void OutputRecorder::record(const BasicWorld<2>&, std::optional<std::size_t>);
template void OutputRecorder::record(const BasicWorld<3>&, std::optional<std::size_t>);
template void OutputRecorder::finish(const BasicWorld<2>&);
template void OutputRecorder::finish(const BasicWorld<3>&);

}  // namespace dem::service
