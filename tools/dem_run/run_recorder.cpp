#include "run_recorder.h"

namespace dem::run {

RunRecorder::RunRecorder(const std::filesystem::path& directory, const io::OutputSettings& output)
    : directory_(directory), contacts_file_(output.contacts_file), walls_(directory), assembly_(directory) {
  files_ = {walls_.path(), assembly_.path()};
  if (!output.probes.empty()) {
    probes_.emplace(directory, output.probes);
    files_.push_back(probes_->path());
  }
}

void RunRecorder::record(const World& world) {
  if (last_cycle_ == world.cycle_count()) return;
  last_cycle_ = world.cycle_count();
  walls_.write(world);
  assembly_.write(world);
  if (probes_) probes_->write(world);
}

void RunRecorder::finish(const World& world) {
  if (contacts_file_) {
    io::write_contacts_csv(directory_, world);
    files_.push_back(directory_ / "contacts.csv");
  }
  io::write_particles_csv(directory_, world);
  files_.push_back(directory_ / "particles.csv");
}

}  // namespace dem::run
