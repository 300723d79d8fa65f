#include "dem/io/csv_writers.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

namespace dem::io {
namespace {

constexpr const char* kWallsHeader2 =
    "cycle,time,wall,fx,fy,moment,normal_force,contacts,eccentricity,x,y,dx,dy,normal_stress,settlement";
constexpr const char* kWallsHeader3 =
    "cycle,time,wall,fx,fy,fz,moment_x,moment_y,moment_z,normal_force,contacts,eccentricity_u,eccentricity_v,"
    "x,y,z,dx,dy,dz,normal_stress,settlement";

// contacts.csv's columns follow the record's one field list
// (ContactRecordFields, dem/measures.h): the bodies as first, second_kind,
// second; then, in list order, a column per number or flag and one per
// axis of a vector.
template <class T>
constexpr bool kIsBody = std::is_same_v<T, ParticleId> || std::is_same_v<T, WallId>;

template <int Dim>
constexpr std::size_t body_fields() {
  return std::apply(
      [](const auto&... f) {
        return (std::size_t{0} + ... +
                (kIsBody<std::remove_cvref_t<decltype(ContactRecordT<Dim>{}.*f.member)>> ? 1 : 0));
      },
      ContactRecordFields<Dim>::list);
}
// The three written as first, second_kind, second (write_contacts_csv).
static_assert(body_fields<2>() == 3 && body_fields<3>() == 3,
              "a ContactRecordT id field other than first, second_particle, second_wall: give it its contacts.csv "
              "columns");

// The vectors contacts.csv had before the field list keep their short
// column names (x, nx, tangential_x); any other is <name>_x.
std::string axis_stem(std::string_view field) {
  if (field == "point") return "";
  if (field == "normal") return "n";
  if (field == "tangential_force") return "tangential_";
  return std::string(field) + "_";
}

template <int Dim>
std::string contacts_header() {
  std::string header = "first,second_kind,second";
  std::apply(
      [&](const auto&... f) {
        const auto columns = [&](const auto& field) {
          using T = std::remove_cvref_t<decltype(ContactRecordT<Dim>{}.*field.member)>;
          if constexpr (kIsBody<T>) {
            return;
          } else if constexpr (std::is_same_v<T, Vec<Dim>>) {
            for (int k = 0; k < Dim; ++k) {
              header += ',';
              header += axis_stem(field.name);
              header += "xyz"[k];
            }
          } else {
            static_assert(std::is_arithmetic_v<T>, "a ContactRecordT member with no contacts.csv columns");
            header += ",";
            header += field.name;
          }
        };
        (columns(f), ...);
      },
      ContactRecordFields<Dim>::list);
  return header;
}

template <int Dim>
void add_measures(std::string& line, const ContactRecordT<Dim>& c) {
  std::apply(
      [&](const auto&... f) {
        const auto cells = [&](const auto& field) {
          const auto& value = c.*field.member;
          using T = std::remove_cvref_t<decltype(value)>;
          if constexpr (kIsBody<T>) {
            return;
          } else if constexpr (std::is_same_v<T, Vec<Dim>>) {
            for (int k = 0; k < Dim; ++k) CsvFile::add_field(line, value[k]);
          } else {
            CsvFile::add_field(line, value);
          }
        };
        (cells(f), ...);
      },
      ContactRecordFields<Dim>::list);
}
constexpr const char* kParticlesHeader2 = "id,x,y,radius,vx,vy,angular_velocity,rotation,material,a,b,n";
constexpr const char* kParticlesHeader3 =
    "id,x,y,z,radius,vx,vy,vz,angular_velocity_x,angular_velocity_y,angular_velocity_z,rotation_w,rotation_x,"
    "rotation_y,rotation_z,material,a1,a2,a3";

}  // namespace

template <int Dim>
WallsCsvT<Dim>::WallsCsvT(const std::filesystem::path& directory, const TableSizes* resume)
    : file_(directory, "walls.csv", Dim == 2 ? kWallsHeader2 : kWallsHeader3, resume) {}

template <int Dim>
void WallsCsvT<Dim>::write(const BasicWorld<Dim>& world) {
  for (const WallMeasureT<Dim>& m : world.wall_measures()) {
    const std::string& name = world.wall(m.wall).name;
    const double stress = m.normal_force / world.wall_area(m.wall);
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
            "inertial_number,gravity_work,wall_work,strain_energy,contact_damping,friction,global_damping,local_"
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
                    measures.inertial_number, e.gravity_work, e.wall_work, e.strain, e.contact_damping, e.friction,
                    e.global_damping, e.local_damping, e.residual());
  } else {
    // A world keeps its energy budget only when the case asks for it
    // (output.energy_budget): the budget's columns stay empty.
    const std::string_view none;
    file_.write_row(world.cycle_count(), world.time(), measures.kinetic_energy, measures.out_of_balance,
                    measures.max_contact_force, measures.contacts, measures.sliding_contacts, measures.time_step_ratio,
                    measures.elastic_energy, measures.kinetic_to_elastic, measures.unbalanced_force,
                    measures.sliding_fraction, measures.mean_stress, measures.deformation_rate,
                    measures.inertial_number, none, none, none, none, none, none, none, none);
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
  CsvFile file(directory, "contacts.csv", contacts_header<Dim>());
  for (const ContactRecordT<Dim>& c : world.contacts()) {
    std::string line;
    CsvFile::add_field(line, c.first);
    if (c.second_wall != kInvalidId) {
      CsvFile::add_field(line, "wall");
      CsvFile::add_field(line, world.wall(c.second_wall).name);
    } else {
      CsvFile::add_field(line, "particle");
      CsvFile::add_field(line, c.second_particle);
    }
    add_measures(line, c);
    file.write_built_row(std::move(line));
  }
  file.flush();
}

template <int Dim>
void write_particles_csv(const std::filesystem::path& directory, const BasicWorld<Dim>& world) {
  CsvFile file(directory, "particles.csv", Dim == 2 ? kParticlesHeader2 : kParticlesHeader3);
  const ParticleViewT<Dim> p = world.particles();
  // The particles' materials and shapes are in the snapshot only (the
  // particle view has the dynamic state); a particles.csv is written once.
  const WorldSnapshotT<Dim> snapshot = world.snapshot();
  for (std::size_t k = 0; k < snapshot.def.particles.size(); ++k) {
    const ParticleId id = world.particle_ids()[k];  // the snapshot lists the particles in id order
    const ParticleDefT<Dim>& def = snapshot.def.particles[k];
    const std::string& material = snapshot.def.materials[def.material.index()].name;
    const double r = p.radius[id];
    if constexpr (Dim == 2) {
      // A superquadric's semi-axes and exponent (Miyata eq. 34; its angle is the rotation); a disc's R, R, 2.
      const bool shaped = def.shape.superquadric();
      file.write_row(id.value(), p.position[id].x(), p.position[id].y(), r, p.velocity[id].x(), p.velocity[id].y(),
                     p.angular_velocity[id], p.rotation[id], material, shaped ? def.shape.a : r,
                     shaped ? def.shape.b : r, shaped ? def.shape.n : 2.0);
    } else {
      // An ellipsoid's semi-axes along its body axes (eq. 43; turned by the rotation); a sphere's R, R, R.
      const Quaternion& q = p.rotation[id];
      const Vec3 axes = def.shape.ellipsoid() ? def.shape.axes : Vec3(r, r, r);
      file.write_row(id.value(), p.position[id].x(), p.position[id].y(), p.position[id].z(), r, p.velocity[id].x(),
                     p.velocity[id].y(), p.velocity[id].z(), p.angular_velocity[id].x(), p.angular_velocity[id].y(),
                     p.angular_velocity[id].z(), q.w(), q.x(), q.y(), q.z(), material, axes.x(), axes.y(), axes.z());
    }
  }
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
