// Miyata et al. (2002) judged over packings: a plate loading case run with
// several random packings (or several finished runs read from their
// tables), each judged by judge_miyata, and every check asked to hold in
// most of them - what the seed states of its one sample is a statement of
// the typical packing. And the four samples of Table 1 compared (3.2(3)):
// circles release stress, rectangles never; a rough surface has fewer
// contacts on the plate than a smooth one.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "miyata_compression.h"

namespace dem::validation {

struct MiyataPacking {
  std::string label;  // "packing seed 3", or the directory read
  std::filesystem::path directory;
  MiyataFigures figures;
  Verdict verdict;       // judge_miyata's
  double seconds = 0.0;  // 0 when read, not run
  int particles = 0;
};

// The seeds of `count` packings: the case's own, then 1, 2, ... (skipping it).
std::vector<std::uint64_t> packing_seeds(std::uint64_t case_seed, int count);

// Runs the case once per seed, `jobs` runs at a time (each on `threads`
// threads), into out/packing_<seed>/, each with its miyata_summary.csv.
std::vector<MiyataPacking> run_miyata_packings(const std::filesystem::path& case_file, const std::filesystem::path& out,
                                               const std::vector<std::uint64_t>& seeds, int jobs, int threads);

// Finished runs of the case, from their tables.
std::vector<MiyataPacking> read_miyata_packings(const MiyataCase& spec,
                                                const std::vector<std::filesystem::path>& directories);

// The packings with a stress release after the initial state (a drop in
// the transition or the final state).
int releasing_packings(const std::vector<MiyataPacking>& packings);

// The packings needed for "most": four of five, 80 % rounded up.
int most_of(std::size_t packings);

// Every check of `judge` holds in at least `needed` packings; each line
// says in how many it held and which it failed.
using MiyataJudge = Verdict (*)(const MiyataCase&, const MiyataFigures&);
Verdict judge_over_packings(const MiyataCase& spec, const std::vector<MiyataPacking>& packings, int needed,
                            MiyataJudge judge);

// The seed's statements judged over packings: what it says happens (the
// curve's states, the contact rates, a straight final state, Fig. 35's
// tail, Fig. 37's shares) must happen in most packings; Fig. 30's
// percentages, numbers read off one sample, are compared as the typical
// packing's: the medians of the shares over the packings.
Verdict judge_miyata_over_packings(const MiyataCase& spec, const std::vector<MiyataPacking>& packings);

// One line per packing: the figures the seed speaks of.
void print_packings_table(std::FILE* out, const MiyataCase& spec, const std::vector<MiyataPacking>& packings);

// The four samples of Table 1 over their packings (3.2(3), Figs. 26 and 29):
// the circular samples release stress after the initial state in most
// packings, the rectangular ones in few (at most packings - needed); the
// rough surfaces have fewer loading plate contacts than the smooth ones
// at the transition and the final bound (medians over the packings).
Verdict judge_miyata_surfaces(const std::vector<MiyataPacking>& cs, const std::vector<MiyataPacking>& cr,
                              const std::vector<MiyataPacking>& ss, const std::vector<MiyataPacking>& sr, int needed);

}  // namespace dem::validation
