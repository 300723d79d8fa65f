#include "world_rows.h"

#include <cstddef>
#include <string>
#include <tuple>
#include <type_traits>

namespace dem::io {
namespace {

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
// The three written as first, second_kind, second (write_contact_rows).
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
std::string contact_columns() {
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
std::string particle_columns() {
  return Dim == 2 ? kParticlesHeader2 : kParticlesHeader3;
}

template <int Dim>
void write_contact_rows(CsvFile& file, const BasicWorld<Dim>& world, std::string_view leading) {
  for (const ContactRecordT<Dim>& c : world.contacts()) {
    std::string line(leading);
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
}

template <int Dim>
void write_particle_rows(CsvFile& file, const BasicWorld<Dim>& world, std::string_view leading) {
  const ParticleViewT<Dim> p = world.particles();
  // The particles' materials and shapes are in the snapshot only (the
  // particle view has the dynamic state): a table of every particle is
  // written seldom.
  const WorldSnapshotT<Dim> snapshot = world.snapshot();
  for (std::size_t k = 0; k < snapshot.def.particles.size(); ++k) {
    const ParticleId id = world.particle_ids()[k];  // the snapshot lists the particles in id order
    const ParticleDefT<Dim>& def = snapshot.def.particles[k];
    const std::string& material = snapshot.def.materials[def.material.index()].name;
    const double r = p.radius[id];
    std::string line(leading);
    const auto add = [&line](const auto&... cells) { (CsvFile::add_field(line, cells), ...); };
    if constexpr (Dim == 2) {
      // A superquadric's semi-axes and exponent (Miyata eq. 34; its angle is the rotation); a disc's R, R, 2.
      const bool shaped = def.shape.superquadric();
      add(id.value(), p.position[id].x(), p.position[id].y(), r, p.velocity[id].x(), p.velocity[id].y(),
          p.angular_velocity[id], p.rotation[id], material, shaped ? def.shape.a : r, shaped ? def.shape.b : r,
          shaped ? def.shape.n : 2.0);
    } else {
      // An ellipsoid's semi-axes along its body axes (eq. 43; turned by the rotation); a sphere's R, R, R.
      const Quaternion& q = p.rotation[id];
      const Vec3 axes = def.shape.ellipsoid() ? def.shape.axes : Vec3(r, r, r);
      add(id.value(), p.position[id].x(), p.position[id].y(), p.position[id].z(), r, p.velocity[id].x(),
          p.velocity[id].y(), p.velocity[id].z(), p.angular_velocity[id].x(), p.angular_velocity[id].y(),
          p.angular_velocity[id].z(), q.w(), q.x(), q.y(), q.z(), material, axes.x(), axes.y(), axes.z());
    }
    file.write_built_row(std::move(line));
  }
}

template std::string contact_columns<2>();
template std::string contact_columns<3>();
template std::string particle_columns<2>();
template std::string particle_columns<3>();
template void write_contact_rows(CsvFile&, const World&, std::string_view);
template void write_contact_rows(CsvFile&, const World3&, std::string_view);
template void write_particle_rows(CsvFile&, const World&, std::string_view);
template void write_particle_rows(CsvFile&, const World3&, std::string_view);

}  // namespace dem::io
