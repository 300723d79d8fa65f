#include "dem/service/engine_readout.h"

#include <algorithm>
#include <cmath>

#include "contact_entry.h"
#include "dem/law_traits.h"
#include "dem/service/command_error.h"

namespace dem::service {

namespace {

// Engine quantities as wire vectors: 2D vectors get z = 0, 2D spins
// (moments, angular velocities) are about z.
protocol::Vector3 vector3(const Vec2& v) { return {v.x(), v.y(), 0.0}; }
protocol::Vector3 vector3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
protocol::Vector3 spin3(double about_z) { return {0.0, 0.0, about_z}; }
protocol::Vector3 spin3(const Vec3& v) { return vector3(v); }

template <int Dim>
protocol::WallForce to_wall_force(const BasicWorld<Dim>& world, const WallMeasureT<Dim>& m) {
  const WallDefT<Dim>& def = world.wall(m.wall);
  protocol::WallForce w;
  w.name = def.name;
  w.id = m.wall.value();
  w.force = vector3(m.force);
  w.moment = spin3(m.moment);
  w.normal_force = m.normal_force;
  w.area = world.wall_area(m.wall);
  w.normal_stress = world.wall_stress(m.wall);
  w.position = vector3(m.point);
  w.displacement = vector3(m.displacement);
  w.settlement = world.wall_settlement(m.wall) + 0.0;  // + 0.0: no "-0" for a wall at rest
  w.contacts = m.contacts;
  return w;
}

template <int Dim>
bool inside(const ContactRecordT<Dim>& c, const ContactFilter& filter) {
  if (filter.wall && c.second_wall != *filter.wall) return false;
  if (filter.particle && c.first != *filter.particle && c.second_particle != *filter.particle) return false;
  if (filter.min_normal_force && !(c.normal_force > *filter.min_normal_force)) return false;
  if (filter.box_min && filter.box_max) {
    const protocol::Vector3 p = vector3(c.point);
    const protocol::Vector3& lo = *filter.box_min;
    const protocol::Vector3& hi = *filter.box_max;
    if (p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y) return false;
    if (Dim == 3 && (p.z < lo.z || p.z > hi.z)) return false;
  }
  return true;
}

}  // namespace

template <int Dim>
protocol::WallForce read_wall(const BasicWorld<Dim>& world, WallId wall) {
  // wall_measures() measures every wall; they are few.
  return to_wall_force(world, world.wall_measures().at(wall.index()));
}

template <int Dim>
std::vector<protocol::WallForce> read_walls(const BasicWorld<Dim>& world) {
  std::vector<protocol::WallForce> walls;
  for (const WallMeasureT<Dim>& m : world.wall_measures()) walls.push_back(to_wall_force(world, m));
  return walls;
}

template <int Dim>
protocol::ContactStats read_contact_stats(const BasicWorld<Dim>& world) {
  protocol::ContactStats s;
  const std::vector<ContactRecordT<Dim>> contacts = world.contacts();
  s.particles = world.particle_count();
  s.contacts = static_cast<std::int32_t>(contacts.size());
  double sum = 0.0;
  for (const ContactRecordT<Dim>& c : contacts) {
    if (c.second_wall != kInvalidId) ++s.wall_contacts;
    if (c.sliding) ++s.sliding_contacts;
    sum += c.normal_force;
    s.max_normal_force = std::max(s.max_normal_force, c.normal_force);
  }
  if (s.contacts > 0) {
    s.sliding_fraction = static_cast<double>(s.sliding_contacts) / s.contacts;
    s.mean_normal_force = sum / s.contacts;
  }
  if (s.particles > 0) {
    // Each particle-particle contact counts for both particles (Randall 1989).
    s.coordination_number = (2.0 * (s.contacts - s.wall_contacts) + s.wall_contacts) / s.particles;
  }
  s.histogram_bin_width = kHistogramBinWidth;
  s.histogram.assign(kHistogramBins, 0);
  if (s.mean_normal_force > 0.0) {
    for (const ContactRecordT<Dim>& c : contacts) {
      const double f = c.normal_force / s.mean_normal_force;
      const int bin = f <= 0.0 ? 0 : std::min(kHistogramBins - 1, static_cast<int>(f / kHistogramBinWidth));
      ++s.histogram[static_cast<std::size_t>(bin)];
    }
  }
  const AssemblyMeasures assembly = world.assembly_measures();
  s.kinetic_energy = assembly.kinetic_energy;
  s.out_of_balance = assembly.out_of_balance;
  s.elastic_energy = assembly.elastic_energy;
  s.kinetic_to_elastic = assembly.kinetic_to_elastic;
  s.unbalanced_force = assembly.unbalanced_force;
  s.mean_stress = assembly.mean_stress;
  s.inertial_number = assembly.inertial_number;
  return s;
}

template <int Dim>
std::vector<protocol::ContactEntry> query_contacts(const BasicWorld<Dim>& world, const ContactFilter& filter) {
  if (filter.particle) {
    if (const auto missing = world.missing_particle(*filter.particle)) {
      throw CommandError(protocol::ReplyStatus::kNotFound, *missing);
    }
  }
  std::vector<protocol::ContactEntry> entries;
  // One wall's: a pass over its rows, not over every contact.
  for (const ContactRecordT<Dim>& c : filter.wall ? world.wall_contacts(*filter.wall) : world.contacts()) {
    if (inside(c, filter)) entries.push_back(to_entry(c));
  }
  return entries;
}

template <int Dim>
std::optional<ServoLimits> default_servo_limits(const BasicWorld<Dim>& world, WallId wall,
                                                const std::vector<ContactModelDef>& contact_models) {
  double stiffness = 0.0;
  for (const ContactModelDef& model : contact_models) {
    if (!is_hertz(model.law)) {
      stiffness = std::max(stiffness, model.linear.normal_stiffness);
    }
  }
  const auto radii = world.particles().radius;
  if (!(stiffness > 0.0) || radii.empty()) return std::nullopt;
  double mean_radius = 0.0;
  for (const double r : radii) mean_radius += r;
  mean_radius /= static_cast<double>(radii.size());
  // Discs side by side along a 2D wall; spheres packed on a 3D one.
  const double area = world.wall_area(wall);
  const double most_contacts =
      std::max(1.0, Dim == 2 ? area / (2.0 * mean_radius) : area / (4.0 * mean_radius * mean_radius));
  const double dt = world.time_step();
  return ServoLimits{0.5 / (stiffness * most_contacts * dt), 0.05 * mean_radius / dt};
}

namespace {

template <int Dim>
std::vector<double> row_by_row(const analysis::Tensor<Dim>& t) {
  std::vector<double> values;
  for (int i = 0; i < Dim; ++i) {
    for (int j = 0; j < Dim; ++j) values.push_back(t(i, j));
  }
  return values;
}

template <int Dim>
std::vector<double> values_of(const Vec<Dim>& v) {
  return {v.data(), v.data() + Dim};
}

}  // namespace

template <int Dim>
protocol::RegionTelemetry read_regions(const BasicWorld<Dim>& world,
                                       const std::vector<analysis::RegionT<Dim>>& regions) {
  protocol::RegionTelemetry t;
  t.dimension = Dim;
  const analysis::AssemblySampleT<Dim> sample = analysis::sample(world);
  for (const analysis::RegionT<Dim>& region : regions) {
    const analysis::RegionMeasuresT<Dim> m = analysis::measure_region(sample, region);
    protocol::RegionMeasures r;
    r.name = region.name;
    r.particles = m.particles;
    r.rattlers = m.rattlers;
    r.contacts = m.contacts;
    r.particle_contacts = m.particle_contacts;
    r.sliding_contacts = m.sliding_contacts;
    r.sliding_fraction = m.sliding_fraction;
    r.coordination = m.coordination;
    r.mechanical_coordination = m.mechanical_coordination;
    r.porosity = m.porosity;
    r.void_ratio = m.void_ratio;
    r.stress = row_by_row<Dim>(m.stress);
    r.principal_stress = values_of<Dim>(m.principal_stress.values);
    r.stress_angle = m.principal_stress.angle;
    r.mean_stress = m.mean_stress;
    r.deviator_stress = m.deviator_stress;
    r.sin_phi = m.sin_phi;
    r.tangential_share = m.tangential_share;
    r.fabric = row_by_row<Dim>(m.fabric.tensor);
    r.principal_fabric = values_of<Dim>(m.fabric.principal.values);
    r.fabric_angle = m.fabric.principal.angle;
    r.anisotropy = m.fabric.anisotropy;
    r.weighted_fabric = row_by_row<Dim>(m.weighted_fabric.tensor);
    r.principal_weighted_fabric = values_of<Dim>(m.weighted_fabric.principal.values);
    r.weighted_fabric_angle = m.weighted_fabric.principal.angle;
    r.weighted_anisotropy = m.weighted_fabric.anisotropy;
    r.fabric_trace = m.fabric_trace;
    r.mean_normal_force = m.mean_normal_force;
    r.max_normal_force = m.max_normal_force;
    r.mean_rotation = m.mean_rotation;
    r.mean_abs_rotation = m.mean_abs_rotation;
    t.regions.push_back(std::move(r));
  }
  return t;
}

template protocol::RegionTelemetry read_regions<2>(const BasicWorld<2>&, const std::vector<analysis::RegionT<2>>&);
template protocol::RegionTelemetry read_regions<3>(const BasicWorld<3>&, const std::vector<analysis::RegionT<3>>&);
template protocol::WallForce read_wall<2>(const BasicWorld<2>&, WallId);
template protocol::WallForce read_wall<3>(const BasicWorld<3>&, WallId);
template std::vector<protocol::WallForce> read_walls<2>(const BasicWorld<2>&);
template std::vector<protocol::WallForce> read_walls<3>(const BasicWorld<3>&);
template protocol::ContactStats read_contact_stats<2>(const BasicWorld<2>&);
template protocol::ContactStats read_contact_stats<3>(const BasicWorld<3>&);
template std::vector<protocol::ContactEntry> query_contacts<2>(const BasicWorld<2>&, const ContactFilter&);
template std::vector<protocol::ContactEntry> query_contacts<3>(const BasicWorld<3>&, const ContactFilter&);
template std::optional<ServoLimits> default_servo_limits<2>(const BasicWorld<2>&, WallId,
                                                            const std::vector<ContactModelDef>&);
template std::optional<ServoLimits> default_servo_limits<3>(const BasicWorld<3>&, WallId,
                                                            const std::vector<ContactModelDef>&);

}  // namespace dem::service
