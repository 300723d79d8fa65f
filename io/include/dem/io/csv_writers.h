// The tables a run writes, one file each, in CSV with a header row (see
// csv_file.h for number formats). Each writer creates its directory if it is
// missing and throws std::runtime_error naming the file when it cannot write.
//
// Time series, one row per call (dem_run calls them every output interval):
//   walls.csv     cycle,time,wall,fx,fy,moment,normal_force,contacts,
//                 eccentricity,x,y,dx,dy
//                 long format: one row per wall; wall is the wall's name,
//                 x,y its reference point P and dx,dy P's displacement.
//   assembly.csv  cycle,time,kinetic_energy,out_of_balance,max_contact_force,
//                 contacts,sliding_contacts
//   probes.csv    cycle,time,probe,normal_force,shear_force,touching
//                 one row per probe; forces are 0 while the pair is apart.
// Snapshots, written once (at the end of a run):
//   contacts.csv  first,second_kind,second,x,y,nx,ny,overlap,normal_force,
//                 shear_force,normal_damping,shear_damping,sliding
//                 second_kind is "particle" (second is its id) or "wall"
//                 (second is the wall's name, as in walls.csv).
//   particles.csv id,x,y,radius,vx,vy,angular_velocity,rotation
// Units are the engine's (SI); booleans (touching, sliding) are 0 or 1.
#pragma once

#include <filesystem>
#include <vector>

#include "dem/io/case_definition.h"
#include "dem/io/csv_file.h"
#include "dem/world.h"

namespace dem::io {

class WallsCsv {
 public:
  explicit WallsCsv(const std::filesystem::path& directory);
  void write(const World& world);
  const std::filesystem::path& path() const { return file_.path(); }

 private:
  CsvFile file_;
};

class AssemblyCsv {
 public:
  explicit AssemblyCsv(const std::filesystem::path& directory);
  void write(const World& world);
  const std::filesystem::path& path() const { return file_.path(); }

 private:
  CsvFile file_;
};

class ProbesCsv {
 public:
  ProbesCsv(const std::filesystem::path& directory, std::vector<Probe> probes);
  void write(const World& world);
  const std::filesystem::path& path() const { return file_.path(); }

 private:
  CsvFile file_;
  std::vector<Probe> probes_;
};

void write_contacts_csv(const std::filesystem::path& directory, const World& world);
void write_particles_csv(const std::filesystem::path& directory, const World& world);

}  // namespace dem::io
