#include "dem/io/vtk_files.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "vtk_xml.h"

namespace dem::io {
namespace {

template <int Dim>
std::array<double, 3> point3(const Vec<Dim>& v) {
  if constexpr (Dim == 2) {
    return {v.x(), v.y(), 0.0};
  } else {
    return {v.x(), v.y(), v.z()};
  }
}

template <int Dim>
std::array<double, 3> spin3(const Spin<Dim>& spin) {
  if constexpr (Dim == 2) {
    return {0.0, 0.0, spin};
  } else {
    return {spin.x(), spin.y(), spin.z()};
  }
}

// A 2D rotation is an angle about z; as a quaternion (w, x, y, z).
template <int Dim>
Quaternion quaternion(const Orientation<Dim>& rotation) {
  if constexpr (Dim == 2) {
    return Quaternion(Eigen::AngleAxisd(rotation, Eigen::Vector3d::UnitZ()));
  } else {
    return rotation.normalized();
  }
}

// The particle's semi-axes along its body axes and its shape exponent.
template <int Dim>
std::pair<Vec3, double> shape_of(const ParticleDefT<Dim>& particle, PlanarParticle planar) {
  const double r = particle.radius;
  if constexpr (Dim == 2) {
    if (particle.shape.superquadric()) return {Vec3(particle.shape.a, particle.shape.b, 0.0), particle.shape.n};
    return {Vec3(r, r, planar == PlanarParticle::kSphere ? r : 0.0), 2.0};
  } else {
    if (particle.shape.ellipsoid()) return {particle.shape.axes, 2.0};
    return {Vec3(r, r, r), 2.0};
  }
}

// Time and cycle, so ParaView orders the files of a series by themselves too.
template <int Dim>
void add_time(vtk::PolyData& data, const WorldSnapshotT<Dim>& snapshot) {
  vtk::DataArray time{.name = "TimeValue", .type = "Float64"};
  time.add(snapshot.time);
  vtk::DataArray cycle{.name = "cycle", .type = "UInt64"};
  cycle.add(static_cast<std::uint64_t>(snapshot.cycle));
  data.field_data.push_back(std::move(time));
  data.field_data.push_back(std::move(cycle));
}

// The separation from a to b, through the nearest periodic image of b.
template <int Dim>
Vec<Dim> nearest_separation(const Vec<Dim>& a, const Vec<Dim>& b, const PeriodicDefT<Dim>& periodic) {
  Vec<Dim> d = b - a;
  for (int axis = 0; axis < Dim; ++axis) {
    if (!periodic.axes[axis]) continue;
    const double period = periodic.max[axis] - periodic.min[axis];
    d[axis] -= period * std::round(d[axis] / period);
  }
  return d;
}

template <int Dim>
double shear_magnitude_or_signed(const ShearForce<Dim>& shear) {
  if constexpr (Dim == 2) {
    return shear;  // signed along t_i (Cundall & Strack Fig. 3)
  } else {
    return shear.norm();
  }
}

}  // namespace

template <int Dim>
void write_particles_vtp(const std::filesystem::path& file, const WorldSnapshotT<Dim>& snapshot) {
  const auto& particles = snapshot.def.particles;
  // Contacts name particles by id (ids keep gaps after a trim): each id's entry.
  const std::vector<std::int32_t> entry = snapshot_entries_by_id(snapshot);
  std::vector<int> coordination(particles.size(), 0);
  for (const ContactSnapshotT<Dim>& c : snapshot.contacts) {
    if (!c.touching) continue;
    ++coordination[entry[c.first]];
    if (!c.with_wall) ++coordination[entry[c.second]];
  }

  vtk::PolyData data;
  vtk::DataArray id{.name = "id", .type = "Int32"};
  vtk::DataArray material{.name = "material", .type = "Int32"};
  vtk::DataArray radius{.name = "radius", .type = "Float64"};
  vtk::DataArray velocity{.name = "velocity", .type = "Float64", .components = 3};
  vtk::DataArray angular_velocity{.name = "angular_velocity", .type = "Float64", .components = 3};
  vtk::DataArray contacts{.name = "coordination", .type = "Int32"};
  vtk::DataArray orientation{.name = "orientation", .type = "Float64", .components = 4};
  vtk::DataArray semi_axes{.name = "semi_axes", .type = "Float64", .components = 3};
  vtk::DataArray exponent{.name = "exponent", .type = "Float64"};
  vtk::DataArray shape_tensor{.name = "shape_tensor", .type = "Float64", .components = 9};
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const ParticleDefT<Dim>& p = particles[i];
    data.points.push_back(point3<Dim>(p.position));
    data.verts.add({static_cast<std::int64_t>(i)});
    id.add(static_cast<std::int64_t>(snapshot_particle_id(snapshot, i).value()));
    material.add(static_cast<std::int64_t>(p.material.value()));
    radius.add(p.radius);
    velocity.add(point3<Dim>(p.velocity));
    angular_velocity.add(spin3<Dim>(p.angular_velocity));
    contacts.add(coordination[i]);
    const Quaternion q = quaternion<Dim>(snapshot.rotation[i]);
    orientation.add(std::array<double, 4>{q.w(), q.x(), q.y(), q.z()});
    const auto [axes, n] = shape_of<Dim>(p, snapshot.def.planar_particle);
    semi_axes.add(std::array<double, 3>{axes.x(), axes.y(), axes.z()});
    exponent.add(n);
    const Eigen::Matrix3d body = q.toRotationMatrix();  // columns: the body axes in the world
    for (int j = 0; j < 3; ++j) {
      const Vec3 axis = body.col(j) * axes[j];
      shape_tensor.add(std::array<double, 3>{axis.x(), axis.y(), axis.z()});
    }
  }
  data.point_data = {id,       material,    radius,    velocity, angular_velocity,
                     contacts, orientation, semi_axes, exponent, shape_tensor};
  data.point_scalars = "radius";
  add_time(data, snapshot);
  vtk::DataArray material_names{.name = "material_names", .type = "String"};
  for (const MaterialDef& m : snapshot.def.materials) material_names.add(m.name);
  data.field_data.push_back(std::move(material_names));
  vtk::write_file(file, vtk::to_xml(data));
}

template <int Dim>
void write_contacts_vtp(const std::filesystem::path& file, const WorldSnapshotT<Dim>& snapshot) {
  const auto& particles = snapshot.def.particles;
  const std::vector<std::int32_t> entry = snapshot_entries_by_id(snapshot);  // each id's particle
  vtk::PolyData data;
  vtk::DataArray normal_force{.name = "normal_force", .type = "Float64"};
  vtk::DataArray shear_force{.name = "shear_force", .type = "Float64"};
  vtk::DataArray sliding{.name = "sliding", .type = "UInt8"};
  vtk::DataArray first{.name = "first", .type = "Int32"};
  vtk::DataArray second{.name = "second", .type = "Int32"};
  vtk::DataArray wall_contact{.name = "wall_contact", .type = "UInt8"};
  vtk::DataArray overlap{.name = "overlap", .type = "Float64"};
  vtk::DataArray normal{.name = "normal", .type = "Float64", .components = 3};
  vtk::DataArray point{.name = "point", .type = "Float64", .components = 3};
  for (const ContactSnapshotT<Dim>& c : snapshot.contacts) {
    if (!c.touching) continue;
    const Vec<Dim>& from = particles[entry[c.first]].position;
    const Vec<Dim> to = c.with_wall ? c.point
                                    : Vec<Dim>(from + nearest_separation<Dim>(from, particles[entry[c.second]].position,
                                                                              snapshot.def.periodic));
    const auto start = static_cast<std::int64_t>(data.points.size());
    data.points.push_back(point3<Dim>(from));
    data.points.push_back(point3<Dim>(to));
    data.lines.add({start, start + 1});
    normal_force.add(c.normal_force);
    shear_force.add(shear_magnitude_or_signed<Dim>(c.shear_force));
    sliding.add(static_cast<std::int64_t>(c.sliding));
    first.add(static_cast<std::int64_t>(c.first));
    second.add(static_cast<std::int64_t>(c.second));
    wall_contact.add(static_cast<std::int64_t>(c.with_wall));
    overlap.add(c.overlap);
    normal.add(point3<Dim>(c.normal));
    point.add(point3<Dim>(c.point));
  }
  data.cell_data = {normal_force, shear_force, sliding, first, second, wall_contact, overlap, normal, point};
  add_time(data, snapshot);
  vtk::write_file(file, vtk::to_xml(data));
}

template <int Dim>
void write_walls_vtp(const std::filesystem::path& file, const WorldSnapshotT<Dim>& snapshot) {
  vtk::PolyData data;
  vtk::DataArray wall{.name = "wall", .type = "Int32"};
  vtk::DataArray name{.name = "name", .type = "String"};
  vtk::DataArray normal_force{.name = "normal_force", .type = "Float64"};
  vtk::DataArray contacts{.name = "contacts", .type = "Int32"};
  vtk::DataArray force{.name = "force", .type = "Float64", .components = 3};
  vtk::DataArray velocity{.name = "velocity", .type = "Float64", .components = 3};
  auto add_cell_data = [&](std::size_t w) {
    const WallSnapshotT<Dim>& measured = snapshot.walls[w];
    wall.add(static_cast<std::int64_t>(w));
    name.add(snapshot.def.walls[w].name);
    normal_force.add(measured.normal_force);
    contacts.add(measured.contacts);
    force.add(point3<Dim>(measured.force));
    velocity.add(point3<Dim>(measured.last_velocity));
  };
  auto add_point = [&](const Vec<Dim>& p) {
    data.points.push_back(point3<Dim>(p));
    return static_cast<std::int64_t>(data.points.size() - 1);
  };
  for (std::size_t w = 0; w < snapshot.def.walls.size(); ++w) {
    const WallDefT<Dim>& def = snapshot.def.walls[w];
    if constexpr (Dim == 2) {
      data.lines.add({add_point(def.point + def.h1 * def.direction), add_point(def.point + def.h2 * def.direction)});
      add_cell_data(w);
    } else if (!def.triangles.empty()) {
      for (const auto& triangle : def.triangles) {
        data.polys.add({add_point(triangle[0]), add_point(triangle[1]), add_point(triangle[2])});
        add_cell_data(w);
      }
    } else {
      const Vec3& u = def.direction;
      const Vec3& v = def.direction2;
      data.polys.add({add_point(def.point + def.h1 * u + def.k1 * v), add_point(def.point + def.h2 * u + def.k1 * v),
                      add_point(def.point + def.h2 * u + def.k2 * v), add_point(def.point + def.h1 * u + def.k2 * v)});
      add_cell_data(w);
    }
  }
  data.cell_data = {wall, name, normal_force, contacts, force, velocity};
  add_time(data, snapshot);
  vtk::write_file(file, vtk::to_xml(data));
}

template void write_particles_vtp(const std::filesystem::path&, const WorldSnapshotT<2>&);
template void write_particles_vtp(const std::filesystem::path&, const WorldSnapshotT<3>&);
template void write_contacts_vtp(const std::filesystem::path&, const WorldSnapshotT<2>&);
template void write_contacts_vtp(const std::filesystem::path&, const WorldSnapshotT<3>&);
template void write_walls_vtp(const std::filesystem::path&, const WorldSnapshotT<2>&);
template void write_walls_vtp(const std::filesystem::path&, const WorldSnapshotT<3>&);

}  // namespace dem::io
