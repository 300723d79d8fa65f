// The tables a run writes, one file each, in CSV with a header row (see
// csv_file.h for number formats). Each writer creates its directory if it is
// missing and throws std::runtime_error naming the file when it cannot write.
// A 2D run writes the 2D columns; a 3D run adds z components, writes
// moments and angular velocities as vectors and rotations as quaternions.
//
// Time series, one row per call (dem_run calls them every output interval):
//   walls.csv     2D: cycle,time,wall,fx,fy,moment,normal_force,contacts,
//                     eccentricity,x,y,dx,dy,normal_stress,settlement
//                 3D: cycle,time,wall,fx,fy,fz,moment_x,moment_y,moment_z,
//                     normal_force,contacts,eccentricity_u,eccentricity_v,
//                     x,y,z,dx,dy,dz,normal_stress,settlement
//                 long format: one row per wall; wall is the wall's name,
//                 x,y(,z) its reference point P and dx,dy(,dz) P's
//                 displacement; the 3D eccentricities are along the wall's
//                 two sides, u (direction) and v (direction2);
//                 normal_stress is normal_force over the wall's area (Pa;
//                 World::wall_area) and settlement how far it has moved
//                 along its normal into the particles since it was built or
//                 placed (m), as the service's telemetry reports them.
//                 The forces of a row at cycle N come from the force pass
//                 that ends cycle N, on the positions the particles and
//                 walls have at that moment: forces, positions,
//                 displacements and settlement belong to the same instant.
//                 (The same holds for probes.csv and contacts.csv against
//                 particles.csv.)
//   assembly.csv  cycle,time,kinetic_energy,out_of_balance,max_contact_force,
//                 contacts,sliding_contacts,time_step_ratio,gravity_work,
//                 wall_work,continuum_work,strain_energy,contact_damping,
//                 friction,global_damping,local_damping,energy_residual
//                 the energy budget since the start (J; dem/measures.h):
//                 initial kinetic + gravity_work (body forces) + wall_work +
//                 continuum_work (a box's continuum field) = kinetic +
//                 strain + the dissipated terms + energy_residual;
//                 time_step_ratio is Randall's particle-wise check (> 0.3: too large)
//   probes.csv    cycle,time,probe,normal_force,shear_force,touching
//                 one row per probe; forces are 0 while the pair is apart;
//                 shear_force is signed in 2D, the magnitude in 3D.
// Snapshots, written once (at the end of a run):
//   contacts.csv  2D: first,second_kind,second,x,y,nx,ny,overlap,normal_force,
//                     shear_force,tangential_x,tangential_y,normal_damping,
//                     shear_damping,sliding,formed_cycle,force_x,force_y
//                 3D: first,second_kind,second,x,y,z,nx,ny,nz,overlap,
//                     normal_force,shear_force,tangential_x,tangential_y,
//                     tangential_z,normal_damping,shear_damping,sliding,
//                     formed_cycle,force_x,force_y,force_z
//                 the fields of the engine's contact record, in the order
//                 of its field list (ContactRecordFields, dem/measures.h),
//                 vectors one column per axis: a field added there is a
//                 column here. second_kind is "particle" (second is its id)
//                 or "wall" (second is the wall's name, as in walls.csv).
//                 The shear force and damping are signed along t in 2D,
//                 magnitudes in 3D; tangential_* is the shear spring's force
//                 on the first particle, force_* the whole force the contact
//                 puts on it (springs and dashpots), formed_cycle the cycle
//                 the contact began touching.
//   particles.csv 2D: id,x,y,radius,vx,vy,angular_velocity,rotation,
//                     material,a,b,n
//                 3D: id,x,y,z,radius,vx,vy,vz,angular_velocity_x,
//                     angular_velocity_y,angular_velocity_z,rotation_w,
//                     rotation_x,rotation_y,rotation_z,material,a1,a2,a3
//                 (the 3D rotation is a unit quaternion; material is the
//                 material's name). The shape: a 2D superquadric's
//                 semi-axes a, b and exponent n (Miyata eq. 34), turned by
//                 the rotation; a disc's R, R, 2. A 3D ellipsoid's
//                 semi-axes along its body axes (eq. 43); a sphere's R, R, R.
//                 radius is a shaped particle's bounding radius.
// Units are the engine's (SI); booleans (touching, sliding) are 0 or 1.
#pragma once

#include <filesystem>
#include <vector>

#include "dem/io/case_definition.h"
#include "dem/io/csv_file.h"
#include "dem/world.h"

namespace dem::io {

template <int Dim>
class WallsCsvT {
 public:
  // `resume`: see CsvFile.
  explicit WallsCsvT(const std::filesystem::path& directory, const TableSizes* resume = nullptr);
  void write(const BasicWorld<Dim>& world);
  const std::filesystem::path& path() const { return file_.path(); }
  CsvFile& file() { return file_; }

 private:
  CsvFile file_;
};

using WallsCsv = WallsCsvT<2>;
using WallsCsv3 = WallsCsvT<3>;

class AssemblyCsv {
 public:
  explicit AssemblyCsv(const std::filesystem::path& directory, const TableSizes* resume = nullptr);
  // Writes a row and returns the measures it wrote.
  template <int Dim>
  AssemblyMeasures write(const BasicWorld<Dim>& world);
  const std::filesystem::path& path() const { return file_.path(); }
  CsvFile& file() { return file_; }

 private:
  CsvFile file_;
};

class ProbesCsv {
 public:
  ProbesCsv(const std::filesystem::path& directory, std::vector<Probe> probes, const TableSizes* resume = nullptr);
  template <int Dim>
  void write(const BasicWorld<Dim>& world);
  const std::filesystem::path& path() const { return file_.path(); }
  CsvFile& file() { return file_; }

 private:
  CsvFile file_;
  std::vector<Probe> probes_;
};

template <int Dim>
void write_contacts_csv(const std::filesystem::path& directory, const BasicWorld<Dim>& world);
template <int Dim>
void write_particles_csv(const std::filesystem::path& directory, const BasicWorld<Dim>& world);

extern template class WallsCsvT<2>;
extern template class WallsCsvT<3>;
extern template AssemblyMeasures AssemblyCsv::write(const World&);
extern template AssemblyMeasures AssemblyCsv::write(const World3&);
extern template void ProbesCsv::write(const World&);
extern template void ProbesCsv::write(const World3&);
extern template void write_contacts_csv(const std::filesystem::path&, const World&);
extern template void write_contacts_csv(const std::filesystem::path&, const World3&);
extern template void write_particles_csv(const std::filesystem::path&, const World&);
extern template void write_particles_csv(const std::filesystem::path&, const World3&);

}  // namespace dem::io
