#include "randall_assembly.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "dem/analysis/assembly_sample.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/csv_file.h"
#include "dem/io/csv_writers.h"
#include "dem/io/regions_csv.h"
#include "dem/programme.h"

namespace dem::validation {

namespace {

constexpr int kRoseBins = 36;       // 10 degree classes, as Randall's roses
constexpr int kObliquityBins = 20;  // 0.1 wide over [-1, 1] (Figs. 6.18-6.19)

// The deviator strains at which chapter 6 shows the assembly.
constexpr double kVelocityStrain = 0.00005;  // 0.005 % (Figs. 6.31, 6.38-6.39)
constexpr double kRoseStrain = 0.00015;      // 0.015 % (Figs. 6.36-6.37)
constexpr double kForceStrain = 0.001;       // 0.1 % (Figs. 6.32-6.33)
constexpr double kLateStrain = 0.002;        // 0.2 % (Figs. 6.40-6.41)

void write_bins(io::CsvFile& file, const std::string& state, const std::string& kind,
                const std::vector<analysis::Bin>& bins) {
  for (const analysis::Bin& b : bins) file.write_row(state, kind, b.low, b.high, b.contacts, b.share);
}

void write_snapshot(const std::filesystem::path& directory, const World& world) {
  io::write_contacts_csv(directory, world);
  io::write_particles_csv(directory, world);
}

}  // namespace

RandallRun run_randall(const std::filesystem::path& case_file, bool shear,
                       const std::optional<std::filesystem::path>& out) {
  const io::LoadedCase loaded = io::load_case_file(case_file);
  const io::CaseDefinition def = io::convert_case(loaded.message, loaded.source);
  std::vector<analysis::Region> regions;
  for (const io::MeasurementRegion& r : def.output.regions) regions.push_back(io::region_for<2>(r));
  if (regions.empty()) throw std::runtime_error(case_file.string() + ": the case names no output.region");

  RandallRun run;
  run.name = def.name;
  World world(def.world);
  run.particles = world.particle_count();
  std::optional<io::CsvFile> series;
  if (out) {
    series.emplace(*out, "randall.csv",
                   "cycle,deviator_strain,volumetric_strain,out_of_balance,region," + io::region_columns<2>());
  }
  const auto start = std::chrono::steady_clock::now();
  bool compressed = true;
  for (const StageDef& stage : def.stages) {
    if (stage.name == "shear") {
      if (!shear) break;
      double next_capture = kVelocityStrain;
      const auto observe = [&](const World& w) {
        const analysis::AssemblySample sample = analysis::sample(w);
        ShearSample s;
        s.cycle = w.cycle_count();
        const BoxMeasure box = w.box_measure();
        s.deviator_strain = box.deviator_strain;
        s.volumetric_strain = box.volumetric_strain;
        s.out_of_balance = w.assembly_measures().out_of_balance;
        for (const analysis::Region& region : regions) {
          s.regions.push_back(analysis::measure_region(sample, region));
          if (series) {
            series->write_row_then(io::region_values<2>(s.regions.back()), s.cycle, s.deviator_strain,
                                   s.volumetric_strain, s.out_of_balance, region.name);
          }
        }
        const analysis::Region& main = regions.front();
        if (s.deviator_strain >= next_capture) {
          if (next_capture == kVelocityStrain) {
            run.early_sliding_rose = analysis::normal_rose(sample, main, kRoseBins, analysis::RoseOf::kSlidingContacts);
            if (out) write_snapshot(*out / "strain_0.005_percent", w);
            next_capture = kRoseStrain;
          } else if (next_capture == kRoseStrain) {
            run.shear_rose = analysis::normal_rose(sample, main, kRoseBins, analysis::RoseOf::kContacts);
            run.shear_weighted_rose = analysis::normal_rose(sample, main, kRoseBins, analysis::RoseOf::kNormalForce);
            next_capture = kForceStrain;
          } else if (next_capture == kForceStrain) {
            if (out) write_snapshot(*out / "strain_0.1_percent", w);
            next_capture = kLateStrain;
          } else if (next_capture == kLateStrain) {
            run.late_sliding_rose = analysis::normal_rose(sample, main, kRoseBins, analysis::RoseOf::kSlidingContacts);
            next_capture = 1.0;
          }
        }
        run.shear.push_back(std::move(s));
        return true;
      };
      // The first sample counts its strains from the shear's box.
      if (stage.box_control) world.set_box_control(stage.box_control);
      observe(world);
      run_stage(world, stage, def.output.interval, observe);
      continue;
    }
    const StageResult result = run_stage(world, stage);
    compressed = compressed && result.condition_met;
    if (stage.name == "friction") {
      // Quasi-equilibrium at 100 kPa with friction (Randall 6.4.3).
      run.compressed = compressed;
      const analysis::AssemblySample sample = analysis::sample(world);
      const analysis::Region& main = regions.front();
      run.at_rest = analysis::measure_region(sample, main);
      run.friction = world.materials().front().friction;
      run.box_mean_stress = world.box_measure().mean_stress;
      run.out_of_balance = world.assembly_measures().out_of_balance;
      run.rose = analysis::normal_rose(sample, main, kRoseBins, analysis::RoseOf::kContacts);
      run.weighted_rose = analysis::normal_rose(sample, main, kRoseBins, analysis::RoseOf::kNormalForce);
      run.obliquity = analysis::obliquity_histogram(sample, main, run.friction, kObliquityBins);
      if (out) write_snapshot(*out / "at_100_kPa", world);
    }
  }
  run.cycles = world.cycle_count();
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (out) {
    io::CsvFile roses(*out, "roses.csv", "state,kind,angle_low,angle_high,contacts,share");
    write_bins(roses, "100 kPa", "contacts", run.rose);
    write_bins(roses, "100 kPa", "normal force", run.weighted_rose);
    write_bins(roses, "0.015 %", "contacts", run.shear_rose);
    write_bins(roses, "0.015 %", "normal force", run.shear_weighted_rose);
    write_bins(roses, "0.005 %", "sliding contacts", run.early_sliding_rose);
    write_bins(roses, "0.2 %", "sliding contacts", run.late_sliding_rose);
    io::CsvFile obliquity(*out, "obliquity.csv", "state,kind,obliquity_low,obliquity_high,contacts,share");
    write_bins(obliquity, "100 kPa", "obliquity", run.obliquity);
  }
  return run;
}

namespace {

// How far a rose departs from a circle: the spread of its classes' shares
// over their mean (0 for a circle).
double rose_roughness(const std::vector<analysis::Bin>& rose) {
  if (rose.empty()) return 0.0;
  const double mean = 1.0 / static_cast<double>(rose.size());
  double sum = 0.0;
  for (const analysis::Bin& b : rose) sum += (b.share - mean) * (b.share - mean);
  return std::sqrt(sum / static_cast<double>(rose.size())) / mean;
}

double sliding_share(const std::vector<analysis::Bin>& obliquity) {
  if (obliquity.empty()) return 0.0;
  return obliquity.front().share + obliquity.back().share;  // the classes at -1 and +1
}

struct Peak {
  double value = 0.0;
  double strain = 0.0;
};

template <typename Measure>
Peak peak_of(const RandallRun& run, std::size_t region, Measure measure) {
  Peak p{-1e300, 0.0};
  for (const ShearSample& s : run.shear) {
    const double v = measure(s.regions[region]);
    if (v > p.value) p = {v, s.deviator_strain};
  }
  return p;
}

}  // namespace

void print_randall(std::FILE* out, const RandallRun& run) {
  const analysis::RegionMeasures& m = run.at_rest;
  std::fprintf(out, "%s: %d spheres, %llu cycles in %.1f s%s\n", run.name.c_str(), run.particles,
               static_cast<unsigned long long>(run.cycles), run.seconds,
               run.compressed ? "" : " (compression or friction stage did NOT settle)");
  std::fprintf(out,
               "  at 100 kPa (box mean %.1f kPa, Delta F / F %.3f), region \"%s\" with tan(phi) = %.2f:\n"
               "    coordination %.3f (without rattlers %.3f; %d of %d particles rattlers), porosity %.3f\n"
               "    contact force max %.3f N, mean %.3f N, F_max / F_mean %.2f\n"
               "    stress %.1f / %.1f kPa, sin(phi) %.4f; fabric anisotropy %.4f (weighted %.4f); rose roughness %.3f "
               "(weighted %.3f)\n"
               "    sliding contacts %.1f %% (obliquity classes at +-1: %.1f %%)\n",
               run.box_mean_stress / 1e3, run.out_of_balance, m.region.c_str(), run.friction, m.coordination,
               m.mechanical_coordination, m.rattlers, m.particles, m.porosity, m.max_normal_force, m.mean_normal_force,
               m.mean_normal_force > 0.0 ? m.max_normal_force / m.mean_normal_force : 0.0,
               m.principal_stress.values[0] / 1e3, m.principal_stress.values[1] / 1e3, m.sin_phi, m.fabric.anisotropy,
               m.weighted_fabric.anisotropy, rose_roughness(run.rose), rose_roughness(run.weighted_rose),
               100.0 * m.sliding_fraction, 100.0 * sliding_share(run.obliquity));
  std::fprintf(out,
               "    Randall: coordination 3.15 (uniform), 3.57 (graded); F_max / F_mean 0.53/0.143 = 3.7 "
               "(uniform), 0.59/0.123 = 4.8 (graded); porosity 16 %% and 14 %%\n");
  if (run.shear.empty()) return;
  std::fprintf(out, "  constant-volume shear, %zu samples to deviator strain %.4f %%:\n", run.shear.size(),
               100.0 * run.shear.back().deviator_strain);
  for (std::size_t r = 0; r < run.shear.front().regions.size(); ++r) {
    const Peak sin_phi = peak_of(run, r, [](const auto& x) { return x.sin_phi; });
    const Peak anisotropy = peak_of(run, r, [](const auto& x) { return x.fabric.anisotropy; });
    const Peak sliding = peak_of(run, r, [](const auto& x) { return x.sliding_fraction; });
    double share_at_peak = 0.0;
    for (const ShearSample& s : run.shear) {
      if (s.deviator_strain == sin_phi.strain) share_at_peak = s.regions[r].tangential_share;
    }
    const auto& first = run.shear.front().regions[r];
    const auto& last = run.shear.back().regions[r];
    std::fprintf(out,
                 "    region \"%s\": peak sin(phi) %.4f at %.4f %% strain, tangential share there %.1f %%; sliding "
                 "at most %.1f %%; anisotropy %.4f -> peak %.4f at %.4f %%; coordination %.3f -> %.3f; mean stress "
                 "%.1f -> %.1f kPa\n",
                 first.region.c_str(), sin_phi.value, 100.0 * sin_phi.strain, 100.0 * share_at_peak,
                 100.0 * sliding.value, first.fabric.anisotropy, anisotropy.value, 100.0 * anisotropy.strain,
                 first.coordination, last.coordination, first.mean_stress / 1e3, last.mean_stress / 1e3);
  }
  double worst = 0.0;
  for (const ShearSample& s : run.shear) worst = std::max(worst, s.out_of_balance);
  std::fprintf(out,
               "    largest Delta F / F during the shear %.4f; Randall: peak sin(phi) about 0.3 (uniform, just "
               "after 0.1 %%) and 0.36 (graded, by 0.05 %%), tangential share 15 %% and 14 %%, sliding never "
               "above 25 %%\n",
               worst);
}

Verdict judge_randall_compression(const RandallRun& run) {
  Verdict v;
  const analysis::RegionMeasures& m = run.at_rest;
  v.expect("compressed to 100 kPa and in quasi-equilibrium with friction", run.compressed);
  v.near("box mean stress / 100 kPa", run.box_mean_stress / 1e5, 1.0, 0.01);
  // "out of balance forces an order of magnitude less than contact forces" (6.4.2).
  v.below("Delta F / F at 100 kPa", run.out_of_balance, 0.1);
  // "All these figures give a fair approximation to a circular
  // distribution indicating no significant structural anisotropy."
  v.below("fabric anisotropy Phi_1 - Phi_2 at 100 kPa", m.fabric.anisotropy, 0.1);
  // "hardly any contacts are sliding" once friction is added (Figs.
  // 6.18-6.19).
  v.below("share of sliding contacts at 100 kPa with friction", m.sliding_fraction, 0.05);
  v.above("coordination at 100 kPa", m.coordination, 3.0);
  v.below("coordination at 100 kPa", m.coordination, 4.5);
  return v;
}

Verdict judge_randall_shear(const RandallRun& run, double sliding_bound) {
  Verdict v;
  if (run.shear.size() < 3) {
    v.expect("shear samples", false, std::to_string(run.shear.size()));
    return v;
  }
  // Region 0: the case's first measurement circle, well inside the walls
  // (Randall's analysis regions).
  double worst = 0.0;
  for (const ShearSample& s : run.shear) worst = std::max(worst, s.out_of_balance);
  v.below("largest Delta F / F during the shear (quasi-static)", worst, 0.05);
  const analysis::RegionMeasures& end = run.shear.back().regions[0];
  // Randall's Hertzian assemblies are stiff: sin(phi) reaches about 0.3
  // (uniform) and 0.36 (graded) within 0.1 % (Fig. 6.24).
  v.above("sin(phi) at the end of the shear", end.sin_phi, 0.25);
  v.below("sin(phi) at the end of the shear", end.sin_phi, 0.45);
  double at_tenth = 0.0;
  for (const ShearSample& s : run.shear) {
    if (s.deviator_strain <= 0.001) at_tenth = s.regions[0].sin_phi;
  }
  v.above("sin(phi) at 0.1 % strain over at the end (a stiff rise)", at_tenth, 0.8 * end.sin_phi);
  // "never more than 25 % of contacts are sliding at any one time" (Fig. 6.28).
  const Peak sliding = peak_of(run, 0, [](const auto& x) { return x.sliding_fraction; });
  v.below("largest share of sliding contacts", sliding.value, sliding_bound);
  // "The tangential force contribution to the deviator stress can be seen
  // to be small, in the order of 14 % ... 15 %".
  v.above("tangential forces' share of the deviator at the end", end.tangential_share, 0.0);
  v.below("tangential forces' share of the deviator at the end", end.tangential_share, 0.3);
  // The structural anisotropy grows with sin(phi) (Fig. 6.29): the one the
  // shear induces, Phi_yy - Phi_xx along the compressed and the extended
  // axes (a small sample starts with some anisotropy in any direction).
  const auto induced = [](const analysis::RegionMeasures& m) { return m.fabric.tensor(1, 1) - m.fabric.tensor(0, 0); };
  v.above("induced anisotropy Phi_yy - Phi_xx at the end over at the start", induced(end),
          induced(run.shear.front().regions[0]));
  // "a smooth build up of isotropic stress" at constant volume (Fig. 6.25).
  v.above("mean stress at the end over at the start of the shear", end.mean_stress,
          run.shear.front().regions[0].mean_stress);
  return v;
}

}  // namespace dem::validation
