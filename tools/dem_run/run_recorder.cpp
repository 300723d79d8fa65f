#include "run_recorder.h"

#include <cstdio>

namespace dem::run {

template <int Dim>
RunRecorder<Dim>::RunRecorder(const std::filesystem::path& directory, const io::OutputSettings& output,
                              const BasicWorld<Dim>& world, const io::ResumePoint* resume)
    : directory_(directory),
      contacts_file_(output.contacts_file),
      walls_(directory, resume ? &resume->tables : nullptr),
      assembly_(directory, resume ? &resume->tables : nullptr) {
  const io::TableSizes* tables = resume ? &resume->tables : nullptr;
  files_ = {walls_.path(), assembly_.path()};
  if (!output.probes.empty()) {
    probes_.emplace(directory, output.probes, tables);
    files_.push_back(probes_->path());
  }
  if (output.compression) {
    compression_.emplace(*output.compression);
    compression_csv_.emplace(directory, world.wall(output.compression->loading_plate).name,
                             world.wall(output.compression->bottom_plate).name, tables);
    if (resume) compression_->restore(resume->analysis);
  }
  // The checkpoint's row is in the tables already.
  if (resume) last_cycle_ = resume->cycle;
}

template <int Dim>
void RunRecorder<Dim>::fill(io::ResumePoint& point) {
  std::vector<io::CsvFile*> tables = {&walls_.file(), &assembly_.file()};
  if (probes_) tables.push_back(&probes_->file());
  if (compression_csv_) {
    tables.push_back(&compression_csv_->samples_file());
    tables.push_back(&compression_csv_->contacts_file());
  }
  point.tables.clear();
  for (io::CsvFile* table : tables) {
    table->flush();
    point.tables[table->path().filename().string()] = table->bytes();
  }
  point.analysis = compression_ ? compression_->state() : std::string();
}

template <int Dim>
void RunRecorder<Dim>::record(const BasicWorld<Dim>& world, int stage) {
  if (compression_) io::record_compression(*compression_, *compression_csv_, world, stage);
  if (last_cycle_ == world.cycle_count()) return;
  last_cycle_ = world.cycle_count();
  walls_.write(world);
  const AssemblyMeasures measures = assembly_.write(world);
  if (probes_) probes_->write(world);
  // Randall (1989) 4.35-4.40: above 0.3 of the particle-wise critical step
  // the step is too large for the stiffness the particles meet. Said once.
  if (measures.time_step_ratio > 0.3 && !warned_time_step_) {
    warned_time_step_ = true;
    std::fprintf(stderr,
                 "warning: at cycle %llu the time step is %.2f of the smallest particle-wise critical step "
                 "(Randall 1989, 4.35-4.40; keep it below 0.3): reduce time_step.fraction\n",
                 static_cast<unsigned long long>(world.cycle_count()), measures.time_step_ratio);
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
  if (compression_) {
    compression_csv_->write_results(compression_->results(world));
    for (const auto& file : compression_csv_->files()) files_.push_back(file);
  }
}

template class RunRecorder<2>;
template class RunRecorder<3>;

}  // namespace dem::run
