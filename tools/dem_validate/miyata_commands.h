// dem_validate's two Miyata subcommands: one case judged on one packing or
// over several (run here, or finished runs read from their tables), and
// the four samples of Table 1 compared over their packings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "verdict.h"

namespace dem::validation {

struct MiyataOptions {
  std::filesystem::path case_file;
  std::filesystem::path out;                // runs here go to out (one packing) or out/packing_<seed>
  int packings = 1;                         // the case's seed, then 1, 2, ...
  std::vector<std::uint64_t> seeds;         // instead of packings
  std::vector<std::filesystem::path> runs;  // finished runs to judge instead of running
  int jobs = 1;                             // runs at a time
  int threads = 1;                          // each run's
};

// miyata-compression: with one packing, judge_miyata's verdict; with more,
// each packing's and the verdict over packings (judge_over_packings).
Verdict miyata_compression_command(const MiyataOptions& options);

// miyata-surfaces: CS, CR, SS and SR (the cases in `cases`, full or, with
// `reduced`, the _reduced ones), each over its packings, and
// judge_miyata_surfaces.
Verdict miyata_surfaces_command(const std::filesystem::path& cases, bool reduced, const MiyataOptions& options);

}  // namespace dem::validation
