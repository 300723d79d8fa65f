#include "dem/analysis/region_measures.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>

#include "solid_volume.h"

namespace dem::analysis {

namespace {

// The full area (2D) or volume (3D) of a round particle.
template <int Dim>
double particle_measure(double r) {
  return Dim == 2 ? std::numbers::pi * r * r : 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

// The shortest periodic image of a separation.
template <int Dim>
Vec<Dim> nearest_image(Vec<Dim> d, const PeriodicDefT<Dim>& periodic) {
  for (int k = 0; k < Dim; ++k) {
    if (!periodic.axes[k]) continue;
    const double length = periodic.max[k] - periodic.min[k];
    d[k] -= length * std::round(d[k] / length);
  }
  return d;
}

template <int Dim>
FabricT<Dim> fabric_of(const Tensor<Dim>& tensor) {
  FabricT<Dim> f;
  f.tensor = tensor;
  f.principal = principal<Dim>(tensor);
  f.anisotropy = f.principal.values[0] - f.principal.values[Dim - 1];
  return f;
}

// The compressive normal force of a contact: the force on the first
// particle against the normal (which points from it to the second body).
template <int Dim>
double normal_part(const ContactRecordT<Dim>& c) {
  return -c.force.dot(c.normal);
}

}  // namespace

template <int Dim>
Vec<Dim> contact_point(const AssemblySampleT<Dim>& s, const ContactRecordT<Dim>& c) {
  Vec<Dim> x = c.point;
  for (int k = 0; k < Dim; ++k) {
    if (!s.periodic.axes[k]) continue;
    const double length = s.periodic.max[k] - s.periodic.min[k];
    x[k] -= length * std::floor((x[k] - s.periodic.min[k]) / length);
  }
  return x;
}

template <int Dim>
Box<Dim> whole_box(const AssemblySampleT<Dim>& s) {
  Box<Dim> box{Vec<Dim>::Constant(std::numeric_limits<double>::infinity()),
               Vec<Dim>::Constant(-std::numeric_limits<double>::infinity())};
  for (std::size_t i = 0; i < s.particle_count(); ++i) {
    box.min = box.min.cwiseMin(s.position[i] - Vec<Dim>::Constant(s.radius[i]));
    box.max = box.max.cwiseMax(s.position[i] + Vec<Dim>::Constant(s.radius[i]));
  }
  for (int k = 0; k < Dim; ++k) {
    if (!s.periodic.axes[k]) continue;
    box.min[k] = s.periodic.min[k];
    box.max[k] = s.periodic.max[k];
  }
  return box;
}

template <int Dim>
std::vector<bool> find_rattlers(const AssemblySampleT<Dim>& s) {
  const std::size_t n = s.particle_count();
  std::vector<int> count(n, 0);
  std::vector<std::vector<ParticleId>> neighbours(n);
  for (const ContactRecordT<Dim>& c : s.contacts) {
    ++count[c.first.index()];
    if (c.second_particle != kInvalidId) {
      ++count[c.second_particle.index()];
      neighbours[c.first.index()].push_back(c.second_particle);
      neighbours[c.second_particle.index()].push_back(c.first);
    }
  }
  // Fewer than two contacts cannot hold a particle in equilibrium (without
  // a body force); taking it away may leave a neighbour with fewer.
  std::vector<bool> rattler(n, false);
  std::deque<std::size_t> queue;
  for (std::size_t i = 0; i < n; ++i) {
    if (count[i] < 2) {
      rattler[i] = true;
      queue.push_back(i);
    }
  }
  while (!queue.empty()) {
    const std::size_t i = queue.front();
    queue.pop_front();
    for (const ParticleId j : neighbours[i]) {
      const std::size_t k = j.index();
      if (rattler[k]) continue;
      if (--count[k] < 2) {
        rattler[k] = true;
        queue.push_back(k);
      }
    }
  }
  return rattler;
}

template <int Dim>
RegionMeasuresT<Dim> measure_region(const AssemblySampleT<Dim>& s, const RegionT<Dim>& region) {
  RegionMeasuresT<Dim> m;
  m.region = region.name;
  const std::size_t n = s.particle_count();
  const Box<Dim> whole = whole_box(s);
  m.volume = region.shape == RegionShape::kWhole ? whole.measure() : region_measure(region);

  // Particles: which lie inside, the solid inside, the radii and rotations.
  std::vector<bool> inside(n, false);
  double full_measure = 0.0, radius_sum = 0.0, rotation_sum = 0.0, abs_rotation_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // The whole assembly's box holds every particle (or, across a periodic
    // boundary, its image): no clipping.
    m.solid += region.shape == RegionShape::kWhole ? particle_measure<Dim>(s.radius[i])
                                                   : solid_in_region<Dim>(s.position[i], s.radius[i], region, whole);
    if (!region.contains(s.position[i])) continue;
    inside[i] = true;
    ++m.particles;
    full_measure += particle_measure<Dim>(s.radius[i]);
    radius_sum += s.radius[i];
    const double turned = i < s.rotation.size() ? s.rotation[i] : 0.0;
    rotation_sum += turned;
    abs_rotation_sum += std::abs(turned);
  }
  if (m.volume > 0.0) {
    m.porosity = 1.0 - m.solid / m.volume;
    m.void_ratio = m.porosity < 1.0 ? m.porosity / (1.0 - m.porosity) : 0.0;
  }
  if (m.particles > 0) {
    m.mean_rotation = rotation_sum / m.particles;
    m.mean_abs_rotation = abs_rotation_sum / m.particles;
  }

  // Coordination, with and without rattlers.
  const std::vector<bool> rattler = find_rattlers(s);
  int contact_ends = 0, mechanical_ends = 0, mechanical_particles = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!inside[i]) continue;
    if (rattler[i]) {
      ++m.rattlers;
    } else {
      ++mechanical_particles;
    }
  }

  // Stress: every contact of every particle inside, with its branch vector.
  Tensor<Dim> normal_sum = Tensor<Dim>::Zero(), tangential_sum = Tensor<Dim>::Zero();
  auto add_particle_share = [&](std::size_t i, const Vec<Dim>& point, const Vec<Dim>& force, const Vec<Dim>& normal) {
    const Vec<Dim> branch = nearest_image<Dim>(point - s.position[i], s.periodic);
    const Vec<Dim> normal_force = force.dot(normal) * normal;
    normal_sum -= branch * normal_force.transpose();
    tangential_sum -= branch * (force - normal_force).transpose();
  };

  // Fabric and contact figures: the contacts whose points lie inside.
  Tensor<Dim> fabric_sum = Tensor<Dim>::Zero(), weighted_sum = Tensor<Dim>::Zero();
  double weight_sum = 0.0, normal_force_sum = 0.0;
  for (const ContactRecordT<Dim>& c : s.contacts) {
    const auto a = c.first.index();
    const bool pair = c.second_particle != kInvalidId;
    const auto b = pair ? c.second_particle.index() : a;
    if (inside[a]) {
      add_particle_share(a, c.point, c.force, c.normal);
      ++contact_ends;
      if (!rattler[a] && (!pair || !rattler[b])) ++mechanical_ends;
    }
    if (pair && inside[b]) {
      add_particle_share(b, c.point, Vec<Dim>(-c.force), c.normal);
      ++contact_ends;
      if (!rattler[b] && !rattler[a]) ++mechanical_ends;
    }
    if (!region.contains(contact_point(s, c))) continue;
    ++m.contacts;
    const double normal = normal_part(c);
    normal_force_sum += normal;
    m.max_normal_force = std::max(m.max_normal_force, normal);
    if (!pair) continue;
    ++m.particle_contacts;
    m.sliding_contacts += c.sliding ? 1 : 0;
    const Tensor<Dim> nn = c.normal * c.normal.transpose();
    fabric_sum += nn;  // (4.48)
    weighted_sum += normal * nn;
    weight_sum += normal;
  }
  if (m.particles > 0) m.coordination = static_cast<double>(contact_ends) / m.particles;
  if (mechanical_particles > 0) m.mechanical_coordination = static_cast<double>(mechanical_ends) / mechanical_particles;
  if (m.contacts > 0) m.mean_normal_force = normal_force_sum / m.contacts;
  if (m.particle_contacts > 0) m.sliding_fraction = static_cast<double>(m.sliding_contacts) / m.particle_contacts;

  // The volume the particles inside stand for: their own over the region's
  // solid fraction (times the depth of a 2D layer).
  if (full_measure > 0.0 && m.volume > 0.0) {
    const double scale = (m.solid / m.volume) / (full_measure * s.depth);
    m.normal_stress = scale * normal_sum;
    m.tangential_stress = scale * tangential_sum;
    m.stress = m.normal_stress + m.tangential_stress;
    m.principal_stress = principal<Dim>(m.stress);
    m.mean_stress = m.stress.trace() / Dim;
    const double major = m.principal_stress.values[0], minor = m.principal_stress.values[Dim - 1];
    m.deviator_stress = major - minor;
    if (major + minor != 0.0) m.sin_phi = (major - minor) / (major + minor);
    if (m.deviator_stress > 0.0) {
      const Tensor<Dim> t = 0.5 * (m.tangential_stress + m.tangential_stress.transpose());
      const Vec<Dim> e1 = m.principal_stress.directions.col(0), e3 = m.principal_stress.directions.col(Dim - 1);
      m.tangential_share = (e1.dot(t * e1) - e3.dot(t * e3)) / m.deviator_stress;
    }
  }

  if (m.particle_contacts > 0) m.fabric = fabric_of<Dim>(fabric_sum / m.particle_contacts);
  if (weight_sum > 0.0) m.weighted_fabric = fabric_of<Dim>(weighted_sum / weight_sum);
  if (m.particles > 0 && m.volume > 0.0) {
    m.fabric_trace = 2.0 * m.particle_contacts * (radius_sum / m.particles) / m.volume;  // (4.46)
  }
  return m;
}

template RegionMeasuresT<2> measure_region(const AssemblySampleT<2>&, const RegionT<2>&);
template RegionMeasuresT<3> measure_region(const AssemblySampleT<3>&, const RegionT<3>&);
template std::vector<bool> find_rattlers(const AssemblySampleT<2>&);
template std::vector<bool> find_rattlers(const AssemblySampleT<3>&);
template Box<2> whole_box(const AssemblySampleT<2>&);
template Box<3> whole_box(const AssemblySampleT<3>&);
template Vec2 contact_point(const AssemblySampleT<2>&, const ContactRecordT<2>&);
template Vec3 contact_point(const AssemblySampleT<3>&, const ContactRecordT<3>&);

}  // namespace dem::analysis
