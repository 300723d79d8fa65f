// Distributions over the contacts of a region (Randall 1989, 6.4.3 and
// 6.5.2): the rose of contact normals, plain, weighted to the normal force
// or of the sliding contacts only (Figs. 6.15-6.16, 6.36-6.41), and the
// histogram of contact force obliquities (Figs. 6.18-6.19). The contacts
// are those whose contact point lies in the region (region_measures.h).
#pragma once

#include <vector>

#include "dem/analysis/assembly_sample.h"
#include "dem/analysis/region.h"

namespace dem::analysis {

struct Bin {
  double low = 0.0, high = 0.0;  // the class [low, high): rad for a rose, F_s / (mu F_n) for obliquities
  int contacts = 0;              // contacts in the class (a rose counts each normal's two ends)
  double share = 0.0;            // of the whole: contacts, or of the normal force for a weighted rose
};

enum class RoseOf { kContacts, kNormalForce, kSlidingContacts };

// 2D: the directions of the particle-particle contacts' normals, each
// counted at its angle and the opposite one, in `bins` classes over
// [0, 2 pi) from the x axis counter-clockwise; shares add up to 1.
std::vector<Bin> normal_rose(const AssemblySample& sample, const Region& region, int bins, RoseOf of);

// The obliquity F_s / (mu F_n) of the contacts (spring forces; particle-
// particle and particle-wall) in `bins` classes: over [-1, 1] in 2D, the
// sign of F_s along t (Cundall & Strack Fig. 3), so sliding contacts sit
// at -1 and +1 (Randall 6.4.3); over [0, 1] in 3D, its magnitude. A
// contact at exactly 1 counts in the last class.
template <int Dim>
std::vector<Bin> obliquity_histogram(const AssemblySampleT<Dim>& sample, const RegionT<Dim>& region, double friction,
                                     int bins);

}  // namespace dem::analysis
