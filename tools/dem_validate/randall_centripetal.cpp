#include "randall_centripetal.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dem/analysis/assembly_sample.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/csv_file.h"
#include "dem/io/csv_writers.h"
#include "dem/io/regions_csv.h"
#include "dem/programme.h"
#include "packings.h"

namespace dem::validation {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kRings = 12;  // annuli of the radial profiles (Figs. 6.4, 6.5)

void write_snapshot(const std::filesystem::path& directory, const World& world) {
  io::write_contacts_csv(directory, world);
  io::write_particles_csv(directory, world);
}

// The circles at one state of the preparation.
std::vector<CircleState> circle_states(const World& world, const std::vector<analysis::Region>& circles) {
  const analysis::AssemblySample sample = analysis::sample(world);
  std::vector<CircleState> states;
  for (const analysis::Region& circle : circles) {
    const analysis::RegionMeasures m = analysis::measure_region(sample, circle);
    states.push_back({circle.name, circle.radius, static_cast<double>(m.particles) / world.particle_count(), m.porosity,
                      m.mean_stress, 0.0, m.mean_normal_force, m.coordination});
  }
  return states;
}

// The field's hydrostatic stress (Randall 6.4.2: forces "decreased in
// magnitude as they radiated to the boundary"): a disc of radius R whose
// mass per unit area is q, in a field g towards its centre, carries
// p(r) = q g (R - r) / depth if the stress is isotropic, and a circle of
// radius a round the centre averages q g (R - 2a/3) / depth. q is the
// largest circle's (its particles' mass over its area), R the disc all the
// particles would fill at that density.
void add_hydrostatic(CentripetalRun& run, const World& world, const std::vector<analysis::Region>& circles) {
  const analysis::Region& largest = circles.back();
  const ParticleView view = world.particles();
  double inside = 0.0, total = 0.0;
  for (const ParticleId id : world.particle_ids()) {
    total += view.mass[id];
    if (largest.contains(view.position[id])) inside += view.mass[id];
  }
  const double q = inside / (kPi * largest.radius * largest.radius);
  run.disc_radius = std::sqrt(total / (kPi * q));
  for (CircleState& c : run.compacted)
    c.hydrostatic = q * run.acceleration * (run.disc_radius - 2.0 * c.radius / 3.0) / world.depth();
}

// Porosity and the mean normal contact force in annuli round the centre.
void write_profile(io::CsvFile& file, const std::string& state, const World& world, const Vec2& centre, double outer) {
  const analysis::AssemblySample sample = analysis::sample(world);
  for (int k = 0; k < kRings; ++k) {
    analysis::Region ring;
    ring.name = state;
    ring.shape = analysis::RegionShape::kBall;
    ring.centre = centre;
    ring.radius = outer * (k + 1) / kRings;
    const analysis::RegionMeasures disc = analysis::measure_region(sample, ring);
    double inner_solid = 0.0, inner_volume = 0.0, inner_force = 0.0;
    int inner_contacts = 0;
    if (k > 0) {
      ring.radius = outer * k / kRings;
      const analysis::RegionMeasures hole = analysis::measure_region(sample, ring);
      inner_solid = hole.solid;
      inner_volume = hole.volume;
      inner_force = hole.mean_normal_force * hole.contacts;
      inner_contacts = hole.contacts;
    }
    const double porosity = 1.0 - (disc.solid - inner_solid) / (disc.volume - inner_volume);
    const int contacts = disc.contacts - inner_contacts;
    const double force = contacts > 0 ? (disc.mean_normal_force * disc.contacts - inner_force) / contacts : 0.0;
    file.write_row(state, outer * k / kRings, outer * (k + 1) / kRings, porosity, contacts, force);
  }
}

}  // namespace

CentripetalRun run_centripetal(const std::filesystem::path& case_file, const std::optional<std::filesystem::path>& out,
                               std::optional<std::uint64_t> packing_seed) {
  io::LoadedCase loaded = io::load_case_file(case_file);
  if (packing_seed) reseed_packings(loaded.message, *packing_seed);
  const io::CaseDefinition def = io::convert_case(loaded.message, loaded.source);
  std::vector<analysis::Region> circles;
  for (const io::MeasurementRegion& r : def.output.regions) {
    const analysis::Region region = io::region_for<2>(r);
    if (region.shape == analysis::RegionShape::kBall) circles.push_back(region);
  }
  if (circles.size() != 3)
    throw std::runtime_error(case_file.string() + ": Randall's 6.4.2 is measured in three circles (output.region " +
                             "ball, smallest first); the case names " + std::to_string(circles.size()));
  if (!def.world.centripetal_gravity)
    throw std::runtime_error(case_file.string() + ": the case sets no centripetal_gravity (Randall 6.4.2)");
  const Vec2 centre = def.world.centripetal_gravity->centre;

  CentripetalRun run;
  run.name = def.name;
  run.packing_seed = first_packing_seed(loaded.message);
  run.acceleration = def.world.centripetal_gravity->acceleration;
  World world(def.world);
  run.particles = world.particle_count();
  std::optional<io::CsvFile> series, profile;
  if (out) {
    series.emplace(*out, "centripetal.csv",
                   "cycle,box_deviator_strain,out_of_balance,region,strain_xx,strain_xy,strain_yy,"
                   "volumetric_strain,deviator_strain,rotation," +
                       io::region_columns<2>());
    profile.emplace(*out, "profile.csv", "state,radius_low,radius_high,porosity,contacts,mean_normal_force");
    io::CsvFile list(*out, "circles.csv", "region,centre_x,centre_y,radius");
    for (const analysis::Region& circle : circles)
      list.write_row(circle.name, circle.centre.x(), circle.centre.y(), circle.radius);
  }
  const double outer = 1.25 * circles.back().radius;
  const auto start = std::chrono::steady_clock::now();
  bool settled = true;
  for (const StageDef& stage : def.stages) {
    if (stage.name == "shear") {
      const analysis::AssemblySample reference = analysis::sample(world);
      const auto observe = [&](const World& w) {
        const analysis::AssemblySample sample = analysis::sample(w);
        CentripetalSample s;
        s.cycle = w.cycle_count();
        s.deviator_strain = w.box_measure().deviator_strain;
        s.out_of_balance = w.assembly_measures().out_of_balance;
        for (const analysis::Region& circle : circles) {
          CircleSample c{analysis::measure_region(sample, circle),
                         analysis::measure_region_strain(reference, sample, circle)};
          if (series) {
            const analysis::RegionStrain& e = c.strain;
            series->write_row_then(io::region_values<2>(c.measures), s.cycle, s.deviator_strain, s.out_of_balance,
                                   circle.name, e.strain(0, 0), e.strain(0, 1), e.strain(1, 1), e.volumetric,
                                   e.deviator, e.rotation);
          }
          s.circles.push_back(std::move(c));
        }
        run.shear.push_back(std::move(s));
        return true;
      };
      if (stage.box_control) world.set_box_control(stage.box_control);
      observe(world);
      run_stage(world, stage, def.output.interval, observe);
      if (out) write_snapshot(*out / "end_of_shear", world);
      continue;
    }
    const StageResult result = run_stage(world, stage);
    if (has_stop_condition(stage.until)) settled = settled && result.condition_met;
    if (stage.name == "compact") {
      run.compacted = circle_states(world, circles);
      add_hydrostatic(run, world, circles);
      if (out) {
        write_profile(*profile, "compacted", world, centre, outer);
        write_snapshot(*out / "compacted", world);
      }
    } else if (stage.name == "friction") {
      run.settled_state = circle_states(world, circles);
      if (out) write_profile(*profile, "equilibrium", world, centre, outer);
    } else if (stage.name == "load") {
      run.at_100_kpa = circle_states(world, circles);
      run.box_stress = world.box_measure().mean_stress;
      run.out_of_balance = world.assembly_measures().out_of_balance;
      if (out) {
        write_profile(*profile, "100 kPa", world, centre, outer);
        write_snapshot(*out / "at_100_kPa", world);
      }
    }
  }
  run.settled = settled && !run.compacted.empty() && !run.settled_state.empty() && !run.at_100_kpa.empty();
  run.cycles = world.cycle_count();
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

namespace {

// Where a circle's volumetric strain (contraction positive) is largest:
// the deviator strain at which it turns from contracting to expanding.
struct Turn {
  double contraction = 0.0;
  double deviator = 0.0;
  double final_volumetric = 0.0;
};

Turn turn_of(const CentripetalRun& run, std::size_t circle) {
  Turn t{-1e300, 0.0, 0.0};
  for (const CentripetalSample& s : run.shear) {
    const analysis::RegionStrain& e = s.circles[circle].strain;
    if (e.volumetric > t.contraction) t = {e.volumetric, e.deviator, 0.0};
  }
  t.final_volumetric = run.shear.back().circles[circle].strain.volumetric;
  return t;
}

}  // namespace

void print_centripetal(std::FILE* out, const CentripetalRun& run) {
  std::fprintf(out, "%s (Randall 6.4.2): %d spheres, field %.0f m/s^2, %llu cycles in %.1f s%s\n", run.name.c_str(),
               run.particles, run.acceleration, static_cast<unsigned long long>(run.cycles), run.seconds,
               run.settled ? "" : " (a preparation stage did NOT meet its condition)");
  const auto states = [&](const char* title, const std::vector<CircleState>& circles, bool hydrostatic) {
    std::fprintf(out, "  %s:\n", title);
    for (const CircleState& c : circles) {
      std::fprintf(out,
                   "    %-10s r %.2f mm, %.1f %% of the particles, porosity %.4f, coordination %.2f, mean stress %.1f "
                   "kPa",
                   c.name.c_str(), 1e3 * c.radius, 100.0 * c.share, c.porosity, c.coordination, c.mean_stress / 1e3);
      if (hydrostatic) std::fprintf(out, " (hydrostatic %.1f kPa)", c.hydrostatic / 1e3);
      std::fprintf(out, ", mean contact force %.4f N\n", c.mean_normal_force);
    }
  };
  if (!run.compacted.empty()) {
    std::fprintf(out, "  the disc the particles fill at the largest circle's density: R = %.2f mm\n",
                 1e3 * run.disc_radius);
    states("compacted in the field (Fig. 6.4)", run.compacted, true);
  }
  if (!run.settled_state.empty())
    states("field removed, friction 0.3, at equilibrium (Fig. 6.5)", run.settled_state, false);
  if (!run.at_100_kpa.empty()) {
    std::fprintf(out, "  box control's mean %.1f kPa (over its extents), Delta F / F %.4f\n", run.box_stress / 1e3,
                 run.out_of_balance);
    states("at 100 kPa (Fig. 6.6)", run.at_100_kpa, false);
  }
  if (run.shear.size() < 2) return;
  std::fprintf(out, "  constant mean stress shear, %zu samples to box deviator strain %.3f %%:\n", run.shear.size(),
               100.0 * run.shear.back().deviator_strain);
  for (std::size_t c = 0; c < run.shear.front().circles.size(); ++c) {
    const Turn t = turn_of(run, c);
    double peak = 0.0;
    for (const CentripetalSample& s : run.shear) peak = std::max(peak, s.circles[c].measures.sin_phi);
    const CircleSample& first = run.shear.front().circles[c];
    const CircleSample& last = run.shear.back().circles[c];
    std::fprintf(out,
                 "    %-10s deviator strain %.3f %%, peak sin(phi) %.3f (end %.3f); volumetric strain largest "
                 "%.4f %% at deviator %.3f %%, end %.4f %% (contraction positive); mean stress %.1f -> %.1f kPa; fit "
                 "residual %.2g m\n",
                 first.measures.region.c_str(), 100.0 * last.strain.deviator, peak, last.measures.sin_phi,
                 100.0 * t.contraction, 100.0 * t.deviator, 100.0 * t.final_volumetric,
                 first.measures.mean_stress / 1e3, last.measures.mean_stress / 1e3, last.strain.fit_residual);
  }
  double worst = 0.0;
  for (const CentripetalSample& s : run.shear) worst = std::max(worst, s.out_of_balance);
  std::fprintf(out, "    largest Delta F / F during the shear %.4f\n", worst);
}

CentripetalMeasured measure_centripetal(const CentripetalRun& run) {
  CentripetalMeasured m;
  m.label = "packing seed " + std::to_string(run.packing_seed);
  m.settled = run.settled;
  if (run.at_100_kpa.size() == 3) {
    m.share_small = run.at_100_kpa[0].share;
    m.share_middle = run.at_100_kpa[1].share;
    m.share_large = run.at_100_kpa[2].share;
    m.interior_stress = run.at_100_kpa[2].mean_stress;
  }
  m.out_of_balance = run.out_of_balance;
  if (run.compacted.size() == 3) {
    m.compaction_stress_ratio =
        run.compacted[2].mean_stress > 0.0 ? run.compacted[0].mean_stress / run.compacted[2].mean_stress : 0.0;
    m.worst_hydrostatic_ratio = 1.0;
    for (const CircleState& c : run.compacted) {
      const double ratio = c.hydrostatic > 0.0 ? c.mean_stress / c.hydrostatic : 0.0;
      if (std::abs(ratio - 1.0) > std::abs(m.worst_hydrostatic_ratio - 1.0)) m.worst_hydrostatic_ratio = ratio;
    }
  }
  if (run.settled_state.size() == 3) {
    m.porosity_small = run.settled_state[0].porosity;
    m.porosity_large = run.settled_state[2].porosity;
  }
  m.sheared = run.shear.size() >= 3;
  if (!m.sheared) return m;
  const CentripetalSample& last = run.shear.back();
  m.final_deviator = last.circles[2].strain.deviator;
  for (const CentripetalSample& s : run.shear) {
    m.peak_sin_phi = std::max(m.peak_sin_phi, s.circles[2].measures.sin_phi);
    if (s.circles[2].strain.deviator < 0.005) continue;
    double low = 1e300, high = -1e300;
    for (const CircleSample& c : s.circles) {
      low = std::min(low, c.measures.sin_phi);
      high = std::max(high, c.measures.sin_phi);
    }
    m.sin_phi_spread = std::max(m.sin_phi_spread, high - low);
  }
  const Turn small = turn_of(run, 0), large = turn_of(run, 2);
  m.contraction_small = small.contraction;
  m.contraction_large = large.contraction;
  m.turn_small = small.deviator;
  m.turn_large = large.deviator;
  m.expansion_small = small.contraction - small.final_volumetric;
  m.expansion_large = large.contraction - large.final_volumetric;
  const CentripetalSample& quarter = run.shear[run.shear.size() * 3 / 4];
  m.late_expansion_large = quarter.circles[2].strain.volumetric - last.circles[2].strain.volumetric;
  m.end_volumetric_difference = small.final_volumetric - large.final_volumetric;
  const double start_stress = run.shear.front().circles[2].measures.mean_stress;
  m.mean_stress_drift = start_stress > 0.0 ? last.circles[2].measures.mean_stress / start_stress : 0.0;
  return m;
}

namespace {

constexpr double CentripetalMeasured::*kFigures[] = {&CentripetalMeasured::share_small,
                                                     &CentripetalMeasured::share_middle,
                                                     &CentripetalMeasured::share_large,
                                                     &CentripetalMeasured::compaction_stress_ratio,
                                                     &CentripetalMeasured::worst_hydrostatic_ratio,
                                                     &CentripetalMeasured::porosity_small,
                                                     &CentripetalMeasured::porosity_large,
                                                     &CentripetalMeasured::interior_stress,
                                                     &CentripetalMeasured::out_of_balance,
                                                     &CentripetalMeasured::final_deviator,
                                                     &CentripetalMeasured::sin_phi_spread,
                                                     &CentripetalMeasured::peak_sin_phi,
                                                     &CentripetalMeasured::contraction_small,
                                                     &CentripetalMeasured::contraction_large,
                                                     &CentripetalMeasured::turn_small,
                                                     &CentripetalMeasured::turn_large,
                                                     &CentripetalMeasured::expansion_small,
                                                     &CentripetalMeasured::expansion_large,
                                                     &CentripetalMeasured::late_expansion_large,
                                                     &CentripetalMeasured::end_volumetric_difference,
                                                     &CentripetalMeasured::mean_stress_drift};

}  // namespace

CentripetalMeasured median_of(const std::vector<CentripetalMeasured>& packings) {
  if (packings.empty()) throw std::invalid_argument("median_of: no packings");
  CentripetalMeasured m;
  m.label = "median of " + std::to_string(packings.size());
  m.settled = std::ranges::all_of(packings, &CentripetalMeasured::settled);
  m.sheared = std::ranges::all_of(packings, &CentripetalMeasured::sheared);
  set_medians(m, packings, kFigures);
  return m;
}

void print_packings(std::FILE* out, const std::vector<CentripetalMeasured>& packings) {
  std::fprintf(out,
               "  (share: of the particles in the largest circle; s15/s62: mean stress in the field, smallest circle "
               "over largest; hydro: the worst circle's over the hydrostatic; n15, n62: porosity at equilibrium; p: "
               "the largest circle's at 100 kPa; spread: of the circles' sin(phi); ev: largest contraction, turn: "
               "the deviator strain there, late: expansion over the last quarter, end: volumetric strain smallest "
               "less largest, all %%)\n");
  std::fprintf(out, "  %-18s %6s %6s %6s %7s %7s %6s %7s %6s %6s %7s %7s %7s %7s %7s\n", "packing", "share", "s15/62",
               "hydro", "n15", "n62", "p kPa", "sinphi", "spread", "ev62", "turn62", "ev15", "turn15", "late62", "end");
  const auto row = [&](const CentripetalMeasured& m) {
    std::fprintf(out, "  %-18s %6.1f %6.2f %6.2f %7.4f %7.4f %6.1f %7.3f %6.3f %6.3f %7.3f %7.3f %7.3f %7.3f %7.3f\n",
                 m.label.c_str(), 100.0 * m.share_large, m.compaction_stress_ratio, m.worst_hydrostatic_ratio,
                 m.porosity_small, m.porosity_large, m.interior_stress / 1e3, m.peak_sin_phi, m.sin_phi_spread,
                 100.0 * m.contraction_large, 100.0 * m.turn_large, 100.0 * m.contraction_small, 100.0 * m.turn_small,
                 100.0 * m.late_expansion_large, 100.0 * m.end_volumetric_difference);
  };
  for (const CentripetalMeasured& m : packings) row(m);
  if (packings.size() > 1) row(median_of(packings));
}

Verdict judge_centripetal(const CentripetalMeasured& m) {
  Verdict v;
  v.expect("compacted, at equilibrium and at 100 kPa (the stages met their conditions)", m.settled);
  // "Three different circular regions of radii 100, 150 and 200mm ...
  // represent 15, 34 and 62% of the total number of particles".
  v.near("share of the particles in the smallest circle (15 %)", m.share_small, 0.15, 0.03);
  v.near("share of the particles in the middle circle (34 %)", m.share_middle, 0.34, 0.03);
  v.near("share of the particles in the largest circle (62 %)", m.share_large, 0.62, 0.03);
  // "large forces in the centre of the assembly which decreased in
  // magnitude as they radiated to the boundary, fig 6.4".
  v.above("mean stress in the field, smallest circle over largest (Fig. 6.4)", m.compaction_stress_ratio, 1.0);
  // The theory's number: the field's hydrostatic stress, within 20 %.
  v.near("mean stress in the field over the hydrostatic q g (R - 2a/3), the worst circle", m.worst_hydrostatic_ratio,
         1.0, 0.2);
  // "the assembly was not uniformly dense, being denser in the centre" (Fig. 6.5).
  v.below("porosity at equilibrium, smallest circle minus largest (Fig. 6.5)", m.porosity_small - m.porosity_large,
          0.0);
  // "an isotropic stress of 100kPa ... a quasi-equilibrium state ... when
  // the out of balance forces ... were an order of magnitude less than the
  // contact forces" (Fig. 6.6).
  v.near("largest circle's mean stress at 100 kPa / 100 kPa", m.interior_stress / 1e5, 1.0, 0.1);
  v.below("Delta F / F at 100 kPa", m.out_of_balance, 0.1);
  if (!m.sheared) {
    v.expect("shear samples", false, "the shear was not run");
    return v;
  }
  // The mean stress held constant during the shear.
  v.near("largest circle's mean stress at the end of the shear over at its start", m.mean_stress_drift, 1.0, 0.1);
  // "the evolution of sin(phi) illustrated in fig 6.7 shows reasonable
  // close agreement for the three regions": within 0.05 of each other from
  // 0.5 % deviator strain on.
  v.at_most("largest spread of the three circles' sin(phi) from 0.5 % (Fig. 6.7)", m.sin_phi_spread, 0.05);
  // Fig. 6.8: "the volumetric strain, as measured inside the largest radius,
  // indicates that the assembly undergoes initial contraction, which once
  // the system reaches a value of around 0.5% deviator strain then begins
  // to expand. This expansion continued until the end of the test." Read:
  // it contracts, turns between 0.25 and 1 %, and expands over the last
  // quarter of the test.
  v.above("largest circle's initial contraction (Fig. 6.8)", m.contraction_large, 0.0);
  v.at_least("deviator strain where the largest circle turns to expand, from 0.25 % (around 0.5 %)", m.turn_large,
             0.0025);
  v.at_most("deviator strain where the largest circle turns to expand, by 1 % (around 0.5 %)", m.turn_large, 0.01);
  v.above("largest circle's expansion over the last quarter of the test", m.late_expansion_large, 0.0);
  // "In contrast, the smallest region expanded from the start of shear":
  // it turns by 0.1 % deviator strain.
  v.at_most("deviator strain where the smallest circle turns to expand (from the start)", m.turn_small, 0.001);
  // "it is clear from fig 6.8 that the centripetal compaction did not lead
  // to uniform volumetric strain behaviour due to the density variation":
  // the dense centre has expanded more than the largest circle by the end.
  v.below("smallest circle's volumetric strain at the end less the largest's (Fig. 6.8)", m.end_volumetric_difference,
          0.0);
  return v;
}

Verdict report_centripetal(const std::filesystem::path& case_file, const std::optional<std::filesystem::path>& out,
                           const std::vector<std::uint64_t>& seeds) {
  std::vector<std::optional<std::uint64_t>> runs(seeds.begin(), seeds.end());
  if (runs.empty()) runs.emplace_back();
  std::vector<CentripetalMeasured> packings;
  for (const std::optional<std::uint64_t>& seed : runs) {
    std::optional<std::filesystem::path> directory = out;
    if (out && runs.size() > 1) directory = *out / ("packing_" + std::to_string(*seed));
    const CentripetalRun run = run_centripetal(case_file, directory, seed);
    print_centripetal(stdout, run);
    packings.push_back(measure_centripetal(run));
  }
  print_packings(stdout, packings);
  return judge_centripetal(median_of(packings));
}

}  // namespace dem::validation
