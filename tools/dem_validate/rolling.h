// Rolling resistance (Iwashita & Oda 1998; Ai et al. 2011, model C;
// engine/src/rolling_resistance.h) checked against closed forms and the
// published trend: a ball rolling to rest on a plane, and the angle of
// repose of a small heap as the rolling friction grows.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "verdict.h"

namespace dem::validation {

// A disc (2D) or a sphere (3D) set rolling without slip at v0 on a plane
// under gravity: once the rolling spring reaches its cap mu_r R N, the
// torque decelerates it at a = mu_r g / (1 + I / (m R^2)) (5/7 mu_r g for a
// sphere, 2/3 mu_r g for a disc), so it stops after v0 / a and v0^2 / (2 a).
struct RollingToRest {
  int dimension = 3;
  double rolling_friction = 0.0;
  double speed = 0.0;            // v0, m/s
  double stop_time = 0.0;        // s, when its speed first falls to 0.1 % of v0
  double stop_distance = 0.0;    // m, travelled by then
  double theory_time = 0.0;      // v0 / a
  double theory_distance = 0.0;  // v0^2 / (2 a)
  double largest_slip = 0.0;     // max |contact point speed| / v0 while rolling (0: no slip)
};
RollingToRest roll_to_rest(int dimension, double rolling_friction);

// A fixed-base heap: a column of 200 discs (radii 1 and 1.5 mm, tan phi
// 0.5) settles between two walls 20 mm apart on a flat base 50 mm wide;
// the walls are taken out and the column collapses; the discs that roll
// off the base's edges fall away and are taken out. The slopes of the heap
// left (least squares over the surface between a fifth and four fifths of
// its height, both sides). One collapse is one draw: its angle moves by
// several degrees with the packing (and with the last bits of a force sum),
// so the trend is judged on the median over several packings.
struct Repose {
  double rolling_friction = 0.0;
  std::uint64_t packing_seed = 0;
  double angle_deg = 0.0;
  double height = 0.0;  // m, of the heap
  int discs_left = 0;   // on the base
  bool at_rest = false;
};
Repose angle_of_repose(double rolling_friction, std::uint64_t packing_seed);

Verdict report_rolling_to_rest(const std::filesystem::path& out);
Verdict report_angle_of_repose(const std::filesystem::path& out, const std::vector<double>& rolling_frictions,
                               const std::vector<std::uint64_t>& packing_seeds);

}  // namespace dem::validation
