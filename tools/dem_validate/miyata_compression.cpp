#include "miyata_compression.h"

#include <google/protobuf/text_format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <variant>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/compression_csv.h"
#include "dem/io/csv_file.h"
#include "dem/io/csv_table.h"
#include "dem/programme.h"
#include "dem/world.h"
#include "packings.h"

namespace dem::validation {

namespace {

// Whether a case's particles are discs: not superquadrics (2D), not ellipsoids (3D).
template <int Dim>
bool round_particles(const WorldDefT<Dim>& world) {
  if (world.particles.empty()) return false;
  if constexpr (Dim == 2) {
    return !world.particles.front().shape.superquadric();
  } else {
    return !world.particles.front().shape.ellipsoid();
  }
}

template <int Dim>
MiyataCase describe(const io::CaseDefinitionT<Dim>& def) {
  MiyataCase spec;
  spec.name = def.name;
  spec.dimension = Dim;
  spec.circles = Dim == 2 && round_particles(def.world);
  for (const StageDefT<Dim>& stage : def.stages) {
    spec.rough = spec.rough || (stage.trim && stage.trim->amplitude > 0.0);
    if (stage.until.wall_stress_above) spec.target_stress = stage.until.wall_stress_above->value;
  }
  const analysis::CompressionSettings& settings = *def.output.compression;
  spec.transition_stress = settings.transition_stress;
  spec.final_stress = settings.final_stress;
  spec.force_distribution = settings.force_distribution.has_value();
  return spec;
}

io::AnyCaseDefinition convert_with_compression(const io::LoadedCase& loaded) {
  io::AnyCaseDefinition any = io::convert_any_case(loaded.message, loaded.source);
  const bool has_compression = std::visit([](const auto& def) { return def.output.compression.has_value(); }, any);
  if (!has_compression) {
    throw io::CaseError(io::describe_problem(
        loaded.source, "output.compression",
        "is missing; the compression check needs output { compression { loading_plate: ... bottom_plate: ... } }"));
  }
  return any;
}

// The run in the case's dimension: 2D (3.2) or 3D (3.3).
template <int Dim>
void run_definition(io::CaseDefinitionT<Dim> def, const std::filesystem::path& out, std::optional<int> threads,
                    MiyataRun& run) {
  if (threads) def.world.threads = *threads;
  const analysis::CompressionSettings settings = *def.output.compression;
  BasicWorld<Dim> world(def.world);
  analysis::CompressionAnalysisT<Dim> analysis(settings);
  io::CompressionCsvT<Dim> csv(out, world.wall(settings.loading_plate).name, world.wall(settings.bottom_plate).name);
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < def.stages.size(); ++i) {
    const int stage = static_cast<int>(i);
    run_stage(world, def.stages[i], def.output.interval,
              [&](const BasicWorld<Dim>& w) { return io::record_compression(analysis, csv, w, stage), true; });
    io::record_compression(analysis, csv, world, stage);
  }
  csv.write_results(analysis.results(world));
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.particles = world.particle_count();
  run.cycles = world.cycle_count();
}

// A state's row of compression_states.csv.
struct StateRow {
  double settlement_from = 0.0, settlement_to = 0.0;
  double secant_stiffness = 0.0, tangent_stiffness = 0.0, r_squared = 0.0, contact_rate = 0.0;
};

std::array<StateRow, 3> read_states(const std::filesystem::path& directory) {
  const io::CsvTable table = io::CsvTable::read(directory / "compression_states.csv");
  std::array<StateRow, 3> states{};
  for (std::size_t row = 0; row < table.rows(); ++row) {
    const std::string& name = table.text(row, "state");
    const std::size_t k = name == "initial" ? 0 : name == "transition" ? 1 : 2;
    states[k] = {table.number(row, "settlement_from"),  table.number(row, "settlement_to"),
                 table.number(row, "secant_stiffness"), table.number(row, "tangent_stiffness"),
                 table.number(row, "r_squared"),        table.number(row, "contact_rate")};
  }
  return states;
}

// The shares of a plate's load by group (load_by_formation.csv) or state
// (load_by_state.csv), in the order initial, transition, final.
std::array<double, 3> load_shares(const io::CsvTable& table, const std::string& plate, const char* column) {
  std::array<double, 3> shares{};
  for (std::size_t row = 0; row < table.rows(); ++row) {
    if (table.text(row, "plate") != plate) continue;
    const std::string& name = table.text(row, column);
    const std::size_t k = name == "initial" ? 0 : name == "transition" ? 1 : 2;
    shares[k] = table.number(row, "load_share");
  }
  return shares;
}

void read_force_distribution(const std::filesystem::path& directory, const std::string& loading, MiyataFigures& f) {
  const io::CsvTable tails = io::CsvTable::read(directory / "force_tail.csv");
  for (std::size_t row = 0; row < tails.rows(); ++row) {
    const std::size_t p = tails.text(row, "plate") == loading ? 0 : 1;
    f.tail_contacts[p] = static_cast<int>(tails.number(row, "tail_contacts"));
    f.decay_rate[p] = tails.number(row, "decay_rate");
    f.decay_rate_error[p] = tails.number(row, "decay_rate_error");
    f.excess_cv[p] = tails.number(row, "excess_cv");
  }
  // Fig. 37: classes of f sum into f < 0.5, [0.5, 2) and f >= 2.
  const io::CsvTable classes = io::CsvTable::read(directory / "force_distribution.csv");
  for (std::size_t row = 0; row < classes.rows(); ++row) {
    const std::size_t p = classes.text(row, "plate") == loading ? 0 : 1;
    const double low = classes.number(row, "f_low");
    const std::size_t k = low < 0.5 - 1e-9 ? 0 : low < 2.0 - 1e-9 ? 1 : 2;
    f.load_by_force_class[p][k] += classes.number(row, "load_share");
  }
  // The pooled snapshots' f, for the spread of the tail.
  const io::CsvTable contacts = io::CsvTable::read(directory / "plate_contacts.csv");
  std::array<int, 2> pooled{}, near{}, far{};
  for (std::size_t row = 0; row < contacts.rows(); ++row) {
    if (contacts.number(row, "for_distribution") == 0.0) continue;
    const std::size_t p = contacts.text(row, "plate") == loading ? 0 : 1;
    const double value = contacts.number(row, "f");
    ++pooled[p];
    f.largest_f[p] = std::max(f.largest_f[p], value);
    if (value > 1.0 && value <= 2.0) ++near[p];
    if (value > 2.0) ++far[p];
  }
  for (std::size_t p = 0; p < 2; ++p) {
    if (pooled[p] == 0) continue;
    f.near_tail_share[p] = static_cast<double>(near[p]) / pooled[p];
    f.far_tail_share[p] = static_cast<double>(far[p]) / pooled[p];
  }
}

}  // namespace

MiyataCase read_miyata_case(const std::filesystem::path& case_file) {
  const io::LoadedCase loaded = io::load_case_file(case_file);
  MiyataCase spec = std::visit([](const auto& def) { return describe(def); }, convert_with_compression(loaded));
  spec.file = case_file;
  spec.packing_seed = first_packing_seed(loaded.message);
  return spec;
}

MiyataRun run_miyata_compression(const std::filesystem::path& case_file, const std::filesystem::path& out,
                                 std::optional<std::uint64_t> packing_seed, std::optional<int> threads) {
  io::LoadedCase loaded = io::load_case_file(case_file);
  if (packing_seed) reseed_packings(loaded.message, *packing_seed);
  const io::AnyCaseDefinition any = convert_with_compression(loaded);
  MiyataRun run;
  run.spec = std::visit([](const auto& def) { return describe(def); }, any);
  run.spec.file = case_file;
  run.packing_seed = run.spec.packing_seed = first_packing_seed(loaded.message);
  run.directory = out;
  std::filesystem::create_directories(out);
  std::string text;
  google::protobuf::TextFormat::PrintToString(loaded.message, &text);
  std::ofstream(out / "case.txtpb") << "# " << case_file.string() << " as run (packing seed " << run.packing_seed
                                    << ")\n"
                                    << text;
  std::visit([&](const auto& def) { run_definition(def, out, threads, run); }, any);
  return run;
}

MiyataFigures miyata_figures(const MiyataCase& spec, const std::filesystem::path& directory) {
  MiyataFigures f;
  const std::array<StateRow, 3> states = read_states(directory);
  const auto& [initial, transition, final_state] = states;
  // A state begins where the one before it ended.
  f.initial_settlement = initial.settlement_to - initial.settlement_from;
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

  const io::CsvTable samples = io::CsvTable::read(directory / "compression.csv");
  if (samples.rows() > 0) {
    const std::size_t last = samples.rows() - 1;
    f.final_stress = samples.number(last, "stress");
    f.cycles = static_cast<std::uint64_t>(samples.number(last, "cycle"));
    f.final_loading_contacts = static_cast<int>(samples.number(last, "loading_contacts"));
    f.final_bottom_contacts = static_cast<int>(samples.number(last, "bottom_contacts"));
    bool at_transition = false, at_final = false;
    for (std::size_t row = 0; row < samples.rows(); ++row) {
      const double stress = samples.number(row, "stress");
      const int contacts = static_cast<int>(samples.number(row, "loading_contacts"));
      if (!at_transition && stress >= spec.transition_stress) {
        at_transition = true;
        f.loading_contacts_at_transition = contacts;
      }
      if (!at_final && stress >= spec.final_stress) {
        at_final = true;
        f.loading_contacts_at_final = contacts;
      }
    }
  }

  const io::CsvTable formation = io::CsvTable::read(directory / "load_by_formation.csv");
  const std::string loading = formation.rows() > 0 ? formation.text(0, "plate") : std::string();
  const std::array<double, 3> groups = load_shares(formation, loading, "group");
  f.initial_load_share = groups[0];
  f.transition_load_share = groups[1];
  f.final_load_share = groups[2];
  const std::array<double, 3> by_state =
      load_shares(io::CsvTable::read(directory / "load_by_state.csv"), loading, "state");
  f.state_initial_load_share = by_state[0];
  f.state_transition_load_share = by_state[1];
  f.state_final_load_share = by_state[2];

  f.force_distribution = spec.force_distribution;
  if (spec.force_distribution) read_force_distribution(directory, loading, f);

  const io::CsvTable drops = io::CsvTable::read(directory / "stress_drops.csv");
  for (std::size_t row = 0; row < drops.rows(); ++row) {
    const std::string& state = drops.text(row, "state");
    const double drop = drops.number(row, "relative_drop");
    if (state == "transition") {
      ++f.transition_drops;
      f.largest_transition_drop = std::max(f.largest_transition_drop, drop);
    } else if (state == "final") {
      ++f.final_drops;
      f.largest_final_drop = std::max(f.largest_final_drop, drop);
    }
  }
  return f;
}

void print_miyata_report(std::FILE* out, const std::string& title, const MiyataFigures& f) {
  std::fprintf(out, "%s: plate at %.0f kPa after %llu cycles\n", title.c_str(), f.final_stress / 1e3,
               static_cast<unsigned long long>(f.cycles));
  std::fprintf(out,
               "  settlement from the first contact: initial %.4f m, transition %.4f m, final %.4f m "
               "(initial softness %.2f)\n",
               f.initial_settlement, f.transition_settlement, f.final_settlement, f.initial_softness);
  std::fprintf(out, "  stiffness: initial %.3g, transition %.3g (secant), final %.3g Pa/m (tangent, R^2 %.4f)\n",
               f.initial_stiffness, f.transition_stiffness, f.final_stiffness, f.final_r_squared);
  std::fprintf(out,
               "  loading plate contacts per kPa: initial %.4f, transition %.4f, final %.4f; at the states' bounds "
               "%d and %d; at the end %d on the loading plate, %d on the bottom\n",
               f.initial_contact_rate, f.transition_contact_rate, f.final_contact_rate,
               f.loading_contacts_at_transition, f.loading_contacts_at_final, f.final_loading_contacts,
               f.final_bottom_contacts);
  std::fprintf(out,
               "  Fig. 30, load on the loading plate carried by its first 40%% / next 30%% / last 30%% of contacts "
               "by order of formation: %.1f%% / %.1f%% / %.1f%% (by the state each formed in: %.1f%% / %.1f%% / "
               "%.1f%%)\n",
               100 * f.initial_load_share, 100 * f.transition_load_share, 100 * f.final_load_share,
               100 * f.state_initial_load_share, 100 * f.state_transition_load_share, 100 * f.state_final_load_share);
  if (f.force_distribution) {
    for (std::size_t p = 0; p < 2; ++p) {
      std::fprintf(out,
                   "  %s plate: tail above f = 1 decays at %.2f +- %.2f (excess cv %.2f; Mueth's fit 1.39, the "
                   "q-model 1.89); largest f %.2f, %.1f%% of contacts in (1, 2], %.1f%% above 2; load carried by "
                   "f < 0.5 / 0.5-2 / > 2: %.1f%% / %.1f%% / %.1f%% (Fig. 37)\n",
                   p == 0 ? "loading" : "bottom", f.decay_rate[p], f.decay_rate_error[p], f.excess_cv[p],
                   f.largest_f[p], 100 * f.near_tail_share[p], 100 * f.far_tail_share[p],
                   100 * f.load_by_force_class[p][0], 100 * f.load_by_force_class[p][1],
                   100 * f.load_by_force_class[p][2]);
    }
  }
  std::fprintf(out, "  stress drops: transition state %d (largest %.1f%%), final state %d (largest %.1f%%)\n",
               f.transition_drops, 100 * f.largest_transition_drop, f.final_drops, 100 * f.largest_final_drop);
}

void write_miyata_summary(const std::filesystem::path& directory, const MiyataRun& run, const MiyataFigures& f) {
  io::CsvFile file(directory, "miyata_summary.csv",
                   "case,packing_seed,particles,cycles,seconds,final_stress,initial_settlement,transition_settlement,"
                   "final_settlement,initial_softness,initial_stiffness,transition_stiffness,final_stiffness,"
                   "final_r_squared,initial_contact_rate,transition_contact_rate,final_contact_rate,"
                   "loading_contacts_at_transition,loading_contacts_at_final,loading_contacts,bottom_contacts,"
                   "initial_load_share,transition_load_share,final_load_share,state_initial_load_share,"
                   "state_transition_load_share,state_final_load_share,loading_decay_rate,loading_decay_rate_error,"
                   "loading_excess_cv,bottom_decay_rate,bottom_decay_rate_error,bottom_excess_cv,loading_largest_f,"
                   "loading_near_tail_share,loading_far_tail_share,bottom_largest_f,bottom_near_tail_share,"
                   "bottom_far_tail_share,loading_small_force_load,loading_medium_force_load,loading_large_force_load,"
                   "transition_drops,largest_transition_drop,final_drops,largest_final_drop");
  file.write_row(
      run.spec.name, run.packing_seed, run.particles, run.cycles, run.seconds, f.final_stress, f.initial_settlement,
      f.transition_settlement, f.final_settlement, f.initial_softness, f.initial_stiffness, f.transition_stiffness,
      f.final_stiffness, f.final_r_squared, f.initial_contact_rate, f.transition_contact_rate, f.final_contact_rate,
      f.loading_contacts_at_transition, f.loading_contacts_at_final, f.final_loading_contacts, f.final_bottom_contacts,
      f.initial_load_share, f.transition_load_share, f.final_load_share, f.state_initial_load_share,
      f.state_transition_load_share, f.state_final_load_share, f.decay_rate[0], f.decay_rate_error[0], f.excess_cv[0],
      f.decay_rate[1], f.decay_rate_error[1], f.excess_cv[1], f.largest_f[0], f.near_tail_share[0], f.far_tail_share[0],
      f.largest_f[1], f.near_tail_share[1], f.far_tail_share[1], f.load_by_force_class[0][0],
      f.load_by_force_class[0][1], f.load_by_force_class[0][2], f.transition_drops, f.largest_transition_drop,
      f.final_drops, f.largest_final_drop);
}

Verdict judge_miyata_loading(const MiyataCase& spec, const MiyataFigures& f) {
  Verdict verdict;
  if (spec.target_stress > 0.0) verdict.at_least("stress reached, Pa", f.final_stress, spec.target_stress);
  // Figs. 26 and 32: a large settlement at low stress, then stiffer.
  verdict.above("final stiffness / initial stiffness", f.initial_softness, 4.0);
  return verdict;
}

Verdict judge_miyata_plate_contacts(const MiyataCase&, const MiyataFigures& f) {
  Verdict verdict;
  // Figs. 29 and 33: the plate's contacts rise quickly, then more slowly,
  // then more slowly still.
  verdict.above("contacts per kPa, initial state over transition", f.initial_contact_rate, f.transition_contact_rate);
  verdict.above("contacts per kPa, transition state over final", f.transition_contact_rate, f.final_contact_rate);
  verdict.above("contacts on the loading plate at the end", f.final_loading_contacts, 4);
  return verdict;
}

Verdict judge_miyata_final_state(const MiyataCase& spec, const MiyataFigures& f) {
  Verdict verdict;
  const bool solid = spec.dimension == 3;
  // Figs. 26 and 32: almost linear - and in 3D without giving way
  // ("behave as a continuum").
  const double straight = solid ? 0.95 : spec.rough ? 0.85 : 0.99;
  verdict.above("final state's R²", f.final_r_squared, straight);
  if (solid) verdict.below("largest stress release in the final state", f.largest_final_drop, kCollapse);
  return verdict;
}

Verdict judge_miyata_load_shares(const MiyataCase& spec, const MiyataFigures& f) {
  Verdict verdict;
  if (spec.dimension == 3) return verdict;
  // Fig. 30: the contacts formed in the initial and transition states
  // carry over 70 % of the load, the final state's 20 % or less; with
  // rectangles the initial state's over 50 % and the final's under 15 %.
  verdict.above("Fig. 30: load on the first 70 % of the plate's contacts",
                f.initial_load_share + f.transition_load_share, 0.7);
  verdict.at_most("Fig. 30: load on the last 30 %", f.final_load_share, 0.2);
  if (!spec.circles) {
    verdict.above("Fig. 30 (rectangles): load on the first 40 %", f.initial_load_share, 0.5);
    verdict.below("Fig. 30 (rectangles): load on the last 30 %", f.final_load_share, 0.15);
  }
  return verdict;
}

namespace {
const char* plate_name(std::size_t plate) { return plate == 0 ? "loading plate" : "bottom plate"; }
}  // namespace

Verdict judge_miyata_force_tail(const MiyataCase& spec, const MiyataFigures& f) {
  Verdict verdict;
  if (spec.dimension != 3 || !f.force_distribution) return verdict;
  for (std::size_t plate = 0; plate < 2; ++plate) {
    const std::string name = plate_name(plate);
    // Fig. 35: an exponential tail above f = 1 whose rate, within twice its
    // standard error, reaches the seed's curves: Mueth's 1.39 to the
    // q-model's 1.89.
    verdict.at_least(name + ": the tail's decay rate + 2 standard errors, against Mueth's 1.39",
                     f.decay_rate[plate] + 2.0 * f.decay_rate_error[plate], kMuethDecayRate);
    verdict.at_most(name + ": the tail's decay rate - 2 standard errors, against the q-model's 1.89",
                    f.decay_rate[plate] - 2.0 * f.decay_rate_error[plate], kQModelDecayRate);
  }
  return verdict;
}

Verdict judge_miyata_force_classes(const MiyataCase& spec, const MiyataFigures& f) {
  Verdict verdict;
  if (spec.dimension != 3 || !f.force_distribution) return verdict;
  for (std::size_t plate = 0; plate < 2; ++plate) {
    const std::string name = plate_name(plate);
    // Fig. 37: small forces (f < 0.5) carry the smallest part of the load.
    const auto& load = f.load_by_force_class[plate];
    verdict.above(name + ": load on 0.5 <= f < 2 over the load on f < 0.5", load[1], load[0]);
    verdict.above(name + ": load on f >= 2 over the load on f < 0.5", load[2], load[0]);
  }
  return verdict;
}

Verdict judge_miyata_events(const MiyataCase& spec, const MiyataFigures& f) {
  Verdict verdict = judge_miyata_loading(spec, f);
  verdict.add(judge_miyata_plate_contacts(spec, f));
  verdict.add(judge_miyata_final_state(spec, f));
  verdict.add(judge_miyata_force_tail(spec, f));
  verdict.add(judge_miyata_force_classes(spec, f));
  return verdict;
}

Verdict judge_miyata(const MiyataCase& spec, const MiyataFigures& f) {
  Verdict verdict = judge_miyata_events(spec, f);
  verdict.add(judge_miyata_load_shares(spec, f));
  return verdict;
}

}  // namespace dem::validation
