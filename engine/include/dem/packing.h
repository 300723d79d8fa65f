// Particle generators: a regular lattice and a random non-overlapping packing
// with a size distribution and a seed. Deterministic for a given definition.
#pragma once

#include <cstdint>
#include <vector>

#include "dem/definitions.h"

namespace dem {

enum class LatticeArrangement { kSquare, kHexagonal };

struct LatticeDef {
  MaterialId material = 0;
  double radius = 1.0;            // m
  Vec2 origin = Vec2::Zero();     // centre of the first particle, m
  int columns = 1;
  int rows = 1;
  double spacing = 2.0;           // centre distance along a row, m
  LatticeArrangement arrangement = LatticeArrangement::kSquare;
};

struct SizeClass {
  double radius = 1.0;  // m
  int count = 0;
};

// Random sequential placement inside [min, max] (centres keep a radius from
// the edges), largest sizes first; a particle that finds no free place after
// max_attempts tries is an error (DefinitionError) naming its size class.
struct RandomPackingDef {
  MaterialId material = 0;
  Vec2 min = Vec2::Zero();
  Vec2 max = Vec2::Ones();
  std::vector<SizeClass> sizes;
  std::uint64_t seed = 1;
  int max_attempts = 100000;
};

std::vector<ParticleDef> generate_lattice(const LatticeDef& def);
std::vector<ParticleDef> generate_random_packing(const RandomPackingDef& def);

}  // namespace dem
