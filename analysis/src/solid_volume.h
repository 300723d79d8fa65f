// How much of a disc or a sphere lies inside a box or a ball: the solid
// part of a region, for its porosity. Exact in 2D (areas of circular
// segments) and for two spheres (a lens); a sphere in a box by quadrature
// over slices, each slice exact.
#pragma once

#include "dem/analysis/region.h"

namespace dem::analysis {

double disc_in_box(const Vec2& centre, double radius, const Box<2>& box);
double disc_in_disc(const Vec2& centre, double radius, const Vec2& other_centre, double other_radius);
double sphere_in_box(const Vec3& centre, double radius, const Box<3>& box);
double sphere_in_sphere(const Vec3& centre, double radius, const Vec3& other_centre, double other_radius);

// A round particle's area (2D) or volume (3D) inside a region; kWhole
// regions are measured against `whole`, the box they stand for.
template <int Dim>
double solid_in_region(const Vec<Dim>& centre, double radius, const RegionT<Dim>& region, const Box<Dim>& whole);

}  // namespace dem::analysis
