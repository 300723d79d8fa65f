// The contact stresses of Hertzian contacts in a region (Randall 1989,
// 4.6): each contact's radius a (3.12: a^2 = R* overlap), its mean normal
// and shear contact stresses N / (pi a^2) and |T| / (pi a^2), a over the
// smaller particle's radius, and the overlap over the smaller particle's
// diameter, flagged past 7 % (6.4.3: "if the overlap was greater than 7% of
// the diameter of the smallest particle in contact" the Hertzian laws no
// longer hold); the moments of their distributions (Figs. 6.42-6.43) and
// the contribution of each particle size to the contacts ("whether ... it
// is the smallest particles that are generally redundant"). Only for
// contacts whose force law is Hertz's: a linear spring has no contact
// radius.
#pragma once

#include <span>
#include <vector>

#include "dem/analysis/assembly_sample.h"
#include "dem/analysis/region.h"

namespace dem::analysis {

// The moments of a sample of values, and how near a normal distribution
// they lie: a normal one has skewness 0, excess kurtosis 0 and 68.3 % and
// 95.4 % of its values within one and two standard deviations of the mean.
struct Moments {
  int count = 0;
  double min = 0.0, max = 0.0, mean = 0.0;
  double standard_deviation = 0.0;  // of the sample (n - 1)
  double skewness = 0.0;            // m3 / m2^(3/2), the moments about the mean
  double excess_kurtosis = 0.0;     // m4 / m2^2 - 3
  double within_one_deviation = 0.0;
  double within_two_deviations = 0.0;
};

// All zero when there are no values; the shape measures zero when the
// values do not spread.
Moments moments_of(std::span<const double> values);

// One particle-particle contact.
struct ContactStress {
  double normal_force = 0.0;    // N (the spring's)
  double contact_radius = 0.0;  // m, a = (R* overlap)^(1/2) (Randall 3.12)
  double normal_stress = 0.0;   // Pa, N / (pi a^2): the mean over the contact area (2/3 of Hertz's p_0, 3.1)
  double shear_stress = 0.0;    // Pa, |T| / (pi a^2)
  double radius_ratio = 0.0;    // a over the smaller particle's radius
  double overlap_ratio = 0.0;   // overlap over the smaller particle's diameter
};

// The particles of one size whose centres lie in the region, and the
// particle-particle contacts they take part in.
struct SizeClassContacts {
  double radius = 0.0;  // m
  int particles = 0;
  int contacts = 0;           // contact ends on these particles
  double coordination = 0.0;  // contacts / particles
  double share = 0.0;         // of all the contact ends in the region
  int without_contacts = 0;   // particles of this size carrying nothing
};

struct ContactStressOptions {
  double overlap_limit = 0.07;  // of the smaller diameter (Randall 6.4.3)
  // A contact "carrying [a] very small normal force" (6.5.2: the
  // distribution stays normal "with the exception of" these): below this
  // fraction of the region's mean normal force.
  double small_force = 0.1;
};

struct ContactStressStatistics {
  std::vector<ContactStress> contacts;  // touching particle-particle contacts whose point lies in the region
  Moments normal_stress;                // Pa, over all of them (Figs. 6.42-6.43)
  Moments normal_stress_without_small;  // over those whose normal force is not small (the options)
  Moments shear_stress;                 // Pa
  Moments radius_ratio;
  double largest_overlap_ratio = 0.0;
  int over_overlap_limit = 0;            // contacts past the options' overlap limit: Hertz's law no longer holds
  std::vector<SizeClassContacts> sizes;  // by radius, ascending (radii within 1e-9 of each other are one size)
};

template <int Dim>
ContactStressStatistics contact_stresses(const AssemblySampleT<Dim>& sample, const RegionT<Dim>& region,
                                         const ContactStressOptions& options = {});

}  // namespace dem::analysis
