#include "deposition.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dem/analysis/assembly_sample.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/csv_writers.h"
#include "dem/programme.h"
#include "packings.h"

namespace dem::validation {

namespace {

WallId wall_named(const World& world, const std::string& name, const std::filesystem::path& case_file) {
  const WallId id = world.find_wall(name);
  if (id == kInvalidId)
    throw std::runtime_error(case_file.string() + ": the container needs a wall named \"" + name + "\"");
  return id;
}

// Follows the particles that come to rest in an arch near the floor and
// counts those that drop afterwards: the arch they stood in collapsed.
class CollapseWatch {
 public:
  CollapseWatch(const World& world, double left, double right, double floor)
      : left_(left), right_(right), floor_(floor) {
    const auto p = world.particles();
    for (const ParticleId i : world.particle_ids()) largest_ = std::max(largest_, p.radius[i]);
    zone_ = 6.0 * largest_;  // three of the largest diameters
    rest_speed_ = 0.01 * std::sqrt(std::abs(world.gravity().y()) * 2.0 * largest_);
    rest_height_.assign(static_cast<std::size_t>(world.particle_id_count()), kNotResting);
    dropped_.assign(rest_height_.size(), false);
  }

  void observe(const World& world, DepositionZones& zones) {
    std::vector<int> contacts(rest_height_.size(), 0);
    for (const ContactRecord& c : world.contacts()) {
      contacts[c.first.index()] += 1;
      if (c.second_particle.valid()) contacts[c.second_particle.index()] += 1;
    }
    const auto p = world.particles();
    for (const ParticleId i : world.particle_ids()) {
      const std::size_t k = i.index();
      const Vec2 x = p.position[i];
      if (rest_height_[k] == kNotResting) {
        // At rest in an arch: held by two contacts or more, barely moving.
        if (contacts[k] < 2 || p.velocity[i].norm() > rest_speed_) continue;
        rest_height_[k] = x.y();
        resting(zones, zone_of(x)) += 1;
      } else if (!dropped_[k] && x.y() < rest_height_[k] - 0.25 * p.radius[i]) {
        dropped_[k] = true;
        collapses(zones, zone_of({x.x(), rest_height_[k]})) += 1;
      }
    }
  }

 private:
  enum class Zone { kElsewhere, kCorner, kMiddle };
  static constexpr double kNotResting = -1e300;

  static int& resting(DepositionZones& z, Zone zone) {
    return zone == Zone::kCorner ? z.corner_resting : zone == Zone::kMiddle ? z.middle_resting : z.elsewhere_resting;
  }
  static int& collapses(DepositionZones& z, Zone zone) {
    return zone == Zone::kCorner   ? z.corner_collapses
           : zone == Zone::kMiddle ? z.middle_collapses
                                   : z.elsewhere_collapses;
  }

  Zone zone_of(const Vec2& x) const {
    if (x.y() > floor_ + zone_) return Zone::kElsewhere;
    if (x.x() < left_ + zone_ || x.x() > right_ - zone_) return Zone::kCorner;
    if (std::abs(x.x() - 0.5 * (left_ + right_)) < 0.5 * zone_) return Zone::kMiddle;
    return Zone::kElsewhere;
  }

  double left_, right_, floor_;
  double largest_ = 0.0, zone_ = 0.0, rest_speed_ = 0.0;
  std::vector<double> rest_height_;
  std::vector<bool> dropped_;
};

}  // namespace

double DepositionRun::bed_height() const {
  // Spheres in the plane: the area of their central sections.
  const double solidity = 1.0 - bed.porosity;
  return width > 0.0 && solidity > 0.0 ? solid_area / (width * solidity) : 0.0;
}

double DepositionRun::janssen_side_share(double mu) const {
  const double k = bed.stress(1, 1) > 0.0 ? bed.stress(0, 0) / bed.stress(1, 1) : 0.0;
  const double x = width > 0.0 ? 2.0 * mu * k * bed_height() / width : 0.0;
  return x > 0.0 ? 1.0 - (1.0 - std::exp(-x)) / x : 0.0;
}

DepositionRun run_deposition(const std::filesystem::path& case_file, const std::optional<std::filesystem::path>& out,
                             std::optional<std::uint64_t> packing_seed) {
  io::LoadedCase loaded = io::load_case_file(case_file);
  if (packing_seed) reseed_packings(loaded.message, *packing_seed);
  const io::CaseDefinition def = io::convert_case(loaded.message, loaded.source);
  if (def.output.regions.empty()) throw std::runtime_error(case_file.string() + ": the case names no output.region");
  DepositionRun run;
  run.name = def.name;
  run.packing_seed = first_packing_seed(loaded.message);
  World world(def.world);
  run.particles = world.particle_count();
  const WallId floor = wall_named(world, "floor", case_file);
  const WallId left = wall_named(world, "left", case_file);
  const WallId right = wall_named(world, "right", case_file);
  const auto wall_point = [&](WallId id) {
    for (const WallMeasure& m : world.wall_measures())
      if (m.wall == id) return m.point;
    return Vec2(Vec2::Zero());
  };
  run.width = wall_point(right).x() - wall_point(left).x();
  run.friction_limit = 1e300;
  for (const MaterialDef& m : world.materials()) run.friction_limit = std::min(run.friction_limit, m.friction);
  CollapseWatch watch(world, wall_point(left).x(), wall_point(right).x(), wall_point(floor).y());
  const auto start = std::chrono::steady_clock::now();
  for (const StageDef& stage : def.stages) {
    double& ratio = stage.name == "rain" ? run.rain_step_ratio : run.settle_step_ratio;
    const StageResult result = run_stage(world, stage, 1000, [&](const World& w) {
      ratio = std::max(ratio, w.assembly_measures().time_step_ratio);
      watch.observe(w, run.zones);
      return true;
    });
    if (stage.name == "settle") run.at_rest = result.condition_met;
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.cycles = world.cycle_count();
  // Spheres in the plane weigh as spheres (Randall 4.4).
  const auto p = world.particles();
  for (const ParticleId i : world.particle_ids()) {
    run.weight += p.mass[i] * std::abs(world.gravity().y());
    run.solid_area += std::numbers::pi * p.radius[i] * p.radius[i];
  }
  // The particles push the walls down by what the walls carry.
  for (const WallMeasure& m : world.wall_measures()) {
    run.walls_vertical -= m.force.y();
    if (m.wall == floor) run.floor_vertical -= m.force.y();
    if (m.wall == left || m.wall == right) run.side_normal += m.normal_force;
  }
  run.bed = analysis::measure_region(analysis::sample(world), io::region_for<2>(def.output.regions.front()));
  if (out) {
    io::write_particles_csv(*out, world);
    io::write_contacts_csv(*out, world);
  }
  return run;
}

void print_deposition(std::FILE* out, const DepositionRun& run) {
  const analysis::RegionMeasures& b = run.bed;
  std::fprintf(out, "%s (packing seed %llu): %d spheres, %llu cycles in %.1f s, %s\n", run.name.c_str(),
               static_cast<unsigned long long>(run.packing_seed), run.particles,
               static_cast<unsigned long long>(run.cycles), run.seconds, run.at_rest ? "at rest" : "NOT at rest");
  std::fprintf(out, "  weight %.6e N, carried by the container's walls %.6e N (%+.3f %%)\n", run.weight,
               run.walls_vertical, 100.0 * (run.walls_vertical / run.weight - 1.0));
  std::fprintf(out,
               "  arching: the side walls carry %.1f %% of the weight (mobilised wall friction %.3f; bed %.1f mm high "
               "in %.1f mm, K = sigma_h / sigma_v %.3f; Janssen's share %.1f %% at that friction, %.1f %% at %.2f)\n",
               100.0 * run.side_share(), run.wall_friction(), run.bed_height() * 1e3, run.width * 1e3,
               b.stress(1, 1) > 0.0 ? b.stress(0, 0) / b.stress(1, 1) : 0.0,
               100.0 * run.janssen_side_share(run.wall_friction()), 100.0 * run.janssen_side_share(run.friction_limit),
               run.friction_limit);
  std::fprintf(out,
               "  collapses (came to rest in an arch, then dropped by R/4): corners %d of %d resting, middle of the "
               "floor %d of %d, elsewhere %d of %d\n",
               run.zones.corner_collapses, run.zones.corner_resting, run.zones.middle_collapses,
               run.zones.middle_resting, run.zones.elsewhere_collapses, run.zones.elsewhere_resting);
  std::fprintf(out,
               "  time step over the particle-wise critical step (Randall 4.35-4.40): at most %.3f while it rains "
               "(Rayleigh step), %.3f while it settles (0.3 of it)\n",
               run.rain_step_ratio, run.settle_step_ratio);
  std::fprintf(out,
               "  bed (region \"%s\"): porosity %.4f, coordination %.3f (without rattlers %.3f, %d of %d "
               "rattlers), sliding %.1f %%, fabric anisotropy %.4f, vertical over horizontal stress %.3f\n",
               b.region.c_str(), b.porosity, b.coordination, b.mechanical_coordination, b.rattlers, b.particles,
               100.0 * b.sliding_fraction, b.fabric.anisotropy,
               b.stress(0, 0) > 0.0 ? b.stress(1, 1) / b.stress(0, 0) : 0.0);
}

Verdict judge_deposition(const DepositionRun& run) {
  Verdict v;
  v.expect("the bed settles (kinetic energy and out-of-balance below the stage's bounds)", run.at_rest);
  v.near("vertical force on the container over the weight", run.walls_vertical / run.weight, 1.0, 0.01);
  // Below Randall's 0.3 at the settling step (4.40).
  v.below("time step over the particle-wise critical step while settling", run.settle_step_ratio, 0.3);
  v.above("bed porosity (a random packing of two sizes)", run.bed.porosity, 0.1);
  v.below("bed porosity", run.bed.porosity, 0.3);
  return v;
}

Verdict judge_deposition_phenomena(const std::vector<DepositionRun>& runs) {
  Verdict v;
  if (runs.empty()) {
    v.expect("deposition runs", false, "none was run");
    return v;
  }
  std::vector<double> side, janssen;
  double rain_step_ratio = 1e300;
  int corner = 0, corner_resting = 0, middle = 0, middle_resting = 0;
  for (const DepositionRun& r : runs) {
    side.push_back(r.side_share());
    janssen.push_back(r.janssen_side_share(r.friction_limit));
    rain_step_ratio = std::min(rain_step_ratio, r.rain_step_ratio);
    corner += r.zones.corner_collapses;
    corner_resting += r.zones.corner_resting;
    middle += r.zones.middle_collapses;
    middle_resting += r.zones.middle_resting;
  }
  // "During the deposition phase the time step was based on the Rayleigh
  // wave speed. However, once the system approached equilibrium ... the
  // time step was too large": above his 0.3 of the particle-wise critical
  // step (4.40) as the rain lands, on every packing.
  v.above("smallest time step over the particle-wise critical step while it rains (too large)", rain_step_ratio, 0.3);
  // "arch formation": the bed arches onto the side walls, which carry part
  // of its weight by friction - read as at least a quarter of what
  // Janssen's bed gives with all of the walls' friction mobilised.
  v.at_least("side walls' share of the weight over Janssen's at full friction (median packing; arching)",
             median(side) / std::max(median(janssen), 1e-300), 0.25);
  // "collapse at the corners of the container": arches that formed in the
  // bottom corners gave way; more often than in the middle of the floor.
  v.above("particles in the corners whose arch collapsed (all packings)", corner, 0.0);
  const double corner_rate = corner_resting > 0 ? static_cast<double>(corner) / corner_resting : 0.0;
  const double middle_rate = middle_resting > 0 ? static_cast<double>(middle) / middle_resting : 0.0;
  v.above("collapses per resting particle, corners over the middle of the floor", corner_rate, middle_rate);
  return v;
}

Verdict report_deposition(const std::filesystem::path& case_file, const std::optional<std::filesystem::path>& out,
                          const std::vector<std::uint64_t>& seeds) {
  std::vector<std::optional<std::uint64_t>> packings(seeds.begin(), seeds.end());
  if (packings.empty()) packings.emplace_back();
  std::vector<DepositionRun> runs;
  Verdict verdict;
  for (const std::optional<std::uint64_t>& seed : packings) {
    std::optional<std::filesystem::path> directory = out;
    if (out && packings.size() > 1) directory = *out / ("packing_" + std::to_string(*seed));
    runs.push_back(run_deposition(case_file, directory, seed));
    print_deposition(stdout, runs.back());
    verdict.add(judge_deposition(runs.back()));
  }
  verdict.add(judge_deposition_phenomena(runs));
  return verdict;
}

}  // namespace dem::validation
