#include "miyata_packings.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <thread>

#include "packings.h"

namespace dem::validation {

namespace {

double median_contacts(const std::vector<MiyataPacking>& packings, bool at_final) {
  std::vector<double> values;
  for (const MiyataPacking& p : packings) {
    values.push_back(at_final ? p.figures.loading_contacts_at_final : p.figures.loading_contacts_at_transition);
  }
  return median(values);
}

}  // namespace

std::vector<std::uint64_t> packing_seeds(std::uint64_t case_seed, int count) {
  std::vector<std::uint64_t> seeds;
  if (count > 0) seeds.push_back(case_seed);
  for (std::uint64_t seed = 1; static_cast<int>(seeds.size()) < count; ++seed) {
    if (seed != case_seed) seeds.push_back(seed);
  }
  return seeds;
}

std::vector<MiyataPacking> run_miyata_packings(const std::filesystem::path& case_file, const std::filesystem::path& out,
                                               const std::vector<std::uint64_t>& seeds, int jobs, int threads) {
  std::vector<MiyataPacking> packings(seeds.size());
  std::vector<std::exception_ptr> errors(seeds.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t k = next++; k < seeds.size(); k = next++) {
      try {
        const std::filesystem::path directory = out / ("packing_" + std::to_string(seeds[k]));
        const MiyataRun run = run_miyata_compression(case_file, directory, seeds[k], threads);
        MiyataPacking& p = packings[k];
        p.label = "packing seed " + std::to_string(seeds[k]);
        p.directory = directory;
        p.figures = miyata_figures(run.spec, directory);
        p.verdict = judge_miyata(run.spec, p.figures);
        p.seconds = run.seconds;
        p.particles = run.particles;
        write_miyata_summary(directory, run, p.figures);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> workers;
  for (int j = 1; j < std::max(1, jobs); ++j) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  return packings;
}

std::vector<MiyataPacking> read_miyata_packings(const MiyataCase& spec,
                                                const std::vector<std::filesystem::path>& directories) {
  std::vector<MiyataPacking> packings;
  for (const std::filesystem::path& directory : directories) {
    MiyataPacking p;
    p.label = directory.string();
    p.directory = directory;
    p.figures = miyata_figures(spec, directory);
    p.verdict = judge_miyata(spec, p.figures);
    packings.push_back(std::move(p));
  }
  return packings;
}

int releasing_packings(const std::vector<MiyataPacking>& packings) {
  return static_cast<int>(std::count_if(packings.begin(), packings.end(), [](const MiyataPacking& p) {
    return p.figures.transition_drops + p.figures.final_drops > 0;
  }));
}

int most_of(std::size_t packings) { return static_cast<int>(std::ceil(0.8 * static_cast<double>(packings))); }

Verdict judge_over_packings(const MiyataCase& spec, const std::vector<MiyataPacking>& packings, int needed,
                            MiyataJudge judge) {
  std::vector<std::string> names;
  std::map<std::string, std::vector<std::string>> failed;
  for (const MiyataPacking& p : packings) {
    const Verdict verdict = judge(spec, p.figures);
    for (const Check& check : verdict.checks()) {
      if (std::find(names.begin(), names.end(), check.name) == names.end()) names.push_back(check.name);
      if (!check.passed) failed[check.name].push_back(p.label);
    }
  }
  Verdict verdict;
  for (const std::string& name : names) {
    const int held = static_cast<int>(packings.size() - failed[name].size());
    std::string detail = std::to_string(held) + " of " + std::to_string(packings.size()) + " packings, at least " +
                         std::to_string(needed) + " needed";
    if (!failed[name].empty()) {
      detail += "; fails for";
      for (const std::string& label : failed[name]) detail += " [" + label + "]";
    }
    verdict.expect(name + ", over packings", held >= needed, detail);
  }
  return verdict;
}

namespace {

// Fig. 30 of the typical packing: each share the median over the packings.
Verdict judge_median_load_shares(const MiyataCase& spec, const std::vector<MiyataPacking>& packings) {
  std::vector<double> first, first_two, last;
  for (const MiyataPacking& p : packings) {
    first.push_back(p.figures.initial_load_share);
    first_two.push_back(p.figures.initial_load_share + p.figures.transition_load_share);
    last.push_back(p.figures.final_load_share);
  }
  MiyataFigures typical;
  typical.initial_load_share = median(first);
  typical.transition_load_share = median(first_two) - typical.initial_load_share;
  typical.final_load_share = median(last);
  const Verdict shares = judge_miyata_load_shares(spec, typical);
  Verdict verdict;
  for (const Check& check : shares.checks()) {
    verdict.expect(check.name + ", median over packings", check.passed, check.detail);
  }
  return verdict;
}

}  // namespace

Verdict judge_miyata_over_packings(const MiyataCase& spec, const std::vector<MiyataPacking>& packings) {
  Verdict verdict = judge_over_packings(spec, packings, most_of(packings.size()), judge_miyata_events);
  verdict.add(judge_median_load_shares(spec, packings));
  return verdict;
}

void print_packings_table(std::FILE* out, const MiyataCase& spec, const std::vector<MiyataPacking>& packings) {
  std::fprintf(out, "%s over %zu packings:\n", spec.name.c_str(), packings.size());
  std::fprintf(out, "  %-22s %9s %8s %9s %11s %13s %11s %12s %16s\n", "packing", "kPa", "R2 final", "softness",
               "contacts", "drops t / f", "final drop", "tail rate", "Fig.30 40/30/30");
  for (const MiyataPacking& p : packings) {
    const MiyataFigures& f = p.figures;
    std::fprintf(out, "  %-22s %9.0f %8.4f %9.1f %5d / %-5d %6d / %-6d %10.1f%% %7.2f+-%-4.2f %5.1f/%4.1f/%4.1f%s\n",
                 p.label.c_str(), f.final_stress / 1e3, f.final_r_squared, f.initial_softness, f.final_loading_contacts,
                 f.final_bottom_contacts, f.transition_drops, f.final_drops, 100 * f.largest_final_drop,
                 f.decay_rate[0], f.decay_rate_error[0], 100 * f.initial_load_share, 100 * f.transition_load_share,
                 100 * f.final_load_share, p.verdict.passed() ? "" : "  (a check fails)");
  }
}

Verdict judge_miyata_surfaces(const std::vector<MiyataPacking>& cs, const std::vector<MiyataPacking>& cr,
                              const std::vector<MiyataPacking>& ss, const std::vector<MiyataPacking>& sr, int needed) {
  Verdict verdict;
  const auto of = [](int count, std::size_t all) {
    return std::to_string(count) + " of " + std::to_string(all) + " packings";
  };
  // 3.2(3): "intermittent stress releases seen for the samples consisting
  // of circular particles ... There is no stress release for samples of
  // rectangular particles."
  for (const auto& [name, packings] : {std::pair{"CS", &cs}, std::pair{"CR", &cr}}) {
    const int count = releasing_packings(*packings);
    verdict.expect(std::string(name) + " (circles) releases stress after the initial state", count >= needed,
                   of(count, packings->size()) + ", at least " + std::to_string(needed) + " needed");
  }
  for (const auto& [name, packings] : {std::pair{"SS", &ss}, std::pair{"SR", &sr}}) {
    const int count = releasing_packings(*packings);
    const int allowed = static_cast<int>(packings->size()) - needed;
    verdict.expect(std::string(name) + " (rectangles) releases no stress after the initial state", count <= allowed,
                   of(count, packings->size()) + " release, at most " + std::to_string(allowed) + " allowed");
  }
  // Fig. 29: "the number of contacts for the rough surface cases is smaller
  // than that for the smooth surface cases in the initial and transition
  // states" - at the end of each, medians over the packings.
  for (const bool at_final : {false, true}) {
    const std::string bound = at_final ? "the final bound" : "the transition bound";
    for (const auto& [rough, smooth, name] : {std::tuple{&cr, &cs, "CR < CS"}, std::tuple{&sr, &ss, "SR < SS"}}) {
      verdict.below(std::string("loading plate contacts at ") + bound + ", median, " + name,
                    median_contacts(*rough, at_final), median_contacts(*smooth, at_final));
    }
  }
  return verdict;
}

}  // namespace dem::validation
