// A run's ParaView time series in its output directory: particles.pvd,
// contacts.pvd and walls.pvd (VTK "Collection" files; open them in
// ParaView and play), each listing its .vtp files in vtk/ by simulated
// time. The files of one step are vtk/particles_<cycle>.vtp,
// vtk/contacts_<cycle>.vtp and vtk/walls_<cycle>.vtp (vtk_files.h). The
// .pvd files are rewritten after every step, so they are complete even
// when a run is cut short.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "dem/snapshot.h"
#include "dem/world.h"

namespace dem::io {

class VtkSeries {
 public:
  // A step of the series: the cycle its files are named by, and its time.
  struct Step {
    std::uint64_t cycle;
    double time;
    friend bool operator==(const Step&, const Step&) = default;
  };

  // `interval`: cycles between steps (> 0). Starts empty .pvd files in
  // `directory` (a previous series' files there are removed). Throws
  // std::runtime_error naming the file it cannot write.
  VtkSeries(std::filesystem::path directory, std::uint64_t interval);
  // Continues a series that had written `steps` (a checkpoint's, for a
  // resumed run): their files are kept and listed, any other step's - one
  // written after the checkpoint by the run that crashed - removed, so the
  // series ends as an uninterrupted run's does.
  VtkSeries(std::filesystem::path directory, std::uint64_t interval, std::vector<Step> steps);

  // Whether a world at `cycle` is due a step: the first call, and then
  // once at least `interval` cycles have passed since the last step.
  bool due(std::uint64_t cycle) const;

  // Writes the step of this snapshot (again, if its cycle has one already:
  // a state that changed without cycling, such as a trimmed sample).
  template <int Dim>
  void write(const WorldSnapshotT<Dim>& snapshot);
  // Writes a step of the world when one is due (or `force`, when its cycle
  // has none yet: the end of a run). Returns whether it wrote.
  template <int Dim>
  bool record(const BasicWorld<Dim>& world, bool force = false);

  const std::filesystem::path& directory() const { return directory_; }
  std::uint64_t interval() const { return interval_; }
  // particles.pvd, contacts.pvd and walls.pvd.
  std::vector<std::filesystem::path> collections() const;
  std::size_t steps() const { return steps_.size(); }
  // The steps written so far, for a checkpoint.
  const std::vector<Step>& step_list() const { return steps_; }

 private:
  void remove_previous_steps() const;  // all but those in steps_
  void write_collections() const;

  std::filesystem::path directory_;
  std::uint64_t interval_;
  std::vector<Step> steps_;
  std::optional<std::uint64_t> last_cycle_;
};

extern template void VtkSeries::write(const WorldSnapshotT<2>&);
extern template void VtkSeries::write(const WorldSnapshotT<3>&);
extern template bool VtkSeries::record(const BasicWorld<2>&, bool);
extern template bool VtkSeries::record(const BasicWorld<3>&, bool);

}  // namespace dem::io
