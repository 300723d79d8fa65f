// Cundall & Strack (1979), verification test (Figs. 10-13, Tables 1-3): the
// photoelastic assembly of De Josselin de Jong & Verruijt (1969) brought by
// four servo walls to F_H/F_V = 0.4 (stage A), then to stage B by raising
// the vertical force 4.348 % and lowering the horizontal one as much, with
// Table 1's stiffnesses and friction and the variants of Table 2 (k_s =
// k_n) and Table 3 (tan phi 0.40 and 0.08).
#pragma once

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "dem/measures.h"
#include "verdict.h"

namespace dem::validation {

// One stage's state when it has come to rest: Table 1's columns.
struct VerificationStage {
  std::string name;
  bool settled = false;  // its stop condition held within its cycles
  std::uint64_t cycle = 0;
  std::array<WallMeasure, 4> walls;     // 1 bottom, 2 right, 3 top, 4 left
  double ratio = 0.0;                   // F_H / F_V
  double out_of_balance = 0.0;          // Delta F / F
  double largest_wall_obliquity = 0.0;  // max over walls of |shear force| / normal force
  int contacts = 0;
  int sliding = 0;
};

struct VerificationRun {
  std::string name;
  double wall_friction = 0.0;  // tan(phi) disc to wall
  VerificationStage a, b;
  double seconds = 0.0;
};

// Runs a verification case (cases/ball/verification_assembly*.case.txtpb):
// its stages "compress" and "settle" make stage A, "stage_B" stage B.
VerificationRun run_verification(const std::filesystem::path& case_file);

void print_verification(std::FILE* out, const VerificationRun& run);

// verification.csv in `out`: a row per stage and wall - the stage's
// F_H / F_V, Delta F / F, contacts and sliding contacts beside the wall's
// forces, eccentricity and contacts (Table 1's columns).
void write_verification_csv(const std::filesystem::path& out, const VerificationRun& run);

// What the seed determines of a force-controlled run: the ratios of stage
// A and of stage B (0.4 x 0.95652 / 1.04348), quasi-equilibrium (the
// seed's Delta F / F at most 4.2 %), and walls whose shear over normal
// force never exceeds the disc-to-wall friction (eq. 19, summed).
Verdict judge_verification(const VerificationRun& run);

}  // namespace dem::validation
