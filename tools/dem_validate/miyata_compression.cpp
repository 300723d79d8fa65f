#include "miyata_compression.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <variant>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/compression_csv.h"
#include "dem/io/csv_file.h"
#include "dem/programme.h"
#include "dem/world.h"

namespace dem::validation {

namespace {

// The run in the case's dimension: 2D (3.2) or 3D (3.3).
template <int Dim>
MiyataRun run_definition(const io::CaseDefinitionT<Dim>& def, const std::optional<std::filesystem::path>& out) {
  MiyataRun run;
  run.name = def.name;
  run.dimension = Dim;
  run.settings = *def.output.compression;
  for (const StageDefT<Dim>& stage : def.stages) {
    run.rough = run.rough || (stage.trim && stage.trim->amplitude > 0.0);
    if (stage.until.wall_stress_above) run.target_stress = stage.until.wall_stress_above->value;
  }
  BasicWorld<Dim> world(def.world);
  dem::analysis::CompressionAnalysisT<Dim> analysis(run.settings);
  std::optional<io::CompressionCsvT<Dim>> csv;
  if (out) csv.emplace(*out, world.wall(run.settings.loading_plate).name, world.wall(run.settings.bottom_plate).name);
  const auto record = [&](const BasicWorld<Dim>& w, int stage) {
    if (csv) {
      io::record_compression(analysis, *csv, w, stage);
    } else {
      analysis.add(w, stage);
    }
  };

  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < def.stages.size(); ++i) {
    const int stage = static_cast<int>(i);
    run_stage(world, def.stages[i], def.output.interval,
              [&](const BasicWorld<Dim>& w) { return record(w, stage), true; });
    record(world, stage);
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.particles = world.particle_count();
  run.cycles = world.cycle_count();
  run.samples = analysis.samples();
  run.results = analysis.results(world);
  if (csv) csv->write_results(run.results);
  return run;
}

}  // namespace

MiyataRun run_miyata_compression(const std::filesystem::path& case_file,
                                 const std::optional<std::filesystem::path>& out) {
  const io::LoadedCase loaded = io::load_case_file(case_file);
  const io::AnyCaseDefinition any = io::convert_any_case(loaded.message, loaded.source);
  const bool has_compression = std::visit([](const auto& def) { return def.output.compression.has_value(); }, any);
  if (!has_compression) {
    throw io::CaseError(io::describe_problem(
        loaded.source, "output.compression",
        "is missing; the compression check needs output { compression { loading_plate: ... bottom_plate: ... } }"));
  }
  return std::visit([&](const auto& def) { return run_definition(def, out); }, any);
}

MiyataFigures miyata_figures(const MiyataRun& run) {
  MiyataFigures f;
  const auto& [initial, transition, final_state] = run.results.states;
  const auto settlement = [](const dem::analysis::StateFit& s) { return s.settlement_to - s.settlement_from; };
  // A state begins where the one before it ended.
  f.initial_settlement = settlement(initial);
  f.transition_settlement = transition.settlement_to - initial.settlement_to;
  f.final_settlement = final_state.settlement_to - transition.settlement_to;
  f.initial_stiffness = initial.secant_stiffness;
  f.transition_stiffness = transition.secant_stiffness;
  f.final_stiffness = final_state.tangent_stiffness;
  f.final_r_squared = final_state.r_squared;
  if (f.initial_stiffness > 0.0) f.initial_softness = f.final_stiffness / f.initial_stiffness;
  // Contacts per kPa.
  f.initial_contact_rate = 1e3 * initial.contact_rate;
  f.transition_contact_rate = 1e3 * transition.contact_rate;
  f.final_contact_rate = 1e3 * final_state.contact_rate;
  f.final_loading_contacts = run.results.last.loading_contacts;
  f.final_bottom_contacts = run.results.last.bottom_contacts;

  const auto& loads = run.results.load_by_state[0];
  const double load = loads[0].load + loads[1].load + loads[2].load;
  const int contacts = loads[0].contacts + loads[1].contacts + loads[2].contacts;
  if (load > 0.0) {
    f.state_initial_load_share = loads[0].load / load;
    f.state_transition_load_share = loads[1].load / load;
    f.state_final_load_share = loads[2].load / load;
    const auto& groups = run.results.load_by_formation[0];
    f.initial_load_share = groups[0].load / load;
    f.transition_load_share = groups[1].load / load;
    f.final_load_share = groups[2].load / load;
  }
  if (contacts > 0) f.initial_contact_share = static_cast<double>(loads[0].contacts) / contacts;

  if (const auto& d = run.results.force_distribution) {
    f.loading_decay_rate = (*d)[0].tail.decay_rate;
    f.loading_decay_rate_error = (*d)[0].tail.decay_rate_error;
    f.bottom_decay_rate = (*d)[1].tail.decay_rate;
    f.bottom_decay_rate_error = (*d)[1].tail.decay_rate_error;
    f.loading_excess_cv = (*d)[0].tail.excess_cv;
    f.bottom_excess_cv = (*d)[1].tail.excess_cv;
    for (std::size_t p = 0; p < 2; ++p) {
      const std::vector<double>& pooled = (*d)[p].f;
      if (pooled.empty()) continue;
      const auto share = [&](double low, double high) {
        const auto n = std::count_if(pooled.begin(), pooled.end(), [&](double x) { return x > low && x <= high; });
        return static_cast<double>(n) / static_cast<double>(pooled.size());
      };
      f.largest_f[p] = *std::max_element(pooled.begin(), pooled.end());
      f.near_tail_share[p] = share(1.0, 2.0);
      f.far_tail_share[p] = share(2.0, std::numeric_limits<double>::infinity());
    }
  }
  for (const dem::analysis::StressDrop& drop : run.results.drops) {
    if (drop.state == dem::analysis::LoadingState::kInitial) continue;
    f.drops += 1;
    f.largest_drop = std::max(f.largest_drop, drop.relative());
  }
  return f;
}

void print_miyata_report(std::FILE* out, const MiyataRun& run, const MiyataFigures& f) {
  std::fprintf(out, "%s: %d particles, %llu cycles in %.1f s; plate at %.0f kPa\n", run.name.c_str(), run.particles,
               static_cast<unsigned long long>(run.cycles), run.seconds, run.results.last.stress / 1e3);
  std::fprintf(out,
               "  settlement from the first contact: initial %.4f m, transition %.4f m, final %.4f m "
               "(initial softness %.2f)\n",
               f.initial_settlement, f.transition_settlement, f.final_settlement, f.initial_softness);
  std::fprintf(out, "  stiffness: initial %.3g, transition %.3g (secant), final %.3g Pa/m (tangent, R^2 %.4f)\n",
               f.initial_stiffness, f.transition_stiffness, f.final_stiffness, f.final_r_squared);
  std::fprintf(out,
               "  loading plate contacts per kPa: initial %.4f, transition %.4f, final %.4f; at the end %d "
               "on the loading plate, %d on the bottom\n",
               f.initial_contact_rate, f.transition_contact_rate, f.final_contact_rate, f.final_loading_contacts,
               f.final_bottom_contacts);
  std::fprintf(out,
               "  Fig. 30, load on the loading plate carried by its first 40%% / next 30%% / last 30%% of contacts "
               "by order of formation: %.1f%% / %.1f%% / %.1f%%\n"
               "  (by the state each formed in, initial/transition/final: %.1f%% / %.1f%% / %.1f%%; initial "
               "contacts %.1f%% of all)\n",
               100 * f.initial_load_share, 100 * f.transition_load_share, 100 * f.final_load_share,
               100 * f.state_initial_load_share, 100 * f.state_transition_load_share, 100 * f.state_final_load_share,
               100 * f.initial_contact_share);
  if (run.results.force_distribution) {
    std::fprintf(out,
                 "  tail of f above %.2g: decay rate on the loading plate %.2f +- %.2f (excess cv %.2f), bottom "
                 "plate %.2f +- %.2f (cv %.2f); Mueth's fit 1.39 (0.95), the q-model 1.89 (0.90); an exponential "
                 "tail has cv 1\n",
                 run.settings.force_distribution->tail_from, f.loading_decay_rate, f.loading_decay_rate_error,
                 f.loading_excess_cv, f.bottom_decay_rate, f.bottom_decay_rate_error, f.bottom_excess_cv);
    std::fprintf(out,
                 "  f on the loading plate: largest %.2f, %.1f%% of contacts in (1, 2], %.1f%% above 2; bottom "
                 "plate: largest %.2f, %.1f%% and %.1f%%\n",
                 f.largest_f[0], 100 * f.near_tail_share[0], 100 * f.far_tail_share[0], f.largest_f[1],
                 100 * f.near_tail_share[1], 100 * f.far_tail_share[1]);
  }
  std::fprintf(out, "  stress drops above %.0f%% after the initial state: %d (largest %.1f%%)\n",
               100 * run.settings.stress_drop_fraction, f.drops, 100 * f.largest_drop);
}

void write_miyata_summary(const std::filesystem::path& directory, const MiyataRun& run, const MiyataFigures& f) {
  io::CsvFile file(directory, "miyata_summary.csv",
                   "case,particles,cycles,seconds,final_stress,initial_settlement,transition_settlement,"
                   "final_settlement,initial_softness,initial_stiffness,transition_stiffness,final_stiffness,"
                   "final_r_squared,initial_contact_rate,transition_contact_rate,final_contact_rate,"
                   "loading_contacts,bottom_contacts,initial_load_share,transition_load_share,final_load_share,"
                   "state_initial_load_share,state_transition_load_share,state_final_load_share,"
                   "initial_contact_share,loading_decay_rate,loading_decay_rate_error,loading_excess_cv,"
                   "bottom_decay_rate,bottom_decay_rate_error,bottom_excess_cv,loading_largest_f,"
                   "loading_near_tail_share,loading_far_tail_share,bottom_largest_f,bottom_near_tail_share,"
                   "bottom_far_tail_share,drops,largest_drop");
  file.write_row(run.name, run.particles, run.cycles, run.seconds, run.results.last.stress, f.initial_settlement,
                 f.transition_settlement, f.final_settlement, f.initial_softness, f.initial_stiffness,
                 f.transition_stiffness, f.final_stiffness, f.final_r_squared, f.initial_contact_rate,
                 f.transition_contact_rate, f.final_contact_rate, f.final_loading_contacts, f.final_bottom_contacts,
                 f.initial_load_share, f.transition_load_share, f.final_load_share, f.state_initial_load_share,
                 f.state_transition_load_share, f.state_final_load_share, f.initial_contact_share, f.loading_decay_rate,
                 f.loading_decay_rate_error, f.loading_excess_cv, f.bottom_decay_rate, f.bottom_decay_rate_error,
                 f.bottom_excess_cv, f.largest_f[0], f.near_tail_share[0], f.far_tail_share[0], f.largest_f[1],
                 f.near_tail_share[1], f.far_tail_share[1], f.drops, f.largest_drop);
}

Verdict judge_miyata(const MiyataRun& run, const MiyataFigures& f) {
  Verdict verdict;
  if (run.target_stress > 0.0) verdict.at_least("stress reached, Pa", run.results.last.stress, run.target_stress);
  verdict.above("final stiffness / initial stiffness", f.initial_softness, 4.0);
  const double straight = run.dimension == 3 ? 0.95 : run.rough ? 0.85 : 0.99;
  verdict.above(kFinalRSquaredCheck, f.final_r_squared, straight);
  verdict.above("initial contact rate over 3x the final one, contacts per kPa", f.initial_contact_rate,
                3.0 * f.final_contact_rate);
  verdict.above("contacts on the loading plate at the end", f.final_loading_contacts, 4);
  // The tail in 2D only: the 3D cell's plates carry some eight contacts,
  // too few for a tail (its distribution is printed; docs/VALIDATION.md).
  if (run.results.force_distribution && run.dimension == 2) {
    for (std::size_t plate = 0; plate < 2; ++plate) {
      const dem::analysis::PlateForceDistribution& d = (*run.results.force_distribution)[plate];
      const std::string name = plate == 0 ? "loading plate" : "bottom plate";
      verdict.above(name + ": contacts in the tail", d.tail.contacts, 0);
      verdict.at_least(name + ": the tail's decay rate", d.tail.decay_rate, 1.0);
      verdict.above(name + ": share with 1 < f <= 2 over the share with f > 2", f.near_tail_share[plate],
                    f.far_tail_share[plate]);
    }
  }
  return verdict;
}

}  // namespace dem::validation
