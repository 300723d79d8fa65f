// The shared "plate compression" benchmark (../shared/bench/README.md, v1):
// loads the case, runs the 200 warm-up steps, times the 2000 steps after
// them, and prints the README's metrics beside the reference values.
//   bench_plate_compression [--case FILE] [--threads N ...] [--materials MIX]
// MIX gives the same bed other materials with the same physics, to time
// what a material mix costs (docs/PERFORMANCE.md):
//   one        the case as it is: one material
//   walls      the floor and the plate of a second material, a copy of the spheres'
//   particles  every other sphere of a second material, a copy of the first
//   few        as particles, and the pairs with the second material given a
//              contact model that differs only in a linear stiffness the
//              Hertz law does not read: two parameter sets in each table,
//              each row chooses its own (parameter_sets.h)
//   many       every third sphere of the first, second and third material,
//              each pair of them with its own such model: six sets of
//              sphere pairs, each row looks its own up
// Figures are printed, not asserted.
#include <sys/resource.h>
#include <time.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/programme.h"
#include "dem/world.h"

namespace {

struct Metrics {
  double timed_seconds = 0.0;
  double cpu_seconds = 0.0;  // process CPU time over the timed steps (all threads)
  double contacts_per_particle = 0.0;
  double plate_force = 0.0;
  int plate_contacts = 0;
  double kinetic_energy = 0.0;
  dem::StepProfile profile;
};

// CPU time of the process: on a shared machine it drifts less than wall time.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Builds the world from its definition (which it frees then: a user's
// program need not keep it) and runs the warm-up and the timed steps.
Metrics run(dem::WorldDef3 world_def, const std::vector<dem::StageDef3>& stages, int threads, std::uint64_t cycles) {
  world_def.threads = threads;
  dem::World3 world(world_def);
  world_def = dem::WorldDef3{};
  dem::run_stage(world, stages.at(0));  // warm-up, untimed
  const double cpu_start = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  dem::StageDef3 timed = stages.at(1);  // the 2000 timed steps
  if (cycles > 0) timed.cycles = cycles;
  dem::run_stage(world, timed);
  Metrics m;
  m.timed_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m.cpu_seconds = cpu_seconds() - cpu_start;
  m.profile = world.profile();
  // README metrics at step 2200.
  const dem::AssemblyMeasures assembly = world.assembly_measures();
  m.contacts_per_particle = 2.0 * assembly.particle_contacts / world.particle_count();
  const dem::WallId plate = world.find_wall("plate");
  m.plate_force = world.wall_measures()[plate.index()].force.z();  // on the plate, positive upward
  const double plate_z = world.wall(plate).point.z();
  const auto p = world.particles();
  for (const dem::ParticleId i : world.particle_ids()) m.plate_contacts += p.position[i].z() + p.radius[i] > plate_z;
  m.kinetic_energy = assembly.kinetic_energy;
  return m;
}

// Gives the bed the material mix `mix` (see the top of the file).
void apply_material_mix(dem::WorldDef3& def, const std::string& mix) {
  if (mix == "one") return;
  const dem::MaterialId second{static_cast<std::int32_t>(def.materials.size())};
  def.materials.push_back(def.materials.at(0));
  def.materials.back().name += "_copy";
  if (mix == "walls") {
    for (dem::WallDef3& wall : def.walls) wall.material = second;
    return;
  }
  std::vector<dem::MaterialId> kinds{dem::MaterialId{0}, second};
  if (mix == "many") {
    kinds.push_back(dem::MaterialId{static_cast<std::int32_t>(def.materials.size())});
    def.materials.push_back(def.materials.at(0));
    def.materials.back().name += "_second_copy";
  }
  for (std::size_t i = 0; i < def.particles.size(); ++i) def.particles[i].material = kinds[i % kinds.size()];
  if (mix == "particles") return;
  // A model for each pair but the first material's own, each with another
  // linear stiffness, which the linear laws alone read.
  const dem::ContactModelDef model = def.contact_models.at(0);
  double stiffness = model.linear.normal_stiffness;
  for (std::size_t a = 0; a < kinds.size(); ++a) {
    for (std::size_t b = std::max<std::size_t>(a, 1); b < kinds.size(); ++b) {
      dem::ContactModelDef pair = model;
      pair.material_a = kinds[a];
      pair.material_b = kinds[b];
      pair.linear.normal_stiffness = (stiffness *= 2.0);
      def.contact_models.push_back(pair);
    }
  }
}

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The shared plate-compression benchmark"};
  std::filesystem::path case_file = DEM_CASES_DIR "/bench/plate_compression_10k.case.txtpb";
  std::vector<int> threads{1, 2};
  std::uint64_t cycles = 0;
  std::string mix = "one";
  app.add_option("--case", case_file, "a plate-compression case (cases/bench/)")->check(CLI::ExistingFile);
  app.add_option("--threads", threads, "thread counts to time, one run each");
  app.add_option("--cycles", cycles, "timed cycles instead of the benchmark's 2000 (for profiling; not the benchmark)");
  app.add_option("--materials", mix, "material mix: one, walls, particles, few or many (the same physics)")
      ->check(CLI::IsMember({"one", "walls", "particles", "few", "many"}));
  CLI11_PARSE(app, argc, argv);
  try {
    const auto total_start = std::chrono::steady_clock::now();
    const dem::io::LoadedCase loaded = dem::io::load_case_file(case_file);
    dem::io::CaseDefinition3 def = dem::io::convert_case<3>(loaded.message, loaded.source);
    apply_material_mix(def.world, mix);
    const double n = static_cast<double>(def.world.particles.size());
    const bool big = def.world.particles.size() > 50000;
    std::printf("plate compression, %.0f spheres (%s), materials %s\n", n, case_file.c_str(), mix.c_str());
    for (std::size_t k = 0; k < threads.size(); ++k) {
      const int t = threads[k];
      // The last run takes the definition over; the others copy it.
      const Metrics m = k + 1 == threads.size() ? run(std::move(def.world), def.stages, t, cycles)
                                                : run(def.world, def.stages, t, cycles);
      const double timed_cycles = cycles > 0 ? static_cast<double>(cycles) : 2000.0;
      const dem::StepProfile& p = m.profile;
      std::printf(
          "  %d thread%s: timed %.3f s (cpu %.3f s), %.3e particle-steps/s; contacts/particle %.4f (reference %.2f, "
          "%+.2f%%), "
          "plate Fz %.5f N (reference %.4f, %+.1f%%), plate contacts %d, KE %.3e J\n",
          t, t == 1 ? "" : "s", m.timed_seconds, m.cpu_seconds, n * timed_cycles / m.timed_seconds,
          m.contacts_per_particle, big ? 5.02 : 4.78, 100.0 * (m.contacts_per_particle / (big ? 5.02 : 4.78) - 1.0),
          m.plate_force, big ? 0.0147 : 0.0119, 100.0 * (m.plate_force / (big ? 0.0147 : 0.0119) - 1.0),
          m.plate_contacts, m.kinetic_energy);
      const double per_step = 1e6 / static_cast<double>(p.cycles);
      std::printf(
          "    per step (warm-up and timed): find %.1f us, forces %.1f us, motion %.1f us, walls %.1f us; %llu "
          "rebuilds\n",
          per_step * p.find_contacts, per_step * p.contact_forces, per_step * p.motion, per_step * p.walls,
          static_cast<unsigned long long>(p.contact_rebuilds));
      const auto rows = static_cast<double>(std::max<std::uint64_t>(p.pair_rows, 1));
      std::printf(
          "    contact table: %.2f pair rows and %.3f wall rows per particle, %.1f%% of pair rows cross blocks, "
          "%.1f%% near (sorted out %llu times)\n",
          static_cast<double>(p.pair_rows) / n, static_cast<double>(p.wall_rows) / n,
          100.0 * static_cast<double>(p.crossing_rows) / rows, 100.0 * static_cast<double>(p.near_rows) / rows,
          static_cast<unsigned long long>(p.near_sortings));
    }
    std::printf("  total wall time %.1f s, peak RSS %.1f MiB\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - total_start).count(), peak_rss_mib());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
