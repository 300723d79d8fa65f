// The contacts an assembly broke and formed between two states (Randall
// 1989, Fig. 6.35: "the structure of the graded assembly by lines joining
// the centres of contacting particles ... contacts that have been broken,
// and ... new contacts that have occurred since the start of shear"), and
// how they lie: the share of them within 45 degrees of an axis ("the
// majority of contacts which are broken during shear are in the direction
// of extension").
#pragma once

#include <vector>

#include "dem/analysis/assembly_sample.h"
#include "dem/analysis/region.h"

namespace dem::analysis {

// A particle-particle contact, by the world's particle ids (stable across
// states), with its unit normal.
struct Bond {
  ParticleId first = kInvalidId, second = kInvalidId;  // first < second
  Vec2 normal = Vec2::Zero();
};

struct ContactChanges {
  std::vector<Bond> kept;    // touching in both states (the later normal)
  std::vector<Bond> broken;  // touching before, not after (the earlier normal)
  std::vector<Bond> formed;  // touching after, not before (the later normal)
};

// The touching particle-particle contacts of `before` and `after` (two
// samples of one world) whose contact point lies in the region in the
// state that has them.
ContactChanges contact_changes(const AssemblySample& before, const AssemblySample& after, const Region& region);

// The share of the bonds whose normal lies within 45 degrees of the axis
// (either way along it); 0 for none.
double share_along(const std::vector<Bond>& bonds, const Vec2& axis);

}  // namespace dem::analysis
