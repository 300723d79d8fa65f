// A region of an assembly (Randall 1989, 4.6; his measurement circles,
// 6.4.2 and 6.5.2): the whole assembly, an axis-aligned box, or a ball (a
// circle in 2D, a sphere in 3D). The analysis layer measures a region's
// state (dem/analysis/region_measures.h); the engine's stop rule can ask
// for the out-of-balance force in one (dem/programme.h).
#pragma once

#include <string>

#include "dem/math.h"

namespace dem {

enum class RegionShape {
  kWhole,  // every particle; its volume is the box the particles span (or the periodic cell along a periodic axis)
  kBox,    // min <= x <= max along every axis
  kBall,   // |x - centre| <= radius
};

template <int Dim>
struct RegionT {
  std::string name;  // labels the rows written for it; unique among a run's regions
  RegionShape shape = RegionShape::kWhole;
  Vec<Dim> min = Vec<Dim>::Zero();     // m, kBox
  Vec<Dim> max = Vec<Dim>::Zero();     // m, kBox
  Vec<Dim> centre = Vec<Dim>::Zero();  // m, kBall
  double radius = 0.0;                 // m, kBall

  bool contains(const Vec<Dim>& x) const;
};

// Throws DefinitionError naming the region and the field when it makes no
// sense: an empty name, a box whose max is not above its min along an axis,
// a ball with a radius that is not > 0, coordinates that are not finite.
template <int Dim>
void check_region(const RegionT<Dim>& region);

// The region's area (2D) or volume (3D); kWhole has none of its own (0).
template <int Dim>
double region_measure(const RegionT<Dim>& region);

using Region = RegionT<2>;
using Region3 = RegionT<3>;

}  // namespace dem
