#include "dem/io/csv_writers.h"

#include <utility>

namespace dem::io {

WallsCsv::WallsCsv(const std::filesystem::path& directory)
    : file_(directory, "walls.csv", "cycle,time,wall,fx,fy,moment,normal_force,contacts,eccentricity,x,y,dx,dy") {}

void WallsCsv::write(const World& world) {
  for (const WallMeasure& measure : world.wall_measures()) {
    file_.write_row(world.cycle_count(), world.time(), world.wall(measure.wall).name, measure.force.x(),
                    measure.force.y(), measure.moment, measure.normal_force, measure.contacts, measure.eccentricity,
                    measure.point.x(), measure.point.y(), measure.displacement.x(), measure.displacement.y());
  }
  file_.flush();
}

AssemblyCsv::AssemblyCsv(const std::filesystem::path& directory)
    : file_(directory, "assembly.csv",
            "cycle,time,kinetic_energy,out_of_balance,max_contact_force,contacts,sliding_contacts") {}

void AssemblyCsv::write(const World& world) {
  const AssemblyMeasures measures = world.assembly_measures();
  file_.write_row(world.cycle_count(), world.time(), measures.kinetic_energy, measures.out_of_balance,
                  measures.max_contact_force, measures.contacts, measures.sliding_contacts);
  file_.flush();
}

ProbesCsv::ProbesCsv(const std::filesystem::path& directory, std::vector<Probe> probes)
    : file_(directory, "probes.csv", "cycle,time,probe,normal_force,shear_force,touching"),
      probes_(std::move(probes)) {}

void ProbesCsv::write(const World& world) {
  for (const Probe& probe : probes_) {
    const std::optional<ContactRecord> contact = world.contact_between(probe.first, probe.second);
    file_.write_row(world.cycle_count(), world.time(), probe.name, contact ? contact->normal_force : 0.0,
                    contact ? contact->shear_force : 0.0, contact.has_value());
  }
  file_.flush();
}

void write_contacts_csv(const std::filesystem::path& directory, const World& world) {
  CsvFile file(directory, "contacts.csv",
               "first,second_kind,second,x,y,nx,ny,overlap,normal_force,shear_force,normal_damping,"
               "shear_damping,sliding");
  for (const ContactRecord& contact : world.contacts()) {
    const bool wall = contact.second_wall != kInvalidId;
    const auto fields = [&](const auto& second) {
      file.write_row(contact.first, wall ? "wall" : "particle", second, contact.point.x(), contact.point.y(),
                     contact.normal.x(), contact.normal.y(), contact.overlap, contact.normal_force, contact.shear_force,
                     contact.normal_damping, contact.shear_damping, contact.sliding);
    };
    if (wall) {
      fields(world.wall(contact.second_wall).name);
    } else {
      fields(contact.second_particle);
    }
  }
  file.flush();
}

void write_particles_csv(const std::filesystem::path& directory, const World& world) {
  CsvFile file(directory, "particles.csv", "id,x,y,radius,vx,vy,angular_velocity,rotation");
  const ParticleView particles = world.particles();
  for (ParticleId id = 0; id < world.particle_count(); ++id) {
    file.write_row(id, particles.position[id].x(), particles.position[id].y(), particles.radius[id],
                   particles.velocity[id].x(), particles.velocity[id].y(), particles.angular_velocity[id],
                   particles.rotation[id]);
  }
  file.flush();
}

}  // namespace dem::io
