// Cundall & Strack (1979) nine-disc test: Figs. 6 and 7 (damping, speed of
// loading) and Figs. 8-9 (distortion, k_s/k_n and friction angle), run from
// the cases in cases/ball/; the checks are dem_validate's
// (tools/dem_validate/nine_disc.cpp: judge_nine_disc).
#include <gtest/gtest.h>

#include "nine_disc.h"

namespace dem::validation {
namespace {

const std::filesystem::path kCases = DEM_CASES_DIR "/ball";

TEST(NineDisc, Figs6To9) {
  const CompressionReport compression = run_compression(kCases);
  const DistortionReport distortion = run_distortion(kCases);
  const Verdict verdict = judge_nine_disc(compression, distortion);
  verdict.print(stdout, "nine-disc");
  EXPECT_TRUE(verdict.passed()) << verdict;
}

}  // namespace
}  // namespace dem::validation
