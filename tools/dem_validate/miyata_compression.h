// Miyata, Mustoe, Nakagawa & Sugano (2002), 3.2-3.3: uniaxial compression
// of a particle sample by a loading plate (cases/miyata/). Runs a case's
// stages with its plate loading analyses (output.compression) and sums up
// what the seed reports: the three states of the stress-settlement curve
// (Fig. 26), the contacts on the plates (Fig. 29), the load carried by
// contacts formed in each state (Fig. 30), the force distribution's
// exponential tail (Fig. 35) and the intermittent stress drops.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dem/analysis/compression_analysis.h"
#include "verdict.h"

namespace dem::validation {

struct MiyataRun {
  std::string name;
  int dimension = 2;
  bool rough = false;          // a stage trims the surface with an amplitude (eq. 60)
  double target_stress = 0.0;  // Pa: the stress the last stage that has one loads the plate to; 0 without

  int particles = 0;  // after trimming
  std::uint64_t cycles = 0;
  double seconds = 0.0;  // wall clock
  analysis::CompressionSettings settings;
  std::vector<analysis::CompressionSample> samples;
  analysis::CompressionResults results;
};

// Runs a 2D (3.2) or 3D (3.3) case that asks for output.compression; with
// `out`, writes the analyses' CSV files there as dem_run does
// (io/compression_csv.h).
// Throws io::CaseError for a bad case or one without output.compression.
MiyataRun run_miyata_compression(const std::filesystem::path& case_file,
                                 const std::optional<std::filesystem::path>& out = std::nullopt);

// The figures the seed's text states, from a run.
struct MiyataFigures {
  // Settlement in each state, from the plate's first contact, m.
  double initial_settlement = 0.0;
  double transition_settlement = 0.0;
  double final_settlement = 0.0;
  // Secant stiffness of the initial and transition states (their stress
  // jumps while few contacts carry the plate), the final state's tangent
  // stiffness and how straight it is, Pa/m.
  double initial_stiffness = 0.0;
  double transition_stiffness = 0.0;
  double final_stiffness = 0.0;
  double final_r_squared = 0.0;
  // final_stiffness / initial_stiffness: how much softer the initial state is.
  double initial_softness = 0.0;
  // The loading plate's contacts per kPa in each state (Figs. 29, 33).
  double initial_contact_rate = 0.0;
  double transition_contact_rate = 0.0;
  double final_contact_rate = 0.0;
  int final_loading_contacts = 0;
  int final_bottom_contacts = 0;
  // Fig. 30 as the seed defines it: the loading plate's load carried by the
  // first 40 %, the next 30 % and the last 30 % of its contacts in the
  // order they formed.
  double initial_load_share = 0.0;
  double transition_load_share = 0.0;
  double final_load_share = 0.0;
  // The same load by the state of the stress-settlement curve each contact
  // formed in, and the initial state's share of the contacts.
  double state_initial_load_share = 0.0;
  double state_transition_load_share = 0.0;
  double state_final_load_share = 0.0;
  double initial_contact_share = 0.0;
  // Fig. 35: the tails' decay rates (0 when the case has no force distribution).
  double loading_decay_rate = 0.0;
  double loading_decay_rate_error = 0.0;
  double bottom_decay_rate = 0.0;
  double bottom_decay_rate_error = 0.0;
  // 1 for an exponential tail (io/force_distribution.h).
  double loading_excess_cv = 0.0;
  double bottom_excess_cv = 0.0;
  // The spread of f (Fig. 34: "a wide range of amplitude"): the largest f,
  // and the shares of the pooled contacts with 1 < f <= 2 and with f > 2,
  // on the loading then the bottom plate. A tail falling with f holds more
  // of them near 1 than beyond 2.
  std::array<double, 2> largest_f{};
  std::array<double, 2> near_tail_share{};
  std::array<double, 2> far_tail_share{};
  // Intermittent stress releases in the transition and final states.
  int drops = 0;
  double largest_drop = 0.0;  // relative
};

MiyataFigures miyata_figures(const MiyataRun& run);

void print_miyata_report(std::FILE* out, const MiyataRun& run, const MiyataFigures& figures);

// What the seed's text states (3.2(3), 3.3; docs/VALIDATION.md lists the
// bounds): the plate reaches its stress; the initial state is over four
// times softer than the final one, which is straight (R² above 0.99 for a
// smooth 2D surface, 0.85 for a rough one, 0.95 in 3D); the loading plate
// gains contacts three times faster in the initial state than in the final
// one, and ends with more than four; with a force distribution, in 2D,
// each plate's tail above f = 1 falls with f (decay rate at least 1, more
// contacts in (1, 2] than above 2).
Verdict judge_miyata(const MiyataRun& run, const MiyataFigures& figures);
// The name of judge_miyata's check on the final state's R², for a test
// that judges it over several packings (tests/validation: the 3D case).
inline constexpr const char* kFinalRSquaredCheck = "final state's R²";
// One row of the figures, miyata_summary.csv, in `directory`.
void write_miyata_summary(const std::filesystem::path& directory, const MiyataRun& run, const MiyataFigures& f);

}  // namespace dem::validation
