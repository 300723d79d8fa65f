// Randall (1989) 6.2: Platts's hopper discharge (cases/randall/hopper.case.txtpb)
// for a given half-angle and orifice width: the spheres fill the wedge
// under gravity, the orifice's wall is taken out, and they flow out. The
// discharge is counted against time; its steady part gives the rate.
#pragma once

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "verdict.h"

namespace dem::validation {

struct HopperRun {
  std::string name;         // "30 deg, 10 mm"
  double half_angle = 0.0;  // rad, from the vertical
  double orifice = 0.0;     // m
  int particles = 0;
  double fill_seconds = 0.0;    // simulated time to fill, s
  bool filled = false;          // at rest before the orifice opened
  std::vector<double> time;     // s since the orifice opened
  std::vector<int> discharged;  // particles below the orifice's line then
  double rate = 0.0;            // particles/s: least squares over 20-70 % discharged
  double rate_r_squared = 0.0;  // how straight the discharge is there
  double steady_from = 0.0;     // s: when 20 % had left
  // s: where the steady line N = rate (t - lag) meets N = 0 - the time the
  // initial acceleration stage cost (0 had the flow started at its steady
  // rate; half the stage's length for a rate that grows evenly to it).
  double acceleration_lag = 0.0;
  double seconds = 0.0;  // wall clock
};

// Builds the hopper of the case with another half-angle (deg) and orifice
// width (m), runs it; with `out`, writes the particles (velocities) when a
// third has left, as <out>/<run>/particles.csv.
HopperRun run_hopper(const std::filesystem::path& case_file, double half_angle_deg, double orifice,
                     const std::optional<std::filesystem::path>& out = std::nullopt);

void print_hopper(std::FILE* out, const std::vector<HopperRun>& runs);
// hopper.csv (run, time, discharged) and hopper_rates.csv.
void write_hopper_csv(const std::filesystem::path& out, const std::vector<HopperRun>& runs);

// What the thesis determines (6.2): a steady discharge between the
// acceleration and the end; a larger half-angle discharges more slowly and
// reaches its steady rate sooner; a wider orifice discharges faster, its
// acceleration stage no shorter or longer. Given runs at several
// half-angles with one orifice and at several orifices with one
// half-angle.
Verdict judge_hopper(const std::vector<HopperRun>& runs);

}  // namespace dem::validation
