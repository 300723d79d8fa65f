// dem_validate: reproduces the seeds' checks and writes their figures as CSV.
//   dem_validate nine-disc --out DIR        (Cundall & Strack 1979, Figs. 6-9)
//   dem_validate hertz-impact --out DIR     (Randall 1989, 5.3.1)
//   dem_validate oblique-impact --out DIR   (Randall 1989, 5.4)
//   dem_validate restitution --out DIR      (Miyata et al. 2002, eq. 17)
//   dem_validate mindlin-loading --out DIR  (Randall 1989, 5.2)
//   dem_validate box-settle --out DIR       (3D settling: weight on the floor, energy budget)
//   dem_validate verification --out DIR [--seeds S,...]      (Cundall & Strack 1979, Tables 1-3: stages A and B)
//   dem_validate randall-compression --case FILE --out DIR [--seeds S,...]  (Randall 1989, 6.4.3: 100 kPa)
//   dem_validate randall-shear --case FILE --out DIR [--seeds S,...]        (6.5.2: constant-volume shear)
//   dem_validate randall-shear --case FILE --out DIR --con1 C,... [--seeds S,...] [--to-strain E]
//                                           (6.5.1, Fig. 6.22: the continuum shear by mass-proportional damping)
//   dem_validate randall-centripetal --case FILE --out DIR [--seeds S,...]  (6.4.2: centripetal compaction)
//   dem_validate hopper --case FILE --out DIR [--runs 45:10,30:10,...]  (Randall 1989, 6.2: discharge rates)
//   dem_validate deposition --case FILE --out DIR [--seeds S,...]  (Randall 1989, 6.3: pluvial deposition)
//   dem_validate rolling-to-rest --out DIR  (rolling resistance: a ball stops where the closed form says)
//   dem_validate angle-of-repose --out DIR [--packings N]  (rolling resistance: the repose angle of a heap by mu_r)
//   dem_validate miyata-compression --case FILE --out DIR [--packings N | --seeds S,... | --runs DIR ...]
//                                           (Miyata et al. 2002, 3.2-3.3: plate loading, Figs. 26-37)
//   dem_validate miyata-surfaces --out DIR [--packings N] [--reduced]
//                                           (Miyata et al. 2002, 3.2: CS, CR, SS and SR compared)
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact_mechanics.h"
#include "dem/version.h"
#include "deposition.h"
#include "hopper.h"
#include "miyata_commands.h"
#include "nine_disc.h"
#include "randall_assembly.h"
#include "randall_centripetal.h"
#include "randall_damping.h"
#include "rolling.h"
#include "verification.h"

namespace {

void report_nine_disc(const dem::validation::CompressionReport& c, const dem::validation::DistortionReport& d) {
  const double feq = c.equilibrium_force;
  std::printf("nine-disc test, normal force at contact C (Cundall & Strack 1979, Figs. 6-9)\n");
  std::printf("  F_eq (contact + global damping, cycle %zu)  %.6e\n", c.damped.normal_force.size(), feq);
  for (const auto* h : {&c.contact_damping, &c.global_damping, &c.damped}) {
    std::printf("  %-28s final %.6e  (%+.4f%% of F_eq)\n", h->variant.c_str(), h->normal_force.back(),
                100.0 * (h->normal_force.back() / feq - 1.0));
  }
  std::printf("  undamped: mean %.6e (%+.3f%% of F_eq), amplitude %.4f F_eq (seed: about 0.15)\n", c.undamped_mean,
              100.0 * (c.undamped_mean / feq - 1.0), c.undamped_amplitude / feq);
  std::printf("  loading speed 0.12 vs 0.04: amplitude %.4f vs %.4f F_eq (Fig. 7)\n", c.undamped_amplitude / feq,
              c.slow_amplitude / feq);
  const dem::validation::Fig7Curves& b = c.fig7b;
  std::printf(
      "  Fig. 7(b), k = 1.5e8, loading speed 0.36 vs 0.12: mean %.6e vs %.6e (%+.3f%%, %+.3f%% of F_eq), amplitude "
      "%.4f vs %.4f F_eq, mean periods %.2f and %.2f cycles\n",
      b.fast_mean, b.slow_mean, 100.0 * (b.fast_mean / feq - 1.0), 100.0 * (b.slow_mean / feq - 1.0),
      b.fast_amplitude / feq, b.slow_amplitude / feq, b.fast_period, b.slow_period);
  std::printf(
      "  undamped: the slow run against the fast one superposed (linearity): largest difference %.2e F_eq; "
      "mean periods %.2f and %.2f cycles; amplitude over the first and second half of the hold %.4f, %.4f\n",
      c.superposition_error, c.fast_period, c.slow_period, c.early_amplitude, c.late_amplitude);
  const std::size_t s = d.distortion_start;
  for (const auto* h : {&d.phi15_ks2_3, &d.phi15_ks1, &d.phi30_ks2_3, &d.phi30_ks1}) {
    const auto peak = std::max_element(h->normal_force.begin() + static_cast<std::ptrdiff_t>(s), h->normal_force.end());
    std::printf("  %-36s F_n start %.4e  peak %.4e (distortion cycle %td)  end %.4e\n", h->variant.c_str(),
                h->normal_force[s], *peak, peak - h->normal_force.begin() - static_cast<std::ptrdiff_t>(s),
                h->normal_force.back());
  }
}

// The repository's cases when this is a build; an installed program's
// beside it (<prefix>/bin/dem_validate -> <prefix>/share/dem/cases).
std::filesystem::path default_cases() {
  if (std::filesystem::exists(DEM_DEFAULT_CASES_DIR)) return DEM_DEFAULT_CASES_DIR;
  std::error_code error;
  const auto program = std::filesystem::read_symlink("/proc/self/exe", error);
  return program.parent_path().parent_path() / "share" / "dem" / "cases";
}

}  // namespace

// Exit codes: 0 every check passed; 1 a check failed (the verdict says
// which) or the run could not be done; 2 a bad command line.
constexpr int kCheckFailed = 1;
constexpr int kFailure = 1;

int main(int argc, char** argv) {
  CLI::App app{"dem_validate: reproduce the seeds' validation checks and write their figures"};
  app.set_version_flag("--version", "dem_validate " DEM_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Every subcommand writes its figures as CSV files into --out DIR (required: nothing is written\n"
      "where it was not asked for), prints them and ends with its verdict: each check against the seed's\n"
      "or the theory's bound, pass or FAIL. dem_validate SUBCOMMAND --help lists its options.\n"
      "Exit codes: 0 every check passed, 1 a check failed or the run failed, 2 bad arguments.");
  std::filesystem::path out;
  std::filesystem::path cases = default_cases();
  auto* nine = app.add_subcommand("nine-disc", "Cundall & Strack (1979) nine-disc test, Figs. 6-9");
  nine->add_option("--out", out, "directory for nine_disc.csv and nine_disc_distortion.csv")->required();
  nine->add_option("--cases", cases, "directory holding the cases/ball case files")->check(CLI::ExistingDirectory);
  auto* hertz =
      app.add_subcommand("hertz-impact", "Hertz normal impact, sphere-wall and sphere-sphere (Randall 5.3.1)");
  auto* oblique = app.add_subcommand("oblique-impact", "oblique impact sweep 0-90 degrees (Randall 5.4, Maw et al.)");
  auto* restitution = app.add_subcommand("restitution", "linear spring-dashpot restitution (Miyata eq. 17)");
  auto* mindlin = app.add_subcommand("mindlin-loading", "Mindlin-Deresiewicz loading history (Randall 5.2)");
  auto* box = app.add_subcommand("box-settle", "spheres settle in a 3D box: weight on the floor, energy budget");
  for (auto* sub : {hertz, oblique, restitution, mindlin, box}) {
    sub->add_option("--out", out, "directory for the CSV files (created)")->required();
  }
  box->add_option("--cases", cases, "directory holding cases/validation")->check(CLI::ExistingDirectory);
  std::filesystem::path verification_case;
  std::vector<std::uint64_t> verification_seeds;
  auto* verification = app.add_subcommand(
      "verification", "Cundall & Strack (1979) verification assembly, Tables 1-3: stages A and B (cases/ball)");
  verification
      ->add_option("--case", verification_case,
                   "one cases/ball/verification_assembly*.case.txtpb file alone (default: Tables 1-3)")
      ->check(CLI::ExistingFile);
  verification->add_option("--cases", cases, "directory holding the cases/ball case files")
      ->check(CLI::ExistingDirectory);
  verification->add_option("--seeds", verification_seeds, "packing seeds (default: the cases' own)")->delimiter(',');
  verification->add_option("--out", out, "directory for verification.csv (stages A and B, wall by wall)")->required();
  std::filesystem::path randall_case;
  std::vector<std::uint64_t> randall_seeds;
  auto* randall_compression = app.add_subcommand(
      "randall-compression", "Randall (1989) 6.4.3: a cases/randall assembly compressed to 100 kPa, then friction");
  auto* randall_shear =
      app.add_subcommand("randall-shear", "Randall (1989) 6.5.2: the same, then sheared at constant volume");
  std::vector<double> randall_con1;
  std::optional<double> randall_to_strain;
  randall_shear
      ->add_option("--con1", randall_con1,
                   "6.5.1, Fig. 6.22: shear once for each of Randall's CON1 values (the velocity kept a step, 1 "
                   "no damping), each into OUT/con1_VALUE/, and print the sweep")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0));
  randall_shear
      ->add_option("--to-strain", randall_to_strain,
                   "with --con1: shear to this deviator strain (0.02 = 2 %) instead of the case's")
      ->check(CLI::PositiveNumber);
  auto* randall_centripetal = app.add_subcommand(
      "randall-centripetal",
      "Randall (1989) 6.4.2: centripetal compaction, 100 kPa, shear at constant mean stress in three circles");
  for (auto* sub : {randall_compression, randall_shear, randall_centripetal}) {
    sub->add_option("--case", randall_case, "a cases/randall case file")->required()->check(CLI::ExistingFile);
    sub->add_option("--out", out,
                    "directory for the figures' CSV files (randall.csv or centripetal.csv, ...) and the snapshots")
        ->required();
    sub->add_option("--seeds", randall_seeds,
                    "packing seeds: one run each (in OUT/packing_SEED/), the median packing judged")
        ->delimiter(',');
  }
  std::filesystem::path hopper_case;
  std::vector<std::string> hopper_runs = {"45:10", "30:10", "15:10", "30:5", "30:14"};
  auto* hopper = app.add_subcommand("hopper", "Randall (1989) 6.2: hopper discharge by half-angle and orifice");
  hopper->add_option("--case", hopper_case, "cases/randall/hopper.case.txtpb")->required()->check(CLI::ExistingFile);
  hopper->add_option("--out", out, "directory for hopper.csv, hopper_rates.csv and the velocity fields")->required();
  hopper->add_option("--runs", hopper_runs, "half-angle (deg):orifice (mm) pairs")->delimiter(',');
  std::filesystem::path deposition_case;
  auto* deposition = app.add_subcommand("deposition", "Randall (1989) 6.3: pluvial deposition into a container");
  deposition->add_option("--case", deposition_case, "cases/randall/pluvial_deposition.case.txtpb")
      ->required()
      ->check(CLI::ExistingFile);
  deposition->add_option("--out", out, "directory for the bed's particles.csv and contacts.csv")->required();
  std::vector<std::uint64_t> deposition_seeds;
  deposition->add_option("--seeds", deposition_seeds, "run on these packing seeds (into DIR/packing_SEED/)")
      ->delimiter(',');
  auto* rolling_to_rest = app.add_subcommand("rolling-to-rest", "rolling resistance: a disc and a sphere roll to rest");
  rolling_to_rest->add_option("--out", out, "directory for rolling_to_rest.csv")->required();
  std::vector<double> rolling_frictions = {0.0, 0.025, 0.05, 0.1, 0.2, 0.4};
  auto* repose = app.add_subcommand("angle-of-repose", "rolling resistance: angle of repose of a collapsed column");
  repose->add_option("--out", out, "directory for angle_of_repose.csv")->required();
  repose->add_option("--rolling-friction", rolling_frictions, "the mu_r values, in rising order")->delimiter(',');
  int repose_packings = 5;
  repose->add_option("--packings", repose_packings, "packings of each heap (seeds 11, 12, ...); judged on the median")
      ->check(CLI::Range(1, 1000));
  dem::validation::MiyataOptions miyata_options;
  auto* miyata = app.add_subcommand("miyata-compression",
                                    "a plate loading case of Miyata et al. (2002) 3.2-3.3 (cases/miyata): three "
                                    "states, plate contacts, force distribution, stress drops; over packings");
  miyata->add_option("--case", miyata_options.case_file, "the case file (it must set output.compression)")
      ->required()
      ->check(CLI::ExistingFile);
  miyata
      ->add_option("--runs", miyata_options.runs,
                   "judge these finished runs of the case (directories of dem_run, dem_server or a sweep's "
                   "tasks) instead of running it")
      ->check(CLI::ExistingDirectory);
  auto* miyata_surfaces =
      app.add_subcommand("miyata-surfaces",
                         "Miyata et al. (2002) 3.2: the four samples of Table 1 (CS, CR, SS, SR) over packings: "
                         "circles release stress, rectangles never; rough surfaces have fewer plate contacts");
  bool reduced = false;
  miyata_surfaces->add_flag("--reduced", reduced, "the _reduced cases (4 m wide) instead of the full ones");
  miyata_surfaces->add_option("--cases", cases, "directory holding cases/miyata")->check(CLI::ExistingDirectory);
  for (auto* sub : {miyata, miyata_surfaces}) {
    sub->add_option("--out", out,
                    "directory for the analyses' CSV files and miyata_summary.csv (one packing), or a directory "
                    "per packing (packing_<seed>)");
    sub->add_option("--packings", miyata_options.packings, "packings to run: the case's seed, then 1, 2, ...")
        ->check(CLI::PositiveNumber);
    sub->add_option("--seeds", miyata_options.seeds, "the packing seeds to run instead")->delimiter(',');
    sub->add_option("--jobs", miyata_options.jobs, "runs at a time")->check(CLI::PositiveNumber);
    sub->add_option("--threads", miyata_options.threads, "threads of each run")->check(CLI::PositiveNumber);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;  // --help is not a mistake; a bad command line is exit code 2
  }
  dem::validation::Verdict verdict;
  try {
    if (*hertz) verdict = dem::validation::report_hertz_impact(out);
    if (*oblique) verdict = dem::validation::report_oblique_impact(out);
    if (*restitution) verdict = dem::validation::report_restitution(out);
    if (*mindlin) verdict = dem::validation::report_mindlin_loading(out);
    if (*box) verdict = dem::validation::report_box_settle(cases / "validation" / "box_settle.case.txtpb", out);
    if (*randall_shear && !randall_con1.empty()) {
      verdict = dem::validation::report_con1_sweep(randall_case, randall_con1, out, randall_seeds, randall_to_strain);
    } else if (*randall_compression || *randall_shear) {
      if (randall_to_strain) throw std::runtime_error("--to-strain goes with --con1");
      verdict = dem::validation::report_randall(randall_case, static_cast<bool>(*randall_shear), out, randall_seeds);
    }
    if (*randall_centripetal) verdict = dem::validation::report_centripetal(randall_case, out, randall_seeds);
    if (*hopper) {
      std::vector<dem::validation::HopperRun> runs;
      for (const std::string& spec : hopper_runs) {
        const auto colon = spec.find(':');
        if (colon == std::string::npos) throw std::runtime_error("--runs: expected ANGLE:MM, got " + spec);
        runs.push_back(dem::validation::run_hopper(hopper_case, std::stod(spec.substr(0, colon)),
                                                   1e-3 * std::stod(spec.substr(colon + 1)), out));
        std::printf("%s: %.1f spheres/s\n", runs.back().name.c_str(), runs.back().rate);
        std::fflush(stdout);
      }
      dem::validation::write_hopper_csv(out, runs);
      dem::validation::print_hopper(stdout, runs);
      verdict = dem::validation::judge_hopper(runs);
    }
    if (*deposition) {
      verdict = dem::validation::report_deposition(deposition_case, out, deposition_seeds);
    }
    if (*rolling_to_rest) verdict = dem::validation::report_rolling_to_rest(out);
    if (*repose) {
      std::vector<std::uint64_t> seeds(static_cast<std::size_t>(repose_packings));
      std::iota(seeds.begin(), seeds.end(), std::uint64_t{11});
      verdict = dem::validation::report_angle_of_repose(out, rolling_frictions, seeds);
    }
    if (*verification) {
      std::vector<dem::validation::VerificationRun> runs;
      if (!verification_case.empty()) {
        const std::vector<std::uint64_t> seeds =
            verification_seeds.empty() ? std::vector<std::uint64_t>{0} : verification_seeds;
        for (const std::uint64_t seed : seeds) {
          runs.push_back(dem::validation::run_verification(
              verification_case, verification_seeds.empty() ? std::nullopt : std::optional<std::uint64_t>(seed)));
          dem::validation::print_verification(stdout, runs.back());
          verdict.add(dem::validation::judge_verification(runs.back()));
        }
      } else {
        const auto packings = dem::validation::run_verification_tables(cases / "ball", verification_seeds);
        for (const auto& p : packings) {
          for (const auto& run : p.tables) {
            dem::validation::print_verification(stdout, run);
            verdict.add(dem::validation::judge_verification(run));
            runs.push_back(run);
          }
        }
        dem::validation::print_verification_tables(stdout, packings);
        verdict.add(dem::validation::judge_verification_tables(packings));
      }
      dem::validation::write_verification_csv(out, runs);
    }
    if (*miyata || *miyata_surfaces) {
      if (out.empty() && miyata_options.runs.empty()) throw std::runtime_error("--out is required to run a case");
      miyata_options.out = out;
      verdict = *miyata ? dem::validation::miyata_compression_command(miyata_options)
                        : dem::validation::miyata_surfaces_command(cases, reduced, miyata_options);
    }
    if (*nine) {
      const auto compression = dem::validation::run_compression(cases / "ball");
      const auto distortion = dem::validation::run_distortion(cases / "ball");
      dem::validation::write_nine_disc_csv(compression, distortion, out);
      report_nine_disc(compression, distortion);
      // Fig. 6's amplitude by time step: the seed's 0.15 F_eq fixes the
      // loading time over the period, not the step itself.
      std::printf("  undamped amplitude after 40 cycles of loading, by time step (fraction of the critical step):\n");
      for (const auto& a : dem::validation::undamped_amplitude_by_time_step(
               cases / "ball", {0.02, 0.04, 0.06, 0.08, 0.093, 0.12, 0.15, 0.2, 0.25, 0.3})) {
        std::printf("    %.3f: amplitude %.4f F_eq, loading %.3f periods\n", a.time_step, a.amplitude,
                    a.loading_over_period);
      }
      std::printf("wrote %s and %s\n", (out / "nine_disc.csv").c_str(), (out / "nine_disc_distortion.csv").c_str());
      verdict = dem::validation::judge_nine_disc(compression, distortion);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kFailure;
  }
  // The verdict: each check against the seed's or the theory's bound.
  std::printf("\n");
  verdict.print(stdout, app.get_subcommands().front()->get_name());
  return verdict.passed() ? 0 : kCheckFailed;
}
