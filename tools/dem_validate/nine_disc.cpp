#include "nine_disc.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <stdexcept>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/programme.h"

namespace dem::validation {

namespace {

constexpr std::size_t kLoadingEnd = 40;       // Figs. 6-7: walls stop after 40 cycles (fast loading)
constexpr std::size_t kSlowLoadingEnd = 120;  // Fig. 7: 0.04 per cycle for 120 cycles

double half_peak_to_peak(const std::vector<double>& f, std::size_t from) {
  const auto [lo, hi] = std::minmax_element(f.begin() + static_cast<std::ptrdiff_t>(from), f.end());
  return 0.5 * (*hi - *lo);
}

double mean(const std::vector<double>& f, std::size_t from) {
  return std::accumulate(f.begin() + static_cast<std::ptrdiff_t>(from), f.end(), 0.0) /
         static_cast<double>(f.size() - from);
}

}  // namespace

ContactHistory follow_contact_c(const std::filesystem::path& case_file) {
  const io::LoadedCase loaded = io::load_case_file(case_file);
  const io::CaseDefinition def = io::convert_case(loaded.message, loaded.source);
  const auto probe = std::find_if(def.output.probes.begin(), def.output.probes.end(),
                                  [](const io::Probe& p) { return p.name == "C"; });
  if (probe == def.output.probes.end()) {
    throw std::runtime_error(case_file.string() + ": the case defines no contact probe named \"C\"");
  }
  World world(def.world);
  ContactHistory history;
  history.variant = def.name;
  auto record = [&](const World& w) {
    const auto c = w.contact_between(probe->first, probe->second);
    history.normal_force.push_back(c ? c->normal_force : 0.0);
    history.shear_force.push_back(c ? c->shear_force : 0.0);
    return true;
  };
  for (const StageDef& stage : def.stages) run_stage(world, stage, 1, record);
  return history;
}

CompressionReport run_compression(const std::filesystem::path& cases_dir) {
  CompressionReport r;
  r.undamped = follow_contact_c(cases_dir / "nine_disc_undamped.case.txtpb");
  r.contact_damping = follow_contact_c(cases_dir / "nine_disc_contact_damping.case.txtpb");
  r.global_damping = follow_contact_c(cases_dir / "nine_disc_global_damping.case.txtpb");
  r.damped = follow_contact_c(cases_dir / "nine_disc_damped.case.txtpb");
  r.slow = follow_contact_c(cases_dir / "nine_disc_slow.case.txtpb");
  r.equilibrium_force = r.damped.normal_force.back();
  r.undamped_mean = mean(r.undamped.normal_force, kLoadingEnd);
  r.undamped_amplitude = half_peak_to_peak(r.undamped.normal_force, kLoadingEnd);
  r.slow_amplitude = half_peak_to_peak(r.slow.normal_force, kSlowLoadingEnd);
  for (const ContactHistory* h : {&r.contact_damping, &r.global_damping, &r.damped}) {
    r.damped_spread = std::max(r.damped_spread, std::abs(h->normal_force.back() / r.equilibrium_force - 1.0));
  }
  return r;
}

DistortionReport run_distortion(const std::filesystem::path& cases_dir) {
  DistortionReport r;
  r.phi15_ks2_3 = follow_contact_c(cases_dir / "nine_disc_distortion_phi15_ks2_3.case.txtpb");
  r.phi15_ks1 = follow_contact_c(cases_dir / "nine_disc_distortion_phi15_ks1.case.txtpb");
  r.phi30_ks2_3 = follow_contact_c(cases_dir / "nine_disc_distortion_phi30_ks2_3.case.txtpb");
  r.phi30_ks1 = follow_contact_c(cases_dir / "nine_disc_distortion_phi30_ks1.case.txtpb");
  r.distortion_start = kSlowLoadingEnd + 1500;  // compress 120 cycles, hold 1500 (the distortion cases)
  return r;
}

void write_nine_disc_csv(const CompressionReport& c, const DistortionReport& d, const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  const auto path = out_dir / "nine_disc.csv";
  std::ofstream out(path);
  out.precision(17);
  out << "cycle";
  const ContactHistory* compression[] = {&c.undamped, &c.contact_damping, &c.global_damping, &c.damped, &c.slow};
  for (const ContactHistory* h : compression) out << ',' << h->variant;
  out << '\n';
  for (std::size_t k = 0; k < c.damped.normal_force.size(); ++k) {
    out << k + 1;
    for (const ContactHistory* h : compression) out << ',' << h->normal_force[k];
    out << '\n';
  }
  if (!out) throw std::runtime_error("cannot write " + path.string());

  const auto distortion_path = out_dir / "nine_disc_distortion.csv";
  std::ofstream dist(distortion_path);
  dist.precision(17);
  dist << "cycle";
  const ContactHistory* distortion[] = {&d.phi15_ks2_3, &d.phi15_ks1, &d.phi30_ks2_3, &d.phi30_ks1};
  for (const ContactHistory* h : distortion) dist << ',' << h->variant << "_Fn," << h->variant << "_Fs";
  dist << '\n';
  for (std::size_t k = 0; k < d.phi15_ks1.normal_force.size(); ++k) {
    dist << k + 1;
    for (const ContactHistory* h : distortion) dist << ',' << h->normal_force[k] << ',' << h->shear_force[k];
    dist << '\n';
  }
  if (!dist) throw std::runtime_error("cannot write " + distortion_path.string());
}

namespace {

// The largest |a - b| / a of two histories' normal forces from `from` on.
double largest_relative_difference(const ContactHistory& a, const ContactHistory& b, std::size_t from) {
  double worst = 0.0;
  for (std::size_t k = from; k < a.normal_force.size() && k < b.normal_force.size(); ++k) {
    worst = std::max(worst, std::abs(a.normal_force[k] - b.normal_force[k]) / a.normal_force[k]);
  }
  return worst;
}

}  // namespace

Verdict judge_nine_disc(const CompressionReport& c, const DistortionReport& d) {
  Verdict verdict;
  const double feq = c.equilibrium_force;
  // Fig. 6: contact, global and both dampings reach the same F_eq within 1%;
  // without damping the force oscillates about F_eq and does not settle.
  verdict.below("Fig. 6: damped runs' spread about F_eq", c.damped_spread, 0.01);
  verdict.near("Fig. 6: undamped mean / F_eq", c.undamped_mean / feq, 1.0, 0.01);
  verdict.above("Fig. 6: undamped amplitude / F_eq", c.undamped_amplitude / feq, 0.05);
  verdict.below("Fig. 6: undamped amplitude / F_eq (seed: about 0.15)", c.undamped_amplitude / feq, 0.5);
  // Damped: settled at the end (the last 500 cycles vary by under 1e-4 F_eq).
  const auto& f = c.damped.normal_force;
  if (f.size() >= 500) {
    const auto [lo, hi] = std::minmax_element(f.end() - 500, f.end());
    verdict.below("Fig. 6: damped variation over the last 500 cycles / F_eq", (*hi - *lo) / feq, 1e-4);
  } else {
    verdict.expect("Fig. 6: 500 cycles of the damped run", false, std::to_string(f.size()) + " cycles");
  }
  // Fig. 7: faster loading, larger oscillation.
  verdict.above("Fig. 7: amplitude at 0.12 over 3x the amplitude at 0.04", c.undamped_amplitude,
                3.0 * c.slow_amplitude);
  // Fig. 9(a): at 15 deg the two stiffness ratios nearly coincide; (b) at 30 deg they deviate significantly.
  const std::size_t s = d.distortion_start;
  const double d15 = largest_relative_difference(d.phi15_ks2_3, d.phi15_ks1, s);
  const double d30 = largest_relative_difference(d.phi30_ks2_3, d.phi30_ks1, s);
  verdict.below("Fig. 9a: ks/kn 2/3 against 1 at 15 deg, largest relative difference", d15, 0.03);
  verdict.above("Fig. 9b: that difference at 30 deg over twice the one at 15 deg", d30, 2.0 * d15);
  // Fig. 9(b): after undistorted compression F_n is less for ks/kn = 1 (the
  // walls' shear carries more load); as shearing proceeds it overtakes the
  // 2/3 one, peaks, and slip sets in and the force falls back.
  const auto& low = d.phi30_ks2_3.normal_force;
  const auto& high = d.phi30_ks1.normal_force;
  if (s < high.size() && s < low.size()) {
    verdict.below("Fig. 9b: F_n at the start of distortion, ks/kn 1 against 2/3", high[s], low[s]);
    bool overtakes = false;
    for (std::size_t k = s; k < high.size() && k < low.size(); ++k) overtakes = overtakes || high[k] > low[k];
    verdict.expect("Fig. 9b: ks/kn 1 overtakes 2/3 under shear", overtakes);
    const auto peak = std::max_element(high.begin() + static_cast<std::ptrdiff_t>(s), high.end());
    verdict.above("Fig. 9b: ks/kn 1 peak over 1.05 of its end", *peak, 1.05 * high.back());
    verdict.above("Fig. 9b: cycles after the peak", static_cast<double>(high.end() - peak), 100.0);
  } else {
    verdict.expect("Fig. 9b: distortion cycles recorded", false);
  }
  return verdict;
}

}  // namespace dem::validation
