#include "dem/analysis/contact_stresses.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dem/analysis/region_measures.h"

namespace dem::analysis {

Moments moments_of(std::span<const double> values) {
  Moments m;
  m.count = static_cast<int>(values.size());
  if (values.empty()) return m;
  const auto [low, high] = std::ranges::minmax(values);
  m.min = low;
  m.max = high;
  const double n = static_cast<double>(values.size());
  double sum = 0.0;
  for (const double v : values) sum += v;
  m.mean = sum / n;
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (const double v : values) {
    const double d = v - m.mean;
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  m2 /= n;
  m3 /= n;
  m4 /= n;
  if (values.size() > 1) m.standard_deviation = std::sqrt(m2 * n / (n - 1.0));
  if (m2 <= 0.0) return m;
  m.skewness = m3 / std::pow(m2, 1.5);
  m.excess_kurtosis = m4 / (m2 * m2) - 3.0;
  const double s = m.standard_deviation;
  int one = 0, two = 0;
  for (const double v : values) {
    one += std::abs(v - m.mean) <= s ? 1 : 0;
    two += std::abs(v - m.mean) <= 2.0 * s ? 1 : 0;
  }
  m.within_one_deviation = one / n;
  m.within_two_deviations = two / n;
  return m;
}

namespace {

// The particles' sizes, ascending: radii within a relative 1e-9 of each
// other are one size.
std::vector<double> sizes_of(std::span<const double> radii) {
  std::vector<double> sizes(radii.begin(), radii.end());
  std::ranges::sort(sizes);
  const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); };
  sizes.erase(std::unique(sizes.begin(), sizes.end(), same), sizes.end());
  return sizes;
}

std::size_t size_of(const std::vector<double>& sizes, double radius) {
  const auto at = std::ranges::lower_bound(sizes, radius * (1.0 - 1e-9));
  return static_cast<std::size_t>(at - sizes.begin());
}

}  // namespace

template <int Dim>
ContactStressStatistics contact_stresses(const AssemblySampleT<Dim>& s, const RegionT<Dim>& region,
                                         const ContactStressOptions& options) {
  ContactStressStatistics out;
  const std::vector<double> sizes = sizes_of(s.radius);
  out.sizes.resize(sizes.size());
  for (std::size_t k = 0; k < sizes.size(); ++k) out.sizes[k].radius = sizes[k];
  std::vector<int> contacts_of(s.particle_count(), 0);
  for (const ContactRecordT<Dim>& c : s.contacts) {
    if (c.second_particle == kInvalidId || c.overlap <= 0.0) continue;
    const double r1 = s.radius[c.first.index()];
    const double r2 = s.radius[c.second_particle.index()];
    contacts_of[c.first.index()] += 1;
    contacts_of[c.second_particle.index()] += 1;
    if (c.normal_force <= 0.0 || !region.contains(contact_point(s, c))) continue;
    ContactStress cs;
    const double effective_radius = r1 * r2 / (r1 + r2);  // Randall 4.5
    const double smaller = std::min(r1, r2);
    cs.normal_force = c.normal_force;
    cs.contact_radius = std::sqrt(effective_radius * c.overlap);  // Randall 3.12
    const double area = std::numbers::pi * cs.contact_radius * cs.contact_radius;
    cs.normal_stress = c.normal_force / area;
    cs.shear_stress = std::abs(c.shear_force) / area;
    cs.radius_ratio = cs.contact_radius / smaller;
    cs.overlap_ratio = c.overlap / (2.0 * smaller);
    out.contacts.push_back(cs);
  }
  std::vector<double> normal, without_small, shear, ratio;
  double mean_force = 0.0;
  for (const ContactStress& c : out.contacts) mean_force += c.normal_force;
  if (!out.contacts.empty()) mean_force /= static_cast<double>(out.contacts.size());
  for (const ContactStress& c : out.contacts) {
    normal.push_back(c.normal_stress);
    if (c.normal_force >= options.small_force * mean_force) without_small.push_back(c.normal_stress);
    shear.push_back(c.shear_stress);
    ratio.push_back(c.radius_ratio);
    out.largest_overlap_ratio = std::max(out.largest_overlap_ratio, c.overlap_ratio);
    out.over_overlap_limit += c.overlap_ratio > options.overlap_limit ? 1 : 0;
  }
  out.normal_stress = moments_of(normal);
  out.normal_stress_without_small = moments_of(without_small);
  out.shear_stress = moments_of(shear);
  out.radius_ratio = moments_of(ratio);

  int ends = 0;
  for (std::size_t p = 0; p < s.particle_count(); ++p) {
    if (!region.contains(s.position[p])) continue;
    SizeClassContacts& size = out.sizes[size_of(sizes, s.radius[p])];
    size.particles += 1;
    size.contacts += contacts_of[p];
    size.without_contacts += contacts_of[p] == 0 ? 1 : 0;
    ends += contacts_of[p];
  }
  for (SizeClassContacts& size : out.sizes) {
    if (size.particles > 0) size.coordination = static_cast<double>(size.contacts) / size.particles;
    if (ends > 0) size.share = static_cast<double>(size.contacts) / ends;
  }
  return out;
}

template ContactStressStatistics contact_stresses(const AssemblySampleT<2>&, const RegionT<2>&,
                                                  const ContactStressOptions&);
template ContactStressStatistics contact_stresses(const AssemblySampleT<3>&, const RegionT<3>&,
                                                  const ContactStressOptions&);

}  // namespace dem::analysis
