#include "dem/region.h"

#include <cmath>
#include <numbers>

#include "dem/error.h"

namespace dem {

namespace {

constexpr const char* kAxes = "xyz";

template <int Dim>
std::string label(const RegionT<Dim>& region) {
  return "region \"" + region.name + "\"";
}

}  // namespace

template <int Dim>
bool RegionT<Dim>::contains(const Vec<Dim>& x) const {
  switch (shape) {
    case RegionShape::kWhole:
      return true;
    case RegionShape::kBox:
      return (x.array() >= min.array()).all() && (x.array() <= max.array()).all();
    case RegionShape::kBall:
      return (x - centre).squaredNorm() <= radius * radius;
  }
  return false;
}

template <int Dim>
void check_region(const RegionT<Dim>& region) {
  if (region.name.empty()) throw DefinitionError("region: name must not be empty");
  switch (region.shape) {
    case RegionShape::kWhole:
      return;
    case RegionShape::kBox:
      for (int d = 0; d < Dim; ++d) {
        if (!std::isfinite(region.min[d]) || !std::isfinite(region.max[d])) {
          throw DefinitionError(label(region) + ": box.min." + kAxes[d] + " and box.max." + kAxes[d] +
                                " must be finite");
        }
        if (!(region.max[d] > region.min[d])) {
          throw DefinitionError(label(region) + ": box.max." + kAxes[d] + " must be greater than box.min." + kAxes[d]);
        }
      }
      return;
    case RegionShape::kBall:
      if (!region.centre.allFinite()) throw DefinitionError(label(region) + ": ball.centre must be finite");
      if (!(region.radius > 0.0) || !std::isfinite(region.radius)) {
        throw DefinitionError(label(region) + ": ball.radius must be > 0");
      }
      return;
  }
}

template <int Dim>
double region_measure(const RegionT<Dim>& region) {
  switch (region.shape) {
    case RegionShape::kWhole:
      return 0.0;
    case RegionShape::kBox:
      return (region.max - region.min).prod();
    case RegionShape::kBall:
      return Dim == 2 ? std::numbers::pi * region.radius * region.radius
                      : 4.0 / 3.0 * std::numbers::pi * std::pow(region.radius, 3);
  }
  return 0.0;
}

template struct RegionT<2>;
template struct RegionT<3>;
template void check_region(const RegionT<2>&);
template void check_region(const RegionT<3>&);
template double region_measure(const RegionT<2>&);
template double region_measure(const RegionT<3>&);

}  // namespace dem
