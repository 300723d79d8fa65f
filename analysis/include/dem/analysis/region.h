// The regions the analysis measures (Randall 1989, 4.6): the engine's
// (dem/region.h), and the box a region's volume is clipped against.
#pragma once

#include "dem/math.h"
#include "dem/region.h"

namespace dem::analysis {

using dem::check_region;
using dem::Region;
using dem::Region3;
using dem::region_measure;
using dem::RegionShape;
using dem::RegionT;

// An axis-aligned box: what a kWhole region becomes once the particles
// are known, and what the solid-volume integrals clip against.
template <int Dim>
struct Box {
  Vec<Dim> min, max;
  double measure() const { return (max - min).prod(); }  // area (2D) or volume (3D)
};

}  // namespace dem::analysis
