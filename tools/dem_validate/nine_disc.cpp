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

}  // namespace dem::validation
