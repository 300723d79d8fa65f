// Cundall & Strack (1979), verification test (Figs. 10-13, Tables 1-3): the
// photoelastic assembly of De Josselin de Jong & Verruijt (1969) loaded as
// the seed's numerical test was, by moving its four walls: translated
// inward to stage A, then moved on to stage B, each held while the
// assembly comes to rest. Table 1's springs and friction, and the variants
// of Table 2 (k_s = k_n) and Table 3 (tan phi 0.40 and 0.08), moved by the
// same displacements, so that what differs between the tables is the
// material.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dem/measures.h"
#include "verdict.h"

namespace dem::validation {

// One stage's state when it has come to rest: Table 1's columns.
struct VerificationStage {
  std::string name;
  bool settled = false;  // its stop condition held within its cycles
  std::uint64_t cycle = 0;
  std::array<WallMeasure, 4> walls;  // 1 bottom, 2 right, 3 top, 4 left
  // e / (L/2) of each wall's normal force (Table 1, note 1), L the side of
  // the box the wall bounds (the distance between the two walls across it)
  // and e measured from that side's middle: the beams of the photoelastic
  // test were as long as the assembly, where our walls run past it.
  std::array<double, 4> eccentricity{};
  double ratio = 0.0;                   // F_H / F_V
  double vertical_force = 0.0;          // F_V: the mean normal force of walls 1 and 3
  double out_of_balance = 0.0;          // Delta F / F (Table 1, note 2)
  double largest_wall_obliquity = 0.0;  // max over walls of |shear force| / normal force
  int contacts = 0;
  int sliding = 0;
};

struct VerificationRun {
  std::string name;
  std::uint64_t packing_seed = 0;
  double disc_friction = 0.0;  // tan(phi) disc to disc
  double wall_friction = 0.0;  // tan(phi) disc to wall
  VerificationStage a, b;
  // Each stage of the case: its name, the cycles it ran and whether its
  // stop condition ended it.
  struct StageLog {
    std::string name;
    std::uint64_t cycles = 0;
    bool condition_met = false;
  };
  std::vector<StageLog> stages;
  double seconds = 0.0;
};

// Runs a verification case (cases/ball/verification_assembly*.case.txtpb):
// stage A is the state at the end of its stage named "A", stage B at the
// end of "B". With `packing_seed`, its random packing is drawn with that
// seed instead of the case's.
VerificationRun run_verification(const std::filesystem::path& case_file,
                                 std::optional<std::uint64_t> packing_seed = std::nullopt);

// What the seed's Tables 1-3 give for one table: its F_H / F_V in stages
// A and B, its Delta F / F, and the eccentricities that can be read.
struct SeedTable {
  int number = 0;
  double ratio_a = 0.0, ratio_b = 0.0;
  double out_of_balance_a = 0.0, out_of_balance_b = 0.0;
  std::vector<double> eccentricities;  // |e| / (L/2) of the walls the scanned tables keep legible
};
const SeedTable& seed_table(int number);  // 1, 2 or 3

// The three tables on one packing.
struct VerificationTables {
  std::uint64_t packing_seed = 0;
  std::array<VerificationRun, 3> tables;  // Tables 1, 2, 3
};

// Runs verification_assembly, _table2 and _table3 from `cases_dir` on each
// packing seed (the cases' own when the list is empty).
std::vector<VerificationTables> run_verification_tables(const std::filesystem::path& cases_dir,
                                                        const std::vector<std::uint64_t>& packing_seeds);

void print_verification(std::FILE* out, const VerificationRun& run);
void print_verification_tables(std::FILE* out, const std::vector<VerificationTables>& packings);

// verification.csv in `out`: a row per table, packing, stage and wall -
// the stage's F_H / F_V, Delta F / F, contacts and sliding contacts beside
// the wall's forces, eccentricities and contacts (Table 1's columns).
void write_verification_csv(const std::filesystem::path& out, const std::vector<VerificationRun>& runs);

// What one run must show whatever its packing: both stages at rest within
// the seed's Delta F / F (at most 4.2 %), every wall's shear over normal
// force at most the disc-to-wall friction (eq. 19, summed), contacts on
// every wall.
Verdict judge_verification(const VerificationRun& run);

// The tables against the seed's, over the packings: Table 3's F_H / F_V
// above Table 1's in both stages on every packing (lower friction, the
// same displacements), the medians' difference within 0.04 of the seed's
// (0.03 and 0.07), each table's median within 0.12 of its Table's (our
// assemblies stand lower: docs/VALIDATION.md), and eccentricities of the
// seed's size: the median and 90th percentile of |e| / (L/2) within a
// factor of two of the seed's.
Verdict judge_verification_tables(const std::vector<VerificationTables>& packings);

}  // namespace dem::validation
