// Miyata, Mustoe, Nakagawa & Sugano (2002), 3.2-3.3, over packings: the
// reduced cases of cases/miyata (the four samples of Table 1 4 m wide,
// loaded by a plate to 900 kPa; a smaller cell of the 3D ellipsoids, to 700
// kPa) and the full circular samples. What the seed states of its one
// sample is judged as a statement of the typical packing: each check of
// dem_validate's judge_miyata must hold in most packings (four of five),
// Fig. 30's shares in their medians; the reduced cases are judged on what
// a small sample can show. Each test prints its figures (docs/VALIDATION.md
// lists them, reduced and full).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "miyata_packings.h"

namespace dem::validation {
namespace {

std::filesystem::path case_file(const std::string& name) {
  return std::filesystem::path(DEM_CASES_DIR) / "miyata" / (name + ".case.txtpb");
}

// `folder` keeps apart the runs of tests that CTest may run side by side.
std::vector<MiyataPacking> run_packings(const std::string& name, int count, const std::string& folder = "miyata") {
  const std::filesystem::path file = case_file(name);
  const MiyataCase spec = read_miyata_case(file);
  const std::vector<MiyataPacking> packings =
      run_miyata_packings(file, std::filesystem::path(DEM_VALIDATION_TEST_OUTPUT) / folder / name,
                          packing_seeds(spec.packing_seed, count), 2, 1);
  for (const MiyataPacking& p : packings) {
    print_miyata_report(stdout, name + ", " + p.label, p.figures);
    p.verdict.print(stdout, p.label);
  }
  print_packings_table(stdout, spec, packings);
  return packings;
}

// The reduced 2D samples (4 m wide, 9-12 contacts on the loading plate)
// show the curve of Fig. 26: the stress reached, a soft initial state and
// a straight final one, in four of five packings. One contact there is a
// tenth of the plate's, too coarse for Figs. 29 and 30's rates and shares,
// which the full samples show (below, and dem_validate for SS and SR).
Verdict judge_reduced_2d(const MiyataCase& spec, const MiyataFigures& figures) {
  Verdict verdict = judge_miyata_loading(spec, figures);
  verdict.add(judge_miyata_final_state(spec, figures));
  return verdict;
}

void expect_reduced_2d_passes(const std::string& name) {
  const std::vector<MiyataPacking> packings = run_packings(name, 5);
  const Verdict verdict =
      judge_over_packings(read_miyata_case(case_file(name)), packings, most_of(packings.size()), judge_reduced_2d);
  verdict.print(stdout, "over packings");
  EXPECT_TRUE(verdict.passed()) << verdict;
}

TEST(MiyataCompression, CirclesSmoothSurfaceReducedOverPackings) { expect_reduced_2d_passes("cs_reduced"); }

TEST(MiyataCompression, CirclesRoughSurfaceReducedOverPackings) { expect_reduced_2d_passes("cr_reduced"); }

TEST(MiyataCompression, SuperquadricsSmoothSurfaceReducedOverPackings) { expect_reduced_2d_passes("ss_reduced"); }

TEST(MiyataCompression, SuperquadricsRoughSurfaceReducedOverPackings) { expect_reduced_2d_passes("sr_reduced"); }

// The full 10 m circular samples CS and CR (about 300 discs, 23-29 contacts
// on the loading plate), five packings each, judged on everything the seed
// states of them (judge_miyata_over_packings: Figs. 26, 29 and 30), and
// Fig. 26, 3.2(3): "intermittent stress releases seen for the samples
// consisting of circular particles" - sedimented with a higher friction
// "to make disordered samples", each releases stress after the initial
// state in four of five packings.
TEST(MiyataCompression, FullCircularSamplesOverPackings) {
  for (const char* name : {"cs", "cr"}) {
    const std::vector<MiyataPacking> packings = run_packings(name, 5);
    const Verdict verdict = judge_miyata_over_packings(read_miyata_case(case_file(name)), packings);
    verdict.print(stdout, std::string(name) + " over packings");
    EXPECT_TRUE(verdict.passed()) << name << ": " << verdict;
    const int releasing = releasing_packings(packings);
    std::printf("%s: %d of %zu packings release stress after the initial state\n", name, releasing, packings.size());
    EXPECT_GE(releasing, most_of(packings.size())) << name;
  }
}

// Section 3.3: ellipsoids (Hertz, eqs. 47-49) in a periodic cell, loaded to
// 700 kPa with the seed's 3D states (100 and 400 kPa). The reduced sample,
// some 45 ellipsoids with 2-9 on the loading plate, is judged on what its
// size can show, in most of fifteen packings: the loading curve (Fig. 32)
// and the load carried by small forces (Fig. 37). The contact rates of
// Fig. 33 (the transition and final states add 0-2 plate contacts here),
// the final state's straightness and Fig. 35's tail need the full sample:
// dem_validate judges them there (docs/VALIDATION.md, "Miyata 3D").
TEST(MiyataCompression, EllipsoidsReducedOverPackings) {
  const std::vector<MiyataPacking> packings = run_packings("ellipsoids_reduced", 15);
  const auto judge = [](const MiyataCase& spec, const MiyataFigures& figures) {
    Verdict verdict = judge_miyata_loading(spec, figures);
    verdict.add(judge_miyata_force_classes(spec, figures));
    return verdict;
  };
  const Verdict verdict =
      judge_over_packings(read_miyata_case(case_file("ellipsoids_reduced")), packings, most_of(packings.size()), judge);
  verdict.print(stdout, "over packings");
  EXPECT_TRUE(verdict.passed()) << verdict;
}

// Known disagreements: the seed's own statements, asserted, that this
// model does not reproduce (docs/VALIDATION.md gives the evidence). Their
// names start with DISABLED_ so that the discovered tests skip them; CTest
// runs each on its own (tests/validation/CMakeLists.txt) and passes it only
// while it fails on its assertion, so the day the model agrees with the
// seed the entry fails and asks for the docs and this test to change.
constexpr const char* kStillDisagrees = "KNOWN DISAGREEMENT, as documented:";

// Fig. 32: above 400 kPa the curve is "almost linear" and the sample
// "behaves as a continuum" - straight (R^2 > 0.95) and without giving way
// in most of fifteen packings. Here about 11 of 15 are straight.
TEST(MiyataCompression, DISABLED_KnownDisagreementEllipsoidsFinalStateStraight) {
  const std::vector<MiyataPacking> packings = run_packings("ellipsoids_reduced", 15, "known_disagreements");
  const Verdict verdict = judge_over_packings(read_miyata_case(case_file("ellipsoids_reduced")), packings,
                                              most_of(packings.size()), judge_miyata_final_state);
  verdict.print(stdout, "the seed's final state over packings");
  if (!verdict.passed()) std::printf("%s the 3D final state gives way or bends\n", kStillDisagrees);
  EXPECT_TRUE(verdict.passed()) << verdict;
}

// Fig. 26, 3.2(3): "There is no stress release for samples of
// rectangular particles" - judged as everywhere here, in most packings:
// at most one of five releases after the initial state. Here the reduced
// SR releases in three of five (SS in one).
TEST(MiyataCompression, DISABLED_KnownDisagreementRectanglesNeverReleaseStress) {
  bool agrees = true;
  for (const char* name : {"ss_reduced", "sr_reduced"}) {
    const std::vector<MiyataPacking> packings = run_packings(name, 5, "known_disagreements");
    const int releasing = releasing_packings(packings);
    const int allowed = static_cast<int>(packings.size()) - most_of(packings.size());
    std::printf("%s: %d of %zu packings release stress after the initial state (at most %d allowed)\n", name, releasing,
                packings.size(), allowed);
    EXPECT_LE(releasing, allowed) << name;
    agrees = agrees && releasing <= allowed;
  }
  if (!agrees) std::printf("%s the rectangles release stress\n", kStillDisagrees);
}

}  // namespace
}  // namespace dem::validation
