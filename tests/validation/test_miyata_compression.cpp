// Miyata, Mustoe, Nakagawa & Sugano (2002), 3.2-3.3: the reduced cases of
// cases/miyata (narrower samples of the four of Table 1, loaded by a plate
// to 900 kPa, and a smaller cell of the 3D ellipsoids, to 700 kPa). Each
// run is deterministic; each test prints what it measured and asserts what
// the seed's text states and the reduced samples show robustly
// (docs/VALIDATION.md lists the figures, reduced and full).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "miyata_compression.h"

namespace dem::validation {
namespace {

struct Reduced {
  MiyataRun run;
  MiyataFigures figures;
};

Reduced run_case(const std::string& file) {
  Reduced r;
  r.run = run_miyata_compression(std::filesystem::path(DEM_CASES_DIR) / "miyata" / file);
  r.figures = miyata_figures(r.run);
  print_miyata_report(stdout, r.run, r.figures);
  return r;
}

Reduced run_reduced(const std::string& name) { return run_case(name + "_reduced.case.txtpb"); }

// What every sample shows (Fig. 26, 3.2(3); Fig. 35): dem_validate's
// verdict (tools/dem_validate/miyata_compression.cpp: judge_miyata).
void expect_verdict(const Reduced& r) {
  const Verdict verdict = judge_miyata(r.run, r.figures);
  verdict.print(stdout, r.run.name);
  EXPECT_TRUE(verdict.passed()) << verdict;
}

// The reduced 2D cases ask for ten force distribution snapshots.
void expect_force_distribution(const Reduced& r) {
  ASSERT_TRUE(r.run.results.force_distribution.has_value());
  for (const analysis::PlateForceDistribution& d : *r.run.results.force_distribution) EXPECT_EQ(d.snapshots, 10);
}

TEST(MiyataCompression, CirclesSmoothSurface) {
  const Reduced r = run_reduced("cs");
  expect_verdict(r);
  expect_force_distribution(r);
}

TEST(MiyataCompression, CirclesRoughSurface) {
  const Reduced r = run_reduced("cr");
  expect_verdict(r);
  expect_force_distribution(r);
}

// The crests of the rough surface collapse under the plate in intermittent
// stress releases (Fig. 26's circular samples). Whether the reduced sample
// (about 120 discs) happens to have one depends on round-off; the full
// sample (309 discs, Table 1's 10 m) shows them, while its smooth twin CS
// loads without any.
TEST(MiyataCompression, CirclesRoughSurfaceReleasesStressWhereTheSmoothOneDoesNot) {
  const Reduced rough = run_case("cr.case.txtpb");
  expect_verdict(rough);
  EXPECT_GE(rough.figures.drops, 1);
  EXPECT_GT(rough.figures.largest_drop, 0.05);
  const Reduced smooth = run_case("cs.case.txtpb");
  expect_verdict(smooth);
  EXPECT_EQ(smooth.figures.drops, 0);
}

TEST(MiyataCompression, SuperquadricsSmoothSurface) {
  const Reduced r = run_reduced("ss");
  expect_verdict(r);
  expect_force_distribution(r);
}

TEST(MiyataCompression, SuperquadricsRoughSurface) {
  const Reduced r = run_reduced("sr");
  expect_verdict(r);
  expect_force_distribution(r);
}

// Section 3.3: ellipsoids (Hertz, eq. 47-49) in a periodic cell, loaded to
// 700 kPa with the seed's 3D states (100 and 400 kPa). The same three
// states and contact counts (Figs. 32, 33); with some eight contacts on the
// reduced loading plate its force distribution is only printed.
//
// The reduced sample (about 45 ellipsoids, three layers) gives way now and
// then under the plate as a whole - every particle shifts by millimetres
// and the plate's stress falls by up to 99 %, a rearrangement whose energy
// the books account for (docs/VALIDATION.md, the reduced 3D case) - and
// whether one falls in the final state depends on the packing and on
// round-off: over 23 packing seeds the final state's R² ranged from 0.0004
// to 0.9998, and a change of the contact search by round-off alone (1e-13
// m) moves such collapses from one packing to another - seven packings
// passed every check with one build and four failed one with the other,
// while over the next sixteen the second build did better than the first.
// What the seed states is of its 1,500-particle sample (3.3(2)); a
// 45-particle packing is one draw of it. So the case runs with its own
// seed and fourteen more (about 40 CPU seconds): each must reach the
// target stress, and every other check of the seed's figures must hold for
// the typical packing - a majority of the fifteen - with its bound
// unchanged.
std::filesystem::path seeded_case(const std::string& file, unsigned seed) {
  std::ifstream in(std::filesystem::path(DEM_CASES_DIR) / "miyata" / file);
  std::stringstream text;
  text << in.rdbuf();
  const std::regex packing_seed("seed: [0-9]+");
  EXPECT_TRUE(std::regex_search(text.str(), packing_seed)) << file << " has no packing seed to change";
  const std::string replaced = std::regex_replace(text.str(), packing_seed, "seed: " + std::to_string(seed));
  const std::filesystem::path dir = std::filesystem::path(DEM_VALIDATION_TEST_OUTPUT) / "miyata_seeds";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / ("seed_" + std::to_string(seed) + "_" + file);
  std::ofstream(path) << replaced;
  return path;
}

TEST(MiyataCompression, EllipsoidsReduced) {
  const std::string file = "ellipsoids_reduced.case.txtpb";
  std::vector<unsigned> seeds = {2002u};  // the case's own, and fourteen more
  for (unsigned seed = 1; seed <= 14; ++seed) seeds.push_back(seed);
  std::map<std::string, std::vector<unsigned>> failed_by;  // check -> the packings it failed for
  std::vector<std::string> checks;
  std::vector<double> r_squared;
  for (const unsigned seed : seeds) {
    const MiyataRun run = run_miyata_compression(seeded_case(file, seed));
    const MiyataFigures figures = miyata_figures(run);
    std::printf("packing seed %u:\n", seed);
    print_miyata_report(stdout, run, figures);
    EXPECT_EQ(run.settings.transition_stress, 100e3);
    EXPECT_EQ(run.target_stress, 700e3);
    EXPECT_GE(run.results.last.stress, run.target_stress) << "packing seed " << seed;
    const Verdict verdict = judge_miyata(run, figures);
    verdict.print(stdout, run.name + " seed " + std::to_string(seed));
    for (const Check& check : verdict.checks()) {
      if (std::find(checks.begin(), checks.end(), check.name) == checks.end()) checks.push_back(check.name);
      if (!check.passed) failed_by[check.name].push_back(seed);
    }
    r_squared.push_back(figures.final_r_squared);
  }
  std::sort(r_squared.begin(), r_squared.end());
  std::printf("final state's R² over the packings: lowest %.4f, median %.4f, highest %.4f\n", r_squared.front(),
              r_squared[r_squared.size() / 2], r_squared.back());
  for (const std::string& check : checks) {
    const std::vector<unsigned>& failed = failed_by[check];
    std::string seeds_failed;
    for (unsigned seed : failed) seeds_failed += " " + std::to_string(seed);
    std::printf("%s: holds for %zu of %zu packings%s%s\n", check.c_str(), seeds.size() - failed.size(), seeds.size(),
                failed.empty() ? "" : "; fails for seeds", seeds_failed.c_str());
    EXPECT_GT(seeds.size() - failed.size(), seeds.size() / 2)
        << check << " fails for the packing seeds" << seeds_failed;
  }
}

}  // namespace
}  // namespace dem::validation
