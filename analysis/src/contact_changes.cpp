#include "dem/analysis/contact_changes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "dem/analysis/region_measures.h"

namespace dem::analysis {

namespace {

// The sample's bonds in the region, ordered by their pair of ids.
std::vector<Bond> bonds_of(const AssemblySample& s, const Region& region) {
  std::vector<Bond> bonds;
  for (const ContactRecord& c : s.contacts) {
    if (c.second_particle == kInvalidId || c.overlap <= 0.0 || !region.contains(contact_point(s, c))) continue;
    Bond b{s.ids[c.first.index()], s.ids[c.second_particle.index()], c.normal};
    if (b.second.index() < b.first.index()) std::swap(b.first, b.second);
    bonds.push_back(b);
  }
  std::ranges::sort(bonds, {}, [](const Bond& b) { return std::pair(b.first.index(), b.second.index()); });
  return bonds;
}

}  // namespace

ContactChanges contact_changes(const AssemblySample& before, const AssemblySample& after, const Region& region) {
  const std::vector<Bond> a = bonds_of(before, region);
  const std::vector<Bond> b = bonds_of(after, region);
  const auto key = [](const Bond& x) { return std::pair(x.first.index(), x.second.index()); };
  ContactChanges out;
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && key(a[i]) < key(b[j]))) {
      out.broken.push_back(a[i++]);
    } else if (i == a.size() || key(b[j]) < key(a[i])) {
      out.formed.push_back(b[j++]);
    } else {
      out.kept.push_back(b[j]);
      ++i;
      ++j;
    }
  }
  return out;
}

double share_along(const std::vector<Bond>& bonds, const Vec2& axis) {
  if (bonds.empty()) return 0.0;
  const Vec2 e = axis.normalized();
  const double within = std::cos(std::numbers::pi / 4.0);
  const auto along = std::ranges::count_if(bonds, [&](const Bond& b) { return std::abs(b.normal.dot(e)) > within; });
  return static_cast<double>(along) / static_cast<double>(bonds.size());
}

}  // namespace dem::analysis
