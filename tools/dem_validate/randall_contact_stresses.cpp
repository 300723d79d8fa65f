#include "randall_contact_stresses.h"

#include <algorithm>
#include <cmath>

#include "dem/analysis/assembly_sample.h"
#include "dem/analysis/region_measures.h"
#include "dem/io/csv_file.h"
#include "packings.h"

namespace dem::validation {

ContactStressState contact_stress_state(const World& world, const analysis::Region& region, std::string state,
                                        double deviator_strain) {
  const analysis::AssemblySample sample = analysis::sample(world);
  ContactStressState s;
  s.state = std::move(state);
  s.deviator_strain = deviator_strain;
  s.mean_stress = analysis::measure_region(sample, region).mean_stress;
  s.statistics = analysis::contact_stresses(sample, region);
  return s;
}

void write_contact_stresses(const std::filesystem::path& directory, const std::vector<ContactStressState>& states) {
  io::CsvFile contacts(directory, "contact_stresses.csv",
                       "state,deviator_strain,normal_force,contact_radius,normal_stress,shear_stress,radius_ratio,"
                       "overlap_ratio");
  io::CsvFile sizes(directory, "size_contacts.csv",
                    "state,deviator_strain,radius,particles,contacts,coordination,share,without_contacts");
  for (const ContactStressState& s : states) {
    for (const analysis::ContactStress& c : s.statistics.contacts) {
      contacts.write_row(s.state, s.deviator_strain, c.normal_force, c.contact_radius, c.normal_stress, c.shear_stress,
                         c.radius_ratio, c.overlap_ratio);
    }
    for (const analysis::SizeClassContacts& z : s.statistics.sizes) {
      sizes.write_row(s.state, s.deviator_strain, z.radius, z.particles, z.contacts, z.coordination, z.share,
                      z.without_contacts);
    }
  }
}

void print_contact_stresses(std::FILE* out, const std::vector<ContactStressState>& states) {
  if (states.empty()) return;
  std::fprintf(out, "  mean normal contact stress N / (pi a^2) in the first region (Figs. 6.42-6.43):\n");
  std::fprintf(out, "    %-6s %8s %9s %9s %9s %9s %7s %7s %6s %6s | %7s %7s | %8s %7s %7s %5s\n", "state", "strain %",
               "region kPa", "mean MPa", "sd MPa", "max MPa", "skew", "kurt", "1 sd", "2 sd", "skew*", "kurt*",
               "shear MPa", "a/Rmin", "overlap", ">7%");
  for (const ContactStressState& s : states) {
    const analysis::ContactStressStatistics& st = s.statistics;
    const analysis::Moments& n = st.normal_stress;
    const analysis::Moments& w = st.normal_stress_without_small;
    std::fprintf(out,
                 "    %-6s %8.4f %9.1f %9.1f %9.1f %9.1f %7.3f %7.3f %6.3f %6.3f | %7.3f %7.3f | %8.1f %7.4f %7.5f %5d "
                 "(%d contacts)\n",
                 s.state.c_str(), 100.0 * s.deviator_strain, s.mean_stress / 1e3, n.mean / 1e6,
                 n.standard_deviation / 1e6, n.max / 1e6, n.skewness, n.excess_kurtosis, n.within_one_deviation,
                 n.within_two_deviations, w.skewness, w.excess_kurtosis, st.shear_stress.mean / 1e6,
                 st.radius_ratio.max, st.largest_overlap_ratio, st.over_overlap_limit, n.count);
  }
  std::fprintf(out,
               "    (* without the contacts whose normal force is below a tenth of the mean; a normal distribution: "
               "skew 0, kurt 0, 0.683 within 1 sd, 0.954 within 2)\n");
  std::fprintf(out, "  each size's contacts at %s (4.6: which sizes are redundant):", states.front().state.c_str());
  for (const analysis::SizeClassContacts& z : states.front().statistics.sizes) {
    if (z.particles == 0) continue;
    std::fprintf(out, " R %.2f mm: %d particles, Z %.2f, %.1f %% of contacts, %d without;", z.radius * 1e3, z.particles,
                 z.coordination, 100.0 * z.share, z.without_contacts);
  }
  std::fprintf(out, "\n");
}

ContactStressFigures contact_stress_figures(const std::vector<ContactStressState>& states) {
  ContactStressFigures f;
  for (const ContactStressState& s : states) {
    f.over_overlap_limit += s.statistics.over_overlap_limit;
    f.largest_overlap_ratio = std::max(f.largest_overlap_ratio, s.statistics.largest_overlap_ratio);
  }
  const auto at = [&](const std::string& state) -> const ContactStressState* {
    const auto it = std::ranges::find(states, state, &ContactStressState::state);
    return it == states.end() ? nullptr : &*it;
  };
  const ContactStressState* start = at("0 %");
  const ContactStressState* late = at("0.2 %");
  if (start == nullptr || late == nullptr || start->statistics.normal_stress.count < 3) return f;
  f.measured = true;
  const analysis::Moments& a = start->statistics.normal_stress;
  const analysis::Moments& b = late->statistics.normal_stress;
  f.skewness_at_start = a.skewness;
  f.kurtosis_at_start = a.excess_kurtosis;
  f.skewness_late = late->statistics.normal_stress_without_small.skewness;
  f.kurtosis_late = late->statistics.normal_stress_without_small.excess_kurtosis;
  f.spread_gain = a.standard_deviation > 0.0 ? b.standard_deviation / a.standard_deviation : 0.0;
  f.mean_gain = a.mean > 0.0 ? b.mean / a.mean : 0.0;
  f.stress_gain = start->mean_stress > 0.0 ? late->mean_stress / start->mean_stress : 0.0;
  return f;
}

namespace {

constexpr double ContactStressFigures::*kFigures[] = {
    &ContactStressFigures::skewness_at_start,    &ContactStressFigures::kurtosis_at_start,
    &ContactStressFigures::skewness_late,        &ContactStressFigures::kurtosis_late,
    &ContactStressFigures::spread_gain,          &ContactStressFigures::mean_gain,
    &ContactStressFigures::stress_gain,          &ContactStressFigures::over_overlap_limit,
    &ContactStressFigures::largest_overlap_ratio};

// How near a normal distribution a histogram must lie to "approximate" one:
// the usual rule of thumb (Bulmer 1979: |skewness| below 1/2 is
// approximately symmetric; an excess kurtosis within +-1).
constexpr double kNormalSkewness = 0.5;
constexpr double kNormalKurtosis = 1.0;

}  // namespace

ContactStressFigures median_of(const std::vector<ContactStressFigures>& packings) {
  ContactStressFigures m;
  m.measured = !packings.empty() && std::ranges::all_of(packings, &ContactStressFigures::measured);
  set_medians(m, packings, kFigures);
  return m;
}

Verdict judge_contact_stresses(const ContactStressFigures& f) {
  Verdict v;
  if (!f.measured) {
    v.expect("contact stresses at 0 and 0.2 % (Figs. 6.42-6.43)", false, "the shear did not reach 0.2 %");
    return v;
  }
  // "at the start of shear the distribution of mean normal contact stress
  // approximates a normal distribution".
  v.near("skewness of the mean normal contact stresses at 0 % (Figs. 6.42-6.43)", f.skewness_at_start, 0.0,
         kNormalSkewness);
  v.near("excess kurtosis of the mean normal contact stresses at 0 % (Figs. 6.42-6.43)", f.kurtosis_at_start, 0.0,
         kNormalKurtosis);
  // "With the exception of contacts carrying very small normal forces the
  // distribution remains essentially normal."
  v.near("skewness at 0.2 %, very small normal forces left out (Figs. 6.42-6.43)", f.skewness_late, 0.0,
         kNormalSkewness);
  v.near("excess kurtosis at 0.2 %, very small normal forces left out (Figs. 6.42-6.43)", f.kurtosis_late, 0.0,
         kNormalKurtosis);
  // "as the deviator strain is applied the spread of the distributions
  // increases".
  v.above("spread of the mean normal contact stresses at 0.2 % over at 0 %", f.spread_gain, 1.0);
  // "with a small increase in the average mean normal contact stress":
  // small beside the assembly's own mean stress, which the constant-volume
  // shear builds (Fig. 6.25); Hertz's N / (pi a^2) grows as N^(1/3).
  v.above("mean normal contact stress at 0.2 % over at 0 %", f.mean_gain, 1.0);
  v.below("that gain against the region's mean stress gain (small)", f.mean_gain, f.stress_gain);
  // 6.4.3: past 7 % of the smaller diameter the Hertzian laws no longer hold.
  v.at_most("contacts past 7 % overlap of the smaller diameter", f.over_overlap_limit, 0.0);
  return v;
}

}  // namespace dem::validation
