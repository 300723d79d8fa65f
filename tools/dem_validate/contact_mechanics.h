// The contact-mechanics checks of Randall (1989) ch. 5 and Miyata et al.
// (2002) eq. 17 as runs that write CSV figures and print what they measured.
#pragma once

#include <filesystem>

#include "dem/definitions.h"
#include "impact.h"
#include "verdict.h"

namespace dem::validation {

// The sphere and law of Randall 5.4 / Maw et al.: steel, R = 1 mm, nu = 0.28, mu = 0.12.
Sphere maw_sphere();
ContactModelDef hertz_mindlin_model();
ContactModelDef restitution_model(double restitution);

// Each runs its check, writes its CSV files under out, prints the figures
// and returns the verdict: the bounds the seed and the theory set, which
// tests/validation asserts as well.
Verdict report_hertz_impact(const std::filesystem::path& out);
Verdict report_oblique_impact(const std::filesystem::path& out);
Verdict report_restitution(const std::filesystem::path& out);
Verdict report_mindlin_loading(const std::filesystem::path& out);
Verdict report_box_settle(const std::filesystem::path& case_file, const std::filesystem::path& out);

// The time-step fraction (of the Rayleigh step) the impact runs use: about
// 400 steps per contact at 0.4 m/s.
inline constexpr double kImpactTimeStepFraction = 0.02;
// The dashpot reads the velocity half a step old (Cundall & Strack eq. 26 and
// the remark after it): an error of order zeta omega dt in e, which matters
// at heavy damping (e = 0.1 lost 5.7% at 80 steps per contact). About 1600
// steps per contact keep it well under 1%.
inline constexpr double kRestitutionTimeStepFraction = 0.001;

}  // namespace dem::validation
