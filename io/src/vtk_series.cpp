#include "dem/io/vtk_series.h"

#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>

#include "dem/io/vtk_files.h"
#include "format_number.h"
#include "vtk_xml.h"

namespace dem::io {
namespace {

constexpr const char* kKinds[] = {"particles", "contacts", "walls"};

// Zero-padded so the files also sort by cycle in a directory listing.
std::string step_file(const char* kind, std::uint64_t cycle) {
  char name[64];
  std::snprintf(name, sizeof name, "vtk/%s_%010llu.vtp", kind, static_cast<unsigned long long>(cycle));
  return name;
}

}  // namespace

VtkSeries::VtkSeries(std::filesystem::path directory, std::uint64_t interval)
    : VtkSeries(std::move(directory), interval, {}) {}

VtkSeries::VtkSeries(std::filesystem::path directory, std::uint64_t interval, std::vector<Step> steps)
    : directory_(std::move(directory)), interval_(interval), steps_(std::move(steps)) {
  if (interval_ == 0) throw std::invalid_argument("a ParaView series needs an interval of at least one cycle");
  if (!steps_.empty()) last_cycle_ = steps_.back().cycle;
  remove_previous_steps();
  write_collections();
}

bool VtkSeries::due(std::uint64_t cycle) const { return !last_cycle_ || cycle >= *last_cycle_ + interval_; }

template <int Dim>
void VtkSeries::write(const WorldSnapshotT<Dim>& snapshot) {
  write_particles_vtp(directory_ / step_file("particles", snapshot.cycle), snapshot);
  write_contacts_vtp(directory_ / step_file("contacts", snapshot.cycle), snapshot);
  write_walls_vtp(directory_ / step_file("walls", snapshot.cycle), snapshot);
  if (last_cycle_ != snapshot.cycle) steps_.push_back({snapshot.cycle, snapshot.time});
  last_cycle_ = snapshot.cycle;
  write_collections();
}

template <int Dim>
bool VtkSeries::record(const BasicWorld<Dim>& world, bool force) {
  const std::uint64_t cycle = world.cycle_count();
  if (!(due(cycle) || (force && last_cycle_ != cycle))) return false;
  write(world.snapshot());
  return true;
}

void VtkSeries::write_collections() const {
  for (const char* kind : kKinds) {
    std::string xml =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        "  <Collection>\n";
    for (const Step& step : steps_) {
      xml += "    <DataSet timestep=\"" + format_number(step.time) + "\" group=\"\" part=\"0\" file=\"" +
             step_file(kind, step.cycle) + "\"/>\n";
    }
    xml +=
        "  </Collection>\n"
        "</VTKFile>\n";
    vtk::write_file(directory_ / (std::string(kind) + ".pvd"), xml);
  }
}

// A previous run's steps in the same directory would be listed by no
// collection, and mixed up with this run's by anyone reading vtk/.
void VtkSeries::remove_previous_steps() const {
  std::set<std::string> kept;
  for (const Step& step : steps_) {
    for (const char* kind : kKinds) kept.insert(std::filesystem::path(step_file(kind, step.cycle)).filename().string());
  }
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory_ / "vtk", error)) {
    const std::string name = entry.path().filename().string();
    for (const char* kind : kKinds) {
      if (name.starts_with(std::string(kind) + "_") && name.ends_with(".vtp") && !kept.contains(name)) {
        std::filesystem::remove(entry.path(), error);
      }
    }
  }
}

std::vector<std::filesystem::path> VtkSeries::collections() const {
  std::vector<std::filesystem::path> files;
  for (const char* kind : kKinds) files.push_back(directory_ / (std::string(kind) + ".pvd"));
  return files;
}

template void VtkSeries::write(const WorldSnapshotT<2>&);
template void VtkSeries::write(const WorldSnapshotT<3>&);
template bool VtkSeries::record(const BasicWorld<2>&, bool);
template bool VtkSeries::record(const BasicWorld<3>&, bool);

}  // namespace dem::io
