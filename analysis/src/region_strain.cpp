#include "dem/analysis/region_strain.h"

#include <Eigen/LU>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace dem::analysis {

namespace {

// Each reference particle's position in the current sample, or -1: by
// world id when the samples carry them, by position in the sample when
// both were built by hand.
template <int Dim>
std::vector<std::ptrdiff_t> match(const AssemblySampleT<Dim>& reference, const AssemblySampleT<Dim>& current) {
  const std::size_t n = reference.particle_count();
  std::vector<std::ptrdiff_t> at(n, -1);
  if (reference.ids.empty() && current.ids.empty()) {
    for (std::size_t k = 0; k < n && k < current.particle_count(); ++k) at[k] = static_cast<std::ptrdiff_t>(k);
    return at;
  }
  if (reference.ids.size() != n || current.ids.size() != current.particle_count())
    throw std::invalid_argument("region strain: one sample names its particles by id and the other does not");
  std::unordered_map<std::uint64_t, std::ptrdiff_t> by_id;
  for (std::size_t k = 0; k < current.ids.size(); ++k)
    by_id.emplace(static_cast<std::uint64_t>(current.ids[k].value()), static_cast<std::ptrdiff_t>(k));
  for (std::size_t k = 0; k < n; ++k) {
    const auto found = by_id.find(static_cast<std::uint64_t>(reference.ids[k].value()));
    if (found != by_id.end()) at[k] = found->second;
  }
  return at;
}

}  // namespace

template <int Dim>
RegionStrainT<Dim> measure_region_strain(const AssemblySampleT<Dim>& reference, const AssemblySampleT<Dim>& current,
                                         const RegionT<Dim>& region) {
  if (reference.periodic.any() || current.periodic.any())
    throw std::invalid_argument("region strain of \"" + region.name +
                                "\": not with periodic boundaries (a particle crossing one jumps a period)");
  const std::vector<std::ptrdiff_t> at = match(reference, current);
  std::vector<Vec<Dim>> from, displacement;
  for (std::size_t k = 0; k < reference.particle_count(); ++k) {
    if (at[k] < 0 || !region.contains(reference.position[k])) continue;
    from.push_back(reference.position[k]);
    displacement.push_back(current.position[static_cast<std::size_t>(at[k])] - reference.position[k]);
  }
  RegionStrainT<Dim> s;
  s.particles = static_cast<int>(from.size());
  if (s.particles < Dim + 1)
    throw std::invalid_argument("region strain of \"" + region.name + "\": " + std::to_string(s.particles) +
                                " particles inside, a gradient needs at least " + std::to_string(Dim + 1));
  Vec<Dim> x_mean = Vec<Dim>::Zero(), u_mean = Vec<Dim>::Zero();
  for (std::size_t k = 0; k < from.size(); ++k) {
    x_mean += from[k];
    u_mean += displacement[k];
  }
  x_mean /= static_cast<double>(from.size());
  u_mean /= static_cast<double>(from.size());
  Tensor<Dim> xx = Tensor<Dim>::Zero(), ux = Tensor<Dim>::Zero();
  for (std::size_t k = 0; k < from.size(); ++k) {
    const Vec<Dim> x = from[k] - x_mean, u = displacement[k] - u_mean;
    xx += x * x.transpose();
    ux += u * x.transpose();
  }
  // The centres must span the space: a line of particles (a plane in 3D)
  // says nothing of the gradient across it.
  const double scale = xx.trace();
  if (!(xx.determinant() > 1e-12 * std::pow(scale, Dim)))
    throw std::invalid_argument("region strain of \"" + region.name + "\": its particles' centres do not span the " +
                                (Dim == 2 ? "plane" : "space"));
  s.displacement_gradient = ux * xx.inverse();
  s.strain = -0.5 * (s.displacement_gradient + s.displacement_gradient.transpose());
  s.principal = principal<Dim>(s.strain);
  s.volumetric = s.strain.trace();
  s.deviator = s.principal.values[0] - s.principal.values[Dim - 1];
  if constexpr (Dim == 2) s.rotation = 0.5 * (s.displacement_gradient(1, 0) - s.displacement_gradient(0, 1));
  double residual = 0.0;
  for (std::size_t k = 0; k < from.size(); ++k) {
    const Vec<Dim> u = displacement[k] - u_mean - s.displacement_gradient * (from[k] - x_mean);
    residual += u.squaredNorm();
  }
  s.fit_residual = std::sqrt(residual / static_cast<double>(from.size()));
  return s;
}

template RegionStrainT<2> measure_region_strain(const AssemblySampleT<2>&, const AssemblySampleT<2>&,
                                                const RegionT<2>&);
template RegionStrainT<3> measure_region_strain(const AssemblySampleT<3>&, const AssemblySampleT<3>&,
                                                const RegionT<3>&);

}  // namespace dem::analysis
