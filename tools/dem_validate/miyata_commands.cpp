#include "miyata_commands.h"

#include <cstdio>
#include <string>

#include "miyata_packings.h"

namespace dem::validation {

namespace {

std::vector<MiyataPacking> packings_of(const MiyataOptions& options, const std::filesystem::path& case_file,
                                       const std::filesystem::path& out, const MiyataCase& spec) {
  if (!options.runs.empty()) return read_miyata_packings(spec, options.runs);
  const std::vector<std::uint64_t> seeds =
      options.seeds.empty() ? packing_seeds(spec.packing_seed, options.packings) : options.seeds;
  return run_miyata_packings(case_file, out, seeds, options.jobs, options.threads);
}

void print_each(const std::vector<MiyataPacking>& packings) {
  for (const MiyataPacking& p : packings) {
    print_miyata_report(stdout, p.label, p.figures);
    p.verdict.print(stdout, p.label);
    std::printf("\n");
  }
}

}  // namespace

Verdict miyata_compression_command(const MiyataOptions& options) {
  const MiyataCase spec = read_miyata_case(options.case_file);
  if (options.runs.empty() && options.seeds.empty() && options.packings == 1) {
    const MiyataRun run = run_miyata_compression(options.case_file, options.out, std::nullopt, options.threads);
    const MiyataFigures figures = miyata_figures(spec, options.out);
    print_miyata_report(stdout, spec.name, figures);
    write_miyata_summary(options.out, run, figures);
    std::printf("wrote the analyses and miyata_summary.csv to %s\n", options.out.c_str());
    return judge_miyata(spec, figures);
  }
  const std::vector<MiyataPacking> packings = packings_of(options, options.case_file, options.out, spec);
  print_each(packings);
  print_packings_table(stdout, spec, packings);
  return judge_miyata_over_packings(spec, packings);
}

Verdict miyata_surfaces_command(const std::filesystem::path& cases, bool reduced, const MiyataOptions& options) {
  std::vector<std::vector<MiyataPacking>> samples;
  Verdict verdict;
  for (const char* name : {"cs", "cr", "ss", "sr"}) {
    const std::filesystem::path file =
        cases / "miyata" / (std::string(name) + (reduced ? "_reduced" : "") + ".case.txtpb");
    const MiyataCase spec = read_miyata_case(file);
    MiyataOptions each = options;
    each.runs.clear();
    samples.push_back(packings_of(each, file, options.out / name, spec));
    print_each(samples.back());
    print_packings_table(stdout, spec, samples.back());
    std::printf("\n");
    Verdict over = judge_miyata_over_packings(spec, samples.back());
    over.print(stdout, spec.name + " over packings");
    std::printf("\n");
    verdict.add(over);
  }
  verdict.add(judge_miyata_surfaces(samples[0], samples[1], samples[2], samples[3], most_of(samples[0].size())));
  return verdict;
}

}  // namespace dem::validation
