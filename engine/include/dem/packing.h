// Particle generators: a regular lattice and a random non-overlapping packing
// with a size distribution and a seed, in 2D and 3D. Deterministic for a
// given definition.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "dem/definitions.h"

namespace dem {

// Square: a square (2D) or simple cubic (3D) grid. Hexagonal: rows shifted
// by half a spacing (2D triangular packing; in 3D the same layers stacked
// with every other layer shifted, a hexagonal close packing of rows).
enum class LatticeArrangement { kSquare, kHexagonal };

template <int Dim>
struct LatticeDefT {
  MaterialId material{0};
  double radius = 1.0;                 // m
  Vec<Dim> origin = Vec<Dim>::Zero();  // centre of the first particle, m
  int columns = 1;
  int rows = 1;
  int layers = 1;        // 3D only
  double spacing = 2.0;  // centre distance along a row, m
  LatticeArrangement arrangement = LatticeArrangement::kSquare;
};

// A class of equal particles: discs or spheres of a radius, or a shape (a
// 2D superquadric, a 3D ellipsoid) whose bounding radius (the largest
// semi-axis, or a superquadric's farthest corner) is then its radius.
template <int Dim>
struct SizeClassT {
  double radius = 1.0;  // m
  int count = 0;
  ShapeDefT<Dim> shape;
};

// Random sequential placement inside [min, max] (centres keep a radius from
// the faces), largest sizes first, no two bounding circles or spheres
// overlapping; superquadrics are turned at random (seeded) angles and
// ellipsoids to random orientations, uniform over all rotations. A
// particle that finds no free place after max_attempts tries is an error
// (DefinitionError) naming its size class - or, with next_size_when_full,
// the end of its class: the generator "would now move on to the next
// smaller particle size and attempt to generate all those" (Randall 1989,
// 4.4), which fills a small box densely, the counts becoming the most of
// each size.
template <int Dim>
struct RandomPackingDefT {
  MaterialId material{0};
  Vec<Dim> min = Vec<Dim>::Zero();
  Vec<Dim> max = Vec<Dim>::Ones();
  std::vector<SizeClassT<Dim>> sizes;
  std::uint64_t seed = 1;
  int max_attempts = 100000;
  bool next_size_when_full = false;  // Randall 4.4's dense generation
  // Asked every few thousand attempts, when set: true ends the packing
  // with a DefinitionError. A caller that gave up on it (dem_server
  // abandoning a load) ends the work too, instead of letting it run on.
  std::function<bool()> stopped;
};

using SizeClass = SizeClassT<2>;
using SizeClass3 = SizeClassT<3>;

template <int Dim>
std::vector<ParticleDefT<Dim>> generate_lattice(const LatticeDefT<Dim>& def);
template <int Dim>
std::vector<ParticleDefT<Dim>> generate_random_packing(const RandomPackingDefT<Dim>& def);

using LatticeDef = LatticeDefT<2>;
using LatticeDef3 = LatticeDefT<3>;
using RandomPackingDef = RandomPackingDefT<2>;
using RandomPackingDef3 = RandomPackingDefT<3>;

}  // namespace dem
