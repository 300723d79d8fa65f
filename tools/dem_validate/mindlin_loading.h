// Randall (1989) 5.2: two spheres pressed together to a normal force N, then
// loaded tangentially, unloaded and reloaded at constant N, against the
// Mindlin-Deresiewicz closed form (Randall 3.52-3.55); and a history with
// increasing and decreasing N.
#pragma once

#include <string>
#include <vector>

namespace dem::validation {

struct MindlinPoint {
  std::string branch;   // loading, unloading, reloading
  double displacement;  // m, tangential
  double simulated;     // N
  double theory;        // N, closed form
};

struct MindlinLoadingResult {
  double normal_force = 0.0;       // N reached by the normal approach
  double friction_force = 0.0;     // mu N
  double slip_displacement = 0.0;  // 3 mu N / (16 G* a): full slip on virgin loading
  std::vector<MindlinPoint> points;
  double largest_error = 0.0;  // max |simulated - theory| / (mu N) over the points
};

// Two spheres R = 10 mm, mu = 0.3, E = 210 GPa, nu = 0.3, pressed to N = 88 N.
MindlinLoadingResult mindlin_constant_normal_force(int steps_per_branch);

struct VaryingNormalResult {
  double largest_ratio = 0.0;  // max |T| / (mu N) over the history (must not exceed 1)
  int sliding_steps = 0;
  int lagging_checks = 0;          // steps where N grew faster than T could follow
  double largest_lag_error = 0.0;  // max |dT - 8 G* a ds| / |dT| on those steps (theta = 1, eq. 3.98)
};

// The same contact under a history in which N rises and falls while the
// tangential displacement loads, unloads and reloads.
VaryingNormalResult mindlin_varying_normal_force();

// A contact that forms with its whole overlap in one step, then carries a
// slowly rising N while the tangential displacement loads it (dT >= mu dN
// at every step): by Mindlin and Deresiewicz (Randall 3.4.1, 3.56-3.69) the
// state stays on the constant-N curve of the current N,
//   T = mu N [1 - (1 - delta / delta*)^(3/2)],  delta* = 3 mu N / (16 G* a),
// with N and a as they stand. Two spheres (a pair) or a sphere on a wall of
// the same steel, through the whole engine (3D).
struct FreshContactResult {
  bool wall = false;
  double initial_normal_force = 0.0;  // N when the contact formed
  double final_normal_force = 0.0;    // N at the end
  double final_ratio = 0.0;           // delta / delta* at the end
  double largest_error = 0.0;         // max |T - closed form| / (mu N) over the steps
  bool sliding = false;               // any step at the Coulomb limit (must not happen below delta*)
  std::vector<MindlinPoint> points;   // "fresh_pair" or "fresh_wall": delta, T, closed form
};
FreshContactResult mindlin_fresh_contact_rising_normal_force(bool wall);

}  // namespace dem::validation
