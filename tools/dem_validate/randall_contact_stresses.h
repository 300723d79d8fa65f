// Randall (1989) 4.6 and Figs. 6.42-6.43: the mean normal contact stresses
// of the graded and the uniform assemblies at 0, 0.1 and 0.2 % deviator
// strain of the constant-volume shear (6.5.2), with the contact radii, the
// 7 % overlap flag (6.4.3) and each particle size's share of the contacts;
// what the thesis says of them, judged.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "dem/analysis/contact_stresses.h"
#include "dem/world.h"
#include "verdict.h"

namespace dem::validation {

// The contact stresses of a region at one moment of the shear.
struct ContactStressState {
  std::string state;  // the figures' label: "0 %", "0.1 %", "0.2 %"
  double deviator_strain = 0.0;
  double mean_stress = 0.0;  // Pa, the region's (Love-Weber; region_measures.h)
  analysis::ContactStressStatistics statistics;
};

ContactStressState contact_stress_state(const World& world, const analysis::Region& region, std::string state,
                                        double deviator_strain);

// contact_stresses.csv (one row a contact and state) and size_contacts.csv
// (one row a particle size and state), which dem.plots draws.
void write_contact_stresses(const std::filesystem::path& directory, const std::vector<ContactStressState>& states);

void print_contact_stresses(std::FILE* out, const std::vector<ContactStressState>& states);

// What a run's states read, for judging (and the median over packings).
struct ContactStressFigures {
  bool measured = false;  // the states at 0 and 0.2 % were both taken
  double skewness_at_start = 0.0;
  double kurtosis_at_start = 0.0;  // excess
  double skewness_late = 0.0;      // at 0.2 %, the contacts with very small normal forces left out
  double kurtosis_late = 0.0;
  double spread_gain = 0.0;         // the standard deviation at 0.2 % over at 0
  double mean_gain = 0.0;           // the mean contact stress at 0.2 % over at 0
  double stress_gain = 0.0;         // the region's mean stress at 0.2 % over at 0
  double over_overlap_limit = 0.0;  // contacts past 7 % of the smaller diameter, over the states
  double largest_overlap_ratio = 0.0;
};

ContactStressFigures contact_stress_figures(const std::vector<ContactStressState>& states);
ContactStressFigures median_of(const std::vector<ContactStressFigures>& packings);

// Randall 6.5.2: "at the start of shear the distribution of mean normal
// contact stress approximates a normal distribution ... as the deviator
// strain is applied the spread of the distributions increases with a small
// increase in the average ... With the exception of contacts carrying very
// small normal forces the distribution remains essentially normal"; and
// no contact past 7 % overlap (6.4.3: the Hertzian laws hold).
Verdict judge_contact_stresses(const ContactStressFigures& figures);

}  // namespace dem::validation
