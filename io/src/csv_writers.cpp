#include "dem/io/csv_writers.h"

#include <string_view>
#include <utility>

#include "world_rows.h"

namespace dem::io {
namespace {

constexpr const char* kWallsHeader2 =
    "cycle,time,wall,fx,fy,moment,normal_force,contacts,eccentricity,x,y,dx,dy,normal_stress,settlement";
constexpr const char* kWallsHeader3 =
    "cycle,time,wall,fx,fy,fz,moment_x,moment_y,moment_z,normal_force,contacts,eccentricity_u,eccentricity_v,"
    "x,y,z,dx,dy,dz,normal_stress,settlement";

}  // namespace

template <int Dim>
WallsCsvT<Dim>::WallsCsvT(const std::filesystem::path& directory, const TableSizes* resume)
    : file_(directory, "walls.csv", Dim == 2 ? kWallsHeader2 : kWallsHeader3, resume) {}

template <int Dim>
void WallsCsvT<Dim>::write(const BasicWorld<Dim>& world) {
  for (const WallMeasureT<Dim>& m : world.wall_measures()) {
    const std::string& name = world.wall(m.wall).name;
    const double stress = world.wall_stress(m.wall);
    const double settlement = world.wall_settlement(m.wall);
    if constexpr (Dim == 2) {
      file_.write_row(world.cycle_count(), world.time(), name, m.force.x(), m.force.y(), m.moment, m.normal_force,
                      m.contacts, m.eccentricity, m.point.x(), m.point.y(), m.displacement.x(), m.displacement.y(),
                      stress, settlement);
    } else {
      file_.write_row(world.cycle_count(), world.time(), name, m.force.x(), m.force.y(), m.force.z(), m.moment.x(),
                      m.moment.y(), m.moment.z(), m.normal_force, m.contacts, m.eccentricity.x(), m.eccentricity.y(),
                      m.point.x(), m.point.y(), m.point.z(), m.displacement.x(), m.displacement.y(), m.displacement.z(),
                      stress, settlement);
    }
  }
  file_.flush();
}

AssemblyCsv::AssemblyCsv(const std::filesystem::path& directory, const TableSizes* resume)
    : file_(directory, "assembly.csv",
            "cycle,time,kinetic_energy,out_of_balance,max_contact_force,contacts,sliding_contacts,time_step_ratio,"
            "elastic_energy,kinetic_to_elastic,unbalanced_force,sliding_fraction,mean_stress,deformation_rate,"
            "inertial_number,gravity_work,wall_work,continuum_work,strain_energy,contact_damping,friction,global_"
            "damping,local_"
            "damping,energy_residual",
            resume) {}

template <int Dim>
AssemblyMeasures AssemblyCsv::write(const BasicWorld<Dim>& world) {
  const AssemblyMeasures measures = world.assembly_measures();
  const EnergyBudget& e = measures.energy;
  if (world.energy_budget()) {
    file_.write_row(world.cycle_count(), world.time(), measures.kinetic_energy, measures.out_of_balance,
                    measures.max_contact_force, measures.contacts, measures.sliding_contacts, measures.time_step_ratio,
                    measures.elastic_energy, measures.kinetic_to_elastic, measures.unbalanced_force,
                    measures.sliding_fraction, measures.mean_stress, measures.deformation_rate,
                    measures.inertial_number, e.gravity_work, e.wall_work, e.continuum_work, e.strain,
                    e.contact_damping, e.friction, e.global_damping, e.local_damping, e.residual());
  } else {
    // A world keeps its energy budget only when the case asks for it
    // (output.energy_budget): the budget's columns stay empty.
    const std::string_view none;
    file_.write_row(world.cycle_count(), world.time(), measures.kinetic_energy, measures.out_of_balance,
                    measures.max_contact_force, measures.contacts, measures.sliding_contacts, measures.time_step_ratio,
                    measures.elastic_energy, measures.kinetic_to_elastic, measures.unbalanced_force,
                    measures.sliding_fraction, measures.mean_stress, measures.deformation_rate,
                    measures.inertial_number, none, none, none, none, none, none, none, none, none);
  }
  file_.flush();
  return measures;
}

ProbesCsv::ProbesCsv(const std::filesystem::path& directory, std::vector<Probe> probes, const TableSizes* resume)
    : file_(directory, "probes.csv", "cycle,time,probe,normal_force,shear_force,touching", resume),
      probes_(std::move(probes)) {}

template <int Dim>
void ProbesCsv::write(const BasicWorld<Dim>& world) {
  for (const Probe& probe : probes_) {
    const std::optional<ContactRecordT<Dim>> contact = world.contact_between(probe.first, probe.second);
    file_.write_row(world.cycle_count(), world.time(), probe.name, contact ? contact->normal_force : 0.0,
                    contact ? contact->shear_force : 0.0, contact.has_value());
  }
  file_.flush();
}

template <int Dim>
void write_contacts_csv(const std::filesystem::path& directory, const BasicWorld<Dim>& world) {
  CsvFile file(directory, "contacts.csv", contact_columns<Dim>());
  write_contact_rows(file, world, {});
  file.flush();
}

template <int Dim>
void write_particles_csv(const std::filesystem::path& directory, const BasicWorld<Dim>& world) {
  CsvFile file(directory, "particles.csv", particle_columns<Dim>());
  write_particle_rows(file, world, {});
  file.flush();
}

template class WallsCsvT<2>;
template class WallsCsvT<3>;
template AssemblyMeasures AssemblyCsv::write(const World&);
template AssemblyMeasures AssemblyCsv::write(const World3&);
template void ProbesCsv::write(const World&);
template void ProbesCsv::write(const World3&);
template void write_contacts_csv(const std::filesystem::path&, const World&);
template void write_contacts_csv(const std::filesystem::path&, const World3&);
template void write_particles_csv(const std::filesystem::path&, const World&);
template void write_particles_csv(const std::filesystem::path&, const World3&);

}  // namespace dem::io
