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

namespace dem::validation {

DepositionRun run_deposition(const std::filesystem::path& case_file, const std::optional<std::filesystem::path>& out) {
  const io::LoadedCase loaded = io::load_case_file(case_file);
  const io::CaseDefinition def = io::convert_case(loaded.message, loaded.source);
  if (def.output.regions.empty()) throw std::runtime_error(case_file.string() + ": the case names no output.region");
  DepositionRun run;
  run.name = def.name;
  World world(def.world);
  run.particles = world.particle_count();
  const auto start = std::chrono::steady_clock::now();
  for (const StageDef& stage : def.stages) {
    double& ratio = stage.name == "rain" ? run.rain_step_ratio : run.settle_step_ratio;
    const StageResult result = run_stage(world, stage, 1000, [&](const World& w) {
      ratio = std::max(ratio, w.assembly_measures().time_step_ratio);
      return true;
    });
    if (stage.name == "settle") run.at_rest = result.condition_met;
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.cycles = world.cycle_count();
  // Spheres in the plane weigh as spheres (Randall 4.4).
  const auto p = world.particles();
  for (const ParticleId i : world.particle_ids()) run.weight += p.mass[i] * std::abs(world.gravity().y());
  // The particles push the walls down by what the walls carry.
  for (const WallMeasure& m : world.wall_measures()) run.walls_vertical -= m.force.y();
  run.bed = analysis::measure_region(analysis::sample(world), io::region_for<2>(def.output.regions.front()));
  if (out) {
    io::write_particles_csv(*out, world);
    io::write_contacts_csv(*out, world);
  }
  return run;
}

void print_deposition(std::FILE* out, const DepositionRun& run) {
  const analysis::RegionMeasures& b = run.bed;
  std::fprintf(out, "%s: %d spheres, %llu cycles in %.1f s, %s\n", run.name.c_str(), run.particles,
               static_cast<unsigned long long>(run.cycles), run.seconds, run.at_rest ? "at rest" : "NOT at rest");
  std::fprintf(out, "  weight %.6e N, carried by the container's walls %.6e N (%+.3f %%)\n", run.weight,
               run.walls_vertical, 100.0 * (run.walls_vertical / run.weight - 1.0));
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

}  // namespace dem::validation
