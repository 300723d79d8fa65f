#include "run_recorder.h"

#include <algorithm>
#include <cstdio>

#include "dem/io/compression_state.h"

namespace dem::run {

template <int Dim>
RunRecorder<Dim>::RunRecorder(const std::filesystem::path& directory, const io::OutputSettings& output,
                              const BasicWorld<Dim>& world, bool stiffness_varies, const io::ResumePoint* resume)
    : directory_(directory),
      contacts_file_(output.contacts_file),
      walls_(directory, resume ? &resume->tables : nullptr),
      assembly_(directory, resume ? &resume->tables : nullptr),
      check_time_step_(stiffness_varies) {
  const io::TableSizes* tables = resume ? &resume->tables : nullptr;
  files_ = {walls_.path(), assembly_.path()};
  if (!output.probes.empty()) {
    probes_.emplace(directory, output.probes, tables);
    files_.push_back(probes_->path());
  }
  if (!output.regions.empty()) {
    std::vector<dem::analysis::RegionT<Dim>> regions;
    for (const io::MeasurementRegion& r : output.regions) regions.push_back(io::region_for<Dim>(r));
    regions_.emplace(directory, std::move(regions), tables);
    files_.push_back(regions_->path());
  }
  // box.csv begins with the first row under a box control; a checkpoint
  // taken after that names it, and the resumed run appends to it.
  if (tables && tables->contains("box.csv")) {
    box_.emplace(directory, tables);
    files_.push_back(box_->path());
  }
  if (output.vtk_interval > 0) {
    // A resumed run keeps the steps before its checkpoint, as it keeps the tables' rows.
    if (resume) {
      vtk_.emplace(directory, output.vtk_interval, resume->vtk_steps);
    } else {
      vtk_.emplace(directory, output.vtk_interval);
    }
  }
  if (output.compression) {
    compression_.emplace(*output.compression);
    compression_csv_.emplace(directory, world.wall(output.compression->loading_plate).name,
                             world.wall(output.compression->bottom_plate).name, tables);
    if (resume) compression_->restore(io::compression_state_from_text<Dim>(resume->analysis));
  }
  // The checkpoint's row is in the tables already.
  if (resume) last_cycle_ = resume->cycle;
}

template <int Dim>
void RunRecorder<Dim>::fill(io::ResumePoint& point) {
  std::vector<io::CsvFile*> tables = {&walls_.file(), &assembly_.file()};
  if (probes_) tables.push_back(&probes_->file());
  if (regions_) tables.push_back(&regions_->file());
  if (box_) tables.push_back(&box_->file());
  if (compression_csv_) {
    for (io::CsvFile* table : compression_csv_->tables()) tables.push_back(table);
  }
  point.tables.clear();
  for (io::CsvFile* table : tables) {
    table->flush();
    point.tables[table->path().filename().string()] = table->bytes();
  }
  point.analysis = compression_ ? io::compression_state_text(compression_->state()) : std::string();
  point.vtk_steps = vtk_ ? vtk_->step_list() : std::vector<io::VtkSeries::Step>{};
}

template <int Dim>
void RunRecorder<Dim>::record(const BasicWorld<Dim>& world, int stage) {
  if (compression_) io::record_compression(*compression_, *compression_csv_, world, stage);
  if (vtk_) vtk_->record(world);
  if (last_cycle_ == world.cycle_count()) return;
  last_cycle_ = world.cycle_count();
  walls_.write(world);
  const AssemblyMeasures measures = assembly_.write(world);
  if (probes_) probes_->write(world);
  if (regions_) regions_->write(world);
  if (world.box_control()) {
    if (!box_) {
      box_.emplace(directory_);
      files_.push_back(box_->path());
    }
    box_->write(world);
  }
  // Randall (1989) 4.35-4.40: above 0.3 of the particle-wise critical step
  // the step is too large for the stiffness the particles meet. Randall
  // estimates that stiffness as K = d|sum F| / dx, dx = |v| dt, because "for
  // a non-linear system K varies" (4.5.1): the running check is for the
  // Hertz laws. A linear law's stiffness is a constant of the case, so the
  // step is set against the critical step of the stiffest contact,
  // 2 sqrt(m/k) (Cundall & Strack), with the same 0.3 for a particle's
  // several contacts; the estimate would only add noise there: under
  // Miyata's plate (case SR reduced, Table 2's step) it reads 0.36-0.45 at
  // 900 kPa, where the step is 0.13 of the stiffest contact's critical step
  // (1.3e-3 s: a particle's rotation on the plate's 1e8 N/m spring) and a
  // particle would need twelve such contacts to reach 0.45. The column
  // stays in assembly.csv for every law.
  if (!check_time_step_) {
    const double ratio = world.time_step() / world.critical_time_step();
    if (ratio > 0.3 && !warned_time_step_) {
      warned_time_step_ = true;
      std::fprintf(stderr,
                   "warning: from cycle %llu the time step %g s is %.2f of the critical step of the stiffest contact, "
                   "2 sqrt(m/k) shortened by its damping = %g s (Cundall & Strack); a particle with several "
                   "contacts needs less: keep it "
                   "below 0.3 of it (time_step.fraction or time_step.fixed)\n",
                   static_cast<unsigned long long>(world.cycle_count()), world.time_step(), ratio,
                   world.critical_time_step());
    }
    return;
  }
  // The estimate is meaningless too for a particle nearly at rest that is
  // struck (dx -> 0): settling samples show isolated spikes (Miyata's CS at
  // the seed's own step: 3 rows of 506 above 0.3, none adjacent, the
  // largest 0.59). A step really too large keeps the ratio high, so the
  // warning waits until it has been above 0.3 at every row for
  // kSustainedCycles cycles - or until it exceeds 1 at once: the step is
  // then longer than a particle's critical step, and the run is blowing
  // up. Said once.
  if (measures.time_step_ratio > 0.3) {
    if (rows_above_ == 0) first_above_ = world.cycle_count();
    ++rows_above_;
    largest_ratio_ = std::max(largest_ratio_, measures.time_step_ratio);
  } else {
    rows_above_ = 0;
    largest_ratio_ = 0.0;
  }
  const bool sustained = rows_above_ > 1 && world.cycle_count() - first_above_ >= kSustainedCycles;
  if ((sustained || measures.time_step_ratio > 1.0) && !warned_time_step_) {
    warned_time_step_ = true;
    std::fprintf(stderr,
                 "warning: from cycle %llu to %llu the time step was %.2f (at most) of the smallest particle-wise "
                 "critical step (Randall 1989, 4.35-4.40; keep it below 0.3): reduce the time step "
                 "(time_step.fraction or time_step.fixed)\n",
                 static_cast<unsigned long long>(first_above_), static_cast<unsigned long long>(world.cycle_count()),
                 largest_ratio_);
  }
}

template <int Dim>
void RunRecorder<Dim>::finish(const BasicWorld<Dim>& world) {
  if (contacts_file_) {
    io::write_contacts_csv(directory_, world);
    files_.push_back(directory_ / "contacts.csv");
  }
  io::write_particles_csv(directory_, world);
  files_.push_back(directory_ / "particles.csv");
  if (vtk_) {
    vtk_->record(world, true);
    for (const auto& file : vtk_->collections()) files_.push_back(file);
  }
  if (compression_) {
    compression_csv_->write_results(compression_->results(world));
    for (const auto& file : compression_csv_->files()) files_.push_back(file);
  }
}

template class RunRecorder<2>;
template class RunRecorder<3>;

}  // namespace dem::run
