// The nine-disc test of Cundall & Strack (1979), Figs. 5-9: runs the cases
// in cases/ball/ and follows the force at contact C cycle by cycle.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "verdict.h"

namespace dem::validation {

// One case's history of the force at contact C (one entry per cycle, from cycle 1).
struct ContactHistory {
  std::string variant;  // the case name
  std::vector<double> normal_force;
  std::vector<double> shear_force;
};

// Runs a case whose output names a probe "C" and records C at every cycle.
ContactHistory follow_contact_c(const std::filesystem::path& case_file);

// Two undamped loadings at different speeds after their loading ends.
struct Fig7Curves {
  ContactHistory fast, slow;
  double fast_mean = 0.0, slow_mean = 0.0;
  double fast_amplitude = 0.0, slow_amplitude = 0.0;
  double fast_period = 0.0, slow_period = 0.0;  // cycles
};

// Undistorted compression (Figs. 6-7).
struct CompressionReport {
  ContactHistory undamped, contact_damping, global_damping, damped, slow;
  double equilibrium_force = 0.0;   // F_eq: the fully damped run's final force at C
  double undamped_mean = 0.0;       // time mean of the undamped force after loading
  double undamped_amplitude = 0.0;  // half the peak-to-peak of the undamped force after loading
  double slow_amplitude = 0.0;      // the same for the slow (0.04) loading
  double damped_spread = 0.0;       // largest |F_final / F_eq - 1| over the three damped runs
  // What the seed determines of the undamped curves without giving the
  // time step: the assembly is linear (every contact stays closed and
  // sticking), so the slow loading (a third of the speed for three times
  // the cycles) is the fast one's response added three times, 40 cycles
  // apart, over three: F_slow(t) = (F_fast(t) + F_fast(t - 40) +
  // F_fast(t - 80)) / 3. The largest difference over F_eq:
  double superposition_error = 0.0;
  // Both oscillate at the assembly's own frequencies ("the frequencies
  // are about the same", Fig. 7): their mean periods, cycles, from the
  // crossings of F_eq after loading.
  double fast_period = 0.0;
  double slow_period = 0.0;
  // Undamped, nothing decays: the amplitude over the first and the second
  // half of the hold, over F_eq.
  double early_amplitude = 0.0;
  double late_amplitude = 0.0;
  // Fig. 7(b): springs nine times softer (k_n = k_s = 1.5e8), the walls in
  // nine times as far at 0.36 and 0.12 per cycle, so that the equilibrium
  // force is Fig. 7(a)'s; undamped. Their means and amplitudes after
  // loading and their mean periods.
  Fig7Curves fig7b;
};

// The undamped amplitude at contact C after the fast loading (walls in by
// 0.12 per cycle for 40 cycles, as the case) with another fixed time step:
// the seed's "about 0.15 F_eq" depends on the step, which it does not give.
struct AmplitudeAtStep {
  double time_step = 0.0;            // the fixed step, as a fraction of the case's critical step
  double amplitude = 0.0;            // over F_eq
  double loading_over_period = 0.0;  // the 40 loading cycles over the oscillation's mean period
};
std::vector<AmplitudeAtStep> undamped_amplitude_by_time_step(const std::filesystem::path& cases_dir,
                                                             const std::vector<double>& fractions);
CompressionReport run_compression(const std::filesystem::path& cases_dir);

// Distortion at constant volume (Figs. 8-9): F_n and F_s at C during the
// distortion stage for phi = 15, 30 deg and ks/kn = 2/3, 1.
struct DistortionReport {
  ContactHistory phi15_ks2_3, phi15_ks1, phi30_ks2_3, phi30_ks1;
  std::size_t distortion_start = 0;  // index of the first distortion cycle in the histories
};
DistortionReport run_distortion(const std::filesystem::path& cases_dir);

// What the seed's Figs. 6-9 show, as checks: the damped runs settle to one
// F_eq, the undamped one oscillates about it (more when loaded faster),
// and under distortion the stiffness ratio matters more at the higher
// friction angle, the stiffer shear spring starting lower, overtaking,
// peaking and then slipping.
Verdict judge_nine_disc(const CompressionReport& compression, const DistortionReport& distortion);

// Writes nine_disc.csv (cycle and the normal force at C for each compression
// variant, Fig. 7(b)'s two among them) and nine_disc_distortion.csv (cycle, F_n and F_s for each distortion variant).
void write_nine_disc_csv(const CompressionReport& compression, const DistortionReport& distortion,
                         const std::filesystem::path& out_dir);

}  // namespace dem::validation
