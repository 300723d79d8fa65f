#include "dem/analysis/distributions.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dem/analysis/region_measures.h"

namespace dem::analysis {

namespace {

std::vector<Bin> empty_bins(int bins, double from, double to) {
  std::vector<Bin> out(static_cast<std::size_t>(std::max(bins, 1)));
  const double width = (to - from) / static_cast<double>(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].low = from + width * static_cast<double>(k);
    out[k].high = from + width * static_cast<double>(k + 1);
  }
  return out;
}

std::size_t class_of(double value, double from, double to, std::size_t bins) {
  const double x = (value - from) / (to - from) * static_cast<double>(bins);
  return static_cast<std::size_t>(std::clamp(x, 0.0, static_cast<double>(bins) - 1.0));
}

}  // namespace

std::vector<Bin> normal_rose(const AssemblySample& s, const Region& region, int bins, RoseOf of) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  std::vector<Bin> rose = empty_bins(bins, 0.0, kTurn);
  double total = 0.0;
  for (const ContactRecord& c : s.contacts) {
    if (c.second_particle == kInvalidId || !region.contains(contact_point(s, c))) continue;
    if (of == RoseOf::kSlidingContacts && !c.sliding) continue;
    const double weight = of == RoseOf::kNormalForce ? std::max(0.0, -c.force.dot(c.normal)) : 1.0;
    double angle = std::atan2(c.normal.y(), c.normal.x());
    if (angle < 0.0) angle += kTurn;
    for (const double a : {angle, std::fmod(angle + std::numbers::pi, kTurn)}) {
      Bin& bin = rose[class_of(a, 0.0, kTurn, rose.size())];
      bin.contacts += 1;
      bin.share += weight;
      total += weight;
    }
  }
  if (total > 0.0) {
    for (Bin& bin : rose) bin.share /= total;
  }
  return rose;
}

template <int Dim>
std::vector<Bin> obliquity_histogram(const AssemblySampleT<Dim>& s, const RegionT<Dim>& region, double friction,
                                     int bins) {
  const double from = Dim == 2 ? -1.0 : 0.0;
  std::vector<Bin> histogram = empty_bins(bins, from, 1.0);
  int total = 0;
  for (const ContactRecordT<Dim>& c : s.contacts) {
    if (!region.contains(contact_point(s, c)) || c.normal_force <= 0.0 || friction <= 0.0) continue;
    const double obliquity = std::clamp(c.shear_force / (friction * c.normal_force), from, 1.0);
    histogram[class_of(obliquity, from, 1.0, histogram.size())].contacts += 1;
    ++total;
  }
  for (Bin& bin : histogram) bin.share = total > 0 ? static_cast<double>(bin.contacts) / total : 0.0;
  return histogram;
}

template std::vector<Bin> obliquity_histogram(const AssemblySampleT<2>&, const RegionT<2>&, double, int);
template std::vector<Bin> obliquity_histogram(const AssemblySampleT<3>&, const RegionT<3>&, double, int);

}  // namespace dem::analysis
