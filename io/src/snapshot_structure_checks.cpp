#include "snapshot_structure_checks.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "dem/io/snapshot_conversion.h"
#include "snapshot_checks.h"
#include "snapshot_contacts.h"
#include "snapshot_packing.h"

namespace dem::io {

namespace {

template <int Dim>
void check_settings(Problems& problems, const proto::SnapshotSettings& s, const Counts& n) {
  for (int i = 0; i < s.contact_models_size(); ++i) {
    const auto& c = s.contact_models(i);
    const bool default_law = c.material_a() == kInvalidId && c.material_b() == kInvalidId;
    if (!default_law && (!in_range(c.material_a(), n.materials) || !in_range(c.material_b(), n.materials))) {
      problems.add("settings.contact_models[" + std::to_string(i) + "]",
                   "material ids (" + std::to_string(c.material_a()) + ", " + std::to_string(c.material_b()) +
                       ") out of range for " + std::to_string(n.materials) + " materials");
    }
  }
  check_array(problems, "settings.gravity", s.gravity(), 1, Dim);
  check_length(problems, "settings.periodic_axes", s.periodic_axes(), Dim);
  check_array(problems, "settings.periodic_min", s.periodic_min(), 1, Dim);
  check_array(problems, "settings.periodic_max", s.periodic_max(), 1, Dim);
  check_finite(problems, "settings.time_step_fraction", s.time_step_fraction());
  check_finite(problems, "settings.fixed_time_step", s.fixed_time_step());
  check_finite(problems, "settings.contact_tolerance", s.contact_tolerance());
}

template <int Dim>
void check_particles(Problems& problems, const proto::SnapshotParticles& p, const Counts& n) {
  check_array(problems, "particles.position", p.position(), n.particles, Dim);
  check_array(problems, "particles.velocity", p.velocity(), n.particles, Dim);
  check_array(problems, "particles.angular_velocity", p.angular_velocity(), n.particles, width<Spin<Dim>>);
  check_array(problems, "particles.rotation", p.rotation(), n.particles, width<Orientation<Dim>>);
  check_array(problems, "particles.force", p.force(), n.particles, Dim);
  check_array(problems, "particles.moment", p.moment(), n.particles, width<Spin<Dim>>);
  check_array(problems, "particles.shape", p.shape(), n.particles, kShapeWidth<Dim>);
  if (!check_length(problems, "particles.material", p.material(), n.particles)) return;
  for (int i = 0; i < p.radius_size(); ++i) {
    if (!(p.radius(i) > 0.0) || !std::isfinite(p.radius(i))) {
      problems.add("particles.radius[" + std::to_string(i) + "]", "must be a finite number > 0");
    }
    if (!in_range(p.material(i), n.materials)) {
      problems.add("particles.material[" + std::to_string(i) + "]", "material " + std::to_string(p.material(i)) +
                                                                        " out of range for " +
                                                                        std::to_string(n.materials) + " materials");
    }
  }
}

template <int Dim>
void check_wall(Problems& problems, const proto::SnapshotWall& w, int index, const Counts& n) {
  const std::string path = "walls[" + std::to_string(index) + "]";
  const std::size_t spin = width<Spin<Dim>>;
  for (const auto& [name, values, item_width] :
       {std::tuple{"point", &w.point(), std::size_t{Dim}},
        {"direction", &w.direction(), std::size_t{Dim}},
        {"direction2", &w.direction2(), std::size_t{Dim == 3 ? 3u : 0u}},
        {"motion_velocity", &w.motion_velocity(), std::size_t{Dim}},
        {"motion_angular_velocity", &w.motion_angular_velocity(), spin},
        {"initial_point", &w.initial_point(), std::size_t{Dim}},
        {"last_velocity", &w.last_velocity(), std::size_t{Dim}},
        {"last_angular_velocity", &w.last_angular_velocity(), spin},
        {"force", &w.force(), std::size_t{Dim}},
        {"moment", &w.moment(), spin},
        {"normal_force_arm", &w.normal_force_arm(), width<Eccentricity<Dim>>}}) {
    check_array(problems, path + "." + name, *values, 1, item_width);
  }
  if (!in_range(w.material(), n.materials)) {
    problems.add(path + ".material", "material " + std::to_string(w.material()) + " out of range");
  }
  const int per_face = Dim == 3 ? 9 : 1;
  if (Dim == 2 && w.triangles_size() > 0) problems.add(path + ".triangles", "a 2D wall has no triangle faces");
  if (Dim == 3) {
    check_array(problems, path + ".triangles", w.triangles(), static_cast<std::size_t>(w.triangles_size() / per_face),
                static_cast<std::size_t>(per_face));
  }
  for (const auto& [name, value] :
       {std::pair{"h1", w.h1()}, {"h2", w.h2()}, {"k1", w.k1()}, {"k2", w.k2()}, {"normal_force", w.normal_force()}}) {
    check_finite(problems, path + "." + name, value);
  }
}

}  // namespace

template <int Dim>
void check_structure(const proto::Snapshot& m, Problems& problems, const ResourceLimits& limits) {
  if (m.format() != kSnapshotFormat) {
    problems.add("format", "is \"" + m.format() + "\", not \"" + kSnapshotFormat + "\": not a dem snapshot");
    return;  // nothing else can be trusted
  }
  if (m.version() != kSnapshotVersion) {
    problems.add("version", std::to_string(m.version()) + " is not supported (this program reads version " +
                                std::to_string(kSnapshotVersion) + ")");
    return;
  }
  if (m.dimension() != Dim) {
    problems.add("dimension",
                 "the snapshot is " + std::to_string(m.dimension()) + "D, expected " + std::to_string(Dim) + "D");
    return;
  }
  for (const auto& [path, message] : snapshot_value_problems(m, limits)) problems.add(path, message);
  Counts n;
  n.particles = static_cast<std::size_t>(m.particles().radius_size());
  n.particle_ids = n.particles;
  if (m.particle_ids_size() > 0) {
    const auto& ids = m.particle_ids();
    if (static_cast<std::size_t>(ids.size()) != n.particles) {
      problems.add("particle_ids",
                   "has " + std::to_string(ids.size()) + " entries for " + std::to_string(n.particles) + " particles");
    }
    for (int i = 0; i < ids.size(); ++i) {
      if (ids[i] < 0 || (i > 0 && ids[i] <= ids[i - 1])) {
        problems.add("particle_ids[" + std::to_string(i) + "]", "ids must ascend from 0");
        break;
      }
    }
    n.particle_ids = static_cast<std::size_t>(std::max(ids[ids.size() - 1], 0)) + 1;
  }
  if (m.particle_id_count() < 0 ||
      (m.particle_id_count() > 0 && static_cast<std::size_t>(m.particle_id_count()) < n.particle_ids)) {
    problems.add("particle_id_count", "is below the particle ids");
  } else if (m.particle_id_count() > 0) {
    n.particle_ids = static_cast<std::size_t>(m.particle_id_count());
  }
  n.walls = static_cast<std::size_t>(m.walls_size());
  n.contacts = static_cast<std::size_t>(m.contacts().first_size());
  n.materials = static_cast<std::size_t>(m.settings().materials_size());
  check_settings<Dim>(problems, m.settings(), n);
  check_particles<Dim>(problems, m.particles(), n);
  for (int i = 0; i < m.walls_size(); ++i) check_wall<Dim>(problems, m.walls(i), i, n);
  check_contacts<Dim>(problems, m.contacts(), n);
  for (const auto& [name, value] : {std::pair{"energy.initial_kinetic", m.energy().initial_kinetic()},
                                    {"energy.gravity_work", m.energy().gravity_work()},
                                    {"energy.wall_work", m.energy().wall_work()},
                                    {"energy.kinetic", m.energy().kinetic()},
                                    {"energy.strain", m.energy().strain()},
                                    {"energy.contact_damping", m.energy().contact_damping()},
                                    {"energy.friction", m.energy().friction()},
                                    {"energy.global_damping", m.energy().global_damping()},
                                    {"energy.local_damping", m.energy().local_damping()},
                                    {"energy.removed", m.energy().removed()},
                                    {"tangential_work", m.tangential_work()}}) {
    check_finite(problems, name, value);
  }
  if (m.reference_positions_size() > 0) {
    check_array(problems, "reference_positions", m.reference_positions(), n.particles, Dim);
  }
  if (m.has_box_control()) {
    const proto::SnapshotBoxControl& box = m.box_control();
    if (box.axes_size() != Dim) {
      problems.add("box_control.axes",
                   "has " + std::to_string(box.axes_size()) + " axes, expected " + std::to_string(Dim));
    }
    for (int i = 0; i < box.axes_size(); ++i) {
      const std::string path = "box_control.axes[" + std::to_string(i) + "]";
      if (!in_range(box.axes(i).lower(), n.walls)) problems.add(path + ".lower", "names no wall");
      if (!in_range(box.axes(i).upper(), n.walls)) problems.add(path + ".upper", "names no wall");
      if (box.axes(i).control() < 0 || box.axes(i).control() > 2) problems.add(path + ".control", "must be 0, 1 or 2");
    }
    if (box.path() < 0 || box.path() > 2) problems.add("box_control.path", "must be 0, 1 or 2");
    check_length(problems, "box_control.reference_extent", box.reference_extent(), Dim);
  }
  if (m.particle_order_size() > 0) {
    if (static_cast<std::size_t>(m.particle_order_size()) != n.particles) {
      problems.add("particle_order", "has " + std::to_string(m.particle_order_size()) + " entries for " +
                                         std::to_string(n.particles) + " particles");
    } else {
      std::vector<bool> seen(n.particle_ids, false);
      for (int i = 0; i < m.particle_order_size(); ++i) {
        const std::int32_t id = m.particle_order(i);
        if (!in_range(id, n.particle_ids) || seen[static_cast<std::size_t>(id)]) {
          problems.add("particle_order[" + std::to_string(i) + "]", "is not a permutation of the particle ids");
          break;
        }
        seen[static_cast<std::size_t>(id)] = true;
      }
    }
  }
  check_finite(problems, "particle_travel", m.particle_travel());
  check_finite(problems, "wall_travel", m.wall_travel());
  check_finite(problems, "time", m.time());
  if (!(m.time_step() > 0.0) || !std::isfinite(m.time_step())) problems.add("time_step", "must be a finite number > 0");
  check_finite(problems, "critical_time_step", m.critical_time_step());
}

template void check_structure<2>(const proto::Snapshot&, Problems&, const ResourceLimits&);
template void check_structure<3>(const proto::Snapshot&, Problems&, const ResourceLimits&);

}  // namespace dem::io
