// Miyata, Mustoe, Nakagawa & Sugano (2002), 3.2-3.3: uniaxial compression
// of a particle sample by a loading plate (cases/miyata/). Runs a case's
// stages with its plate loading analyses (output.compression), or reads a
// finished run's tables (dem_run, dem_server, a sweep's task), and sums up
// what the seed reports: the three states of the stress-settlement curve
// (Figs. 26, 32), the contacts on the plates (Figs. 29, 33), the load
// carried by contacts formed in each state (Fig. 30), the force
// distribution's exponential tail and load shares (Figs. 35, 37) and the
// intermittent stress releases. Judged one packing at a time here, over
// packings in miyata_packings.h.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "verdict.h"

namespace dem::validation {

// What a case says of its test: the dimension, whether a stage trims a
// rough surface (eq. 60 with an amplitude), the plate's target stress and
// the states' bounds (3.2(3): 50 and 250 kPa; 3.3(2): 100 and 400 kPa).
struct MiyataCase {
  std::filesystem::path file;
  std::string name;
  int dimension = 2;
  bool rough = false;
  bool circles = false;        // discs, not superquadrics or ellipsoids
  double target_stress = 0.0;  // Pa: the stress the last stage that has one loads the plate to; 0 without
  double transition_stress = 0.0;
  double final_stress = 0.0;
  bool force_distribution = false;
  std::uint64_t packing_seed = 0;  // the first random packing's
};

// Reads a case file; throws io::CaseError for a bad case or one without
// output.compression.
MiyataCase read_miyata_case(const std::filesystem::path& case_file);

// A run made here: where its tables went and what it cost.
struct MiyataRun {
  MiyataCase spec;
  std::filesystem::path directory;
  std::uint64_t packing_seed = 0;
  int particles = 0;  // after trimming
  std::uint64_t cycles = 0;
  double seconds = 0.0;  // wall clock
};

// Runs a case that asks for output.compression, with every random
// packing's seed replaced by `packing_seed` when given, writing the
// analyses' tables to `out` as dem_run does (io/compression_csv.h) and a
// case file of the run there (case.txtpb). `threads` overrides the case's.
MiyataRun run_miyata_compression(const std::filesystem::path& case_file, const std::filesystem::path& out,
                                 std::optional<std::uint64_t> packing_seed = std::nullopt,
                                 std::optional<int> threads = std::nullopt);

// The figures the seed's text states, from a run's tables.
struct MiyataFigures {
  double final_stress = 0.0;  // Pa, at the end
  std::uint64_t cycles = 0;   // the last sample's
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
  // The loading plate's contacts when its stress first reached the
  // transition and the final bound (Fig. 29: fewer under a rough surface),
  // and at the end, with the bottom plate's.
  int loading_contacts_at_transition = 0;
  int loading_contacts_at_final = 0;
  int final_loading_contacts = 0;
  int final_bottom_contacts = 0;
  // Fig. 30 as the seed defines it: the loading plate's load carried by the
  // first 40 %, the next 30 % and the last 30 % of its contacts in the
  // order they formed.
  double initial_load_share = 0.0;
  double transition_load_share = 0.0;
  double final_load_share = 0.0;
  // The same load by the state of the stress-settlement curve each contact
  // formed in.
  double state_initial_load_share = 0.0;
  double state_transition_load_share = 0.0;
  double state_final_load_share = 0.0;
  // Fig. 35, the loading then the bottom plate: the tails above f = 1 (their
  // contacts, decay rate and its standard error; excess cv 1 for an
  // exponential tail, io/force_distribution.h), the largest f, and the
  // shares of the pooled contacts with 1 < f <= 2 and with f > 2.
  bool force_distribution = false;
  std::array<int, 2> tail_contacts{};
  std::array<double, 2> decay_rate{};
  std::array<double, 2> decay_rate_error{};
  std::array<double, 2> excess_cv{};
  std::array<double, 2> largest_f{};
  std::array<double, 2> near_tail_share{};
  std::array<double, 2> far_tail_share{};
  // Fig. 37: the share of the load carried by contacts with f < 0.5, 0.5 <=
  // f < 2 and f >= 2, on each plate.
  std::array<std::array<double, 3>, 2> load_by_force_class{};
  // Stress releases (drops above the case's fraction of a peak) in the
  // transition and in the final state, and the largest of each.
  int transition_drops = 0;
  int final_drops = 0;
  double largest_transition_drop = 0.0;
  double largest_final_drop = 0.0;
};

// Reads the figures from the tables of a run of `spec` in `directory`;
// throws io::CsvTableError when a table is missing or damaged.
MiyataFigures miyata_figures(const MiyataCase& spec, const std::filesystem::path& directory);

void print_miyata_report(std::FILE* out, const std::string& title, const MiyataFigures& figures);

// What the seed's text states of one sample (3.2(3), 3.3(2); docs/VALIDATION.md
// lists the bounds), in parts, so that a reduced sample can be judged on
// what its size can show. judge_miyata is all of them.
inline constexpr double kCollapse = 0.1;
inline constexpr double kMuethDecayRate = 1.39;   // eq. (61) above f = 1 (force_tail.csv)
inline constexpr double kQModelDecayRate = 1.89;  // eq. (62), N = 3
// Figs. 26, 32: the plate reaches its stress; the initial state is over
// four times softer than the final one.
Verdict judge_miyata_loading(const MiyataCase& spec, const MiyataFigures& figures);
// Figs. 29, 33: the loading plate gains contacts fastest in the initial
// state and slowest in the final one.
Verdict judge_miyata_plate_contacts(const MiyataCase& spec, const MiyataFigures& figures);
// Figs. 26, 32: the final state is straight (R² above 0.99 for a smooth 2D
// surface, 0.85 for a rough one, 0.95 in 3D) and, in 3D, gives way nowhere
// by more than kCollapse of its stress ("behave as a continuum").
Verdict judge_miyata_final_state(const MiyataCase& spec, const MiyataFigures& figures);
// Fig. 30 (2D): the contacts formed first carry most of the load.
Verdict judge_miyata_load_shares(const MiyataCase& spec, const MiyataFigures& figures);
// Fig. 35 (3D): each plate's force tail above f = 1 decays at a rate whose
// interval reaches the seed's curves.
Verdict judge_miyata_force_tail(const MiyataCase& spec, const MiyataFigures& figures);
// Fig. 37 (3D): small forces carry the least of the load.
Verdict judge_miyata_force_classes(const MiyataCase& spec, const MiyataFigures& figures);
// All of them but Fig. 30's percentages: what the seed says happens.
Verdict judge_miyata_events(const MiyataCase& spec, const MiyataFigures& figures);
Verdict judge_miyata(const MiyataCase& spec, const MiyataFigures& figures);
// One row of the figures, miyata_summary.csv, in `directory`.
void write_miyata_summary(const std::filesystem::path& directory, const MiyataRun& run, const MiyataFigures& f);

}  // namespace dem::validation
