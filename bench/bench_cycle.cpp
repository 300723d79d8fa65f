// Disc-steps per second of the calculation cycle for a dense 2D assembly:
// N discs in a hexagonal packing whose neighbours touch, in a box under
// gravity, so every disc has about six contacts from the first cycle.
// Figures are printed, not asserted; the us_* counters split a cycle's time
// into the phases of step() and rebuild_every counts cycles per rebuild of
// the contact table.
//   bench_cycle --benchmark_filter=Dense
// Health: the cost of a health assessment (dem/health.h) in cycles.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "dem/health.h"
#include "dem/packing.h"
#include "dem/world.h"

namespace {

dem::WorldDef dense_assembly(int discs, int threads) {
  using namespace dem;
  const int columns = static_cast<int>(std::sqrt(discs * 2.0));
  const int rows = discs / columns;
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.5, 0.0}, MaterialDef{"wall", 1.0, 0.3, 0.0}};
  // Stiff enough that the column barely settles under its own weight.
  ContactModelDef model;
  model.linear = {1.0e8, 0.7e8};
  def.contact_models = {model};
  LatticeDef lattice;
  lattice.radius = 0.01;
  lattice.origin = {0.011, 0.011};
  lattice.columns = columns;
  lattice.rows = rows;
  lattice.spacing = 0.02;
  lattice.arrangement = LatticeArrangement::kHexagonal;
  def.particles = generate_lattice(lattice);
  const double width = columns * 0.02 + 0.011, height = rows * 0.02;
  def.walls = {WallDef{"bottom", {0, 0}, {1, 0}, 0, width, MaterialId{1}, {}},
               WallDef{"right", {width, 0}, {0, 1}, 0, 2 * height, MaterialId{1}, {}},
               WallDef{"left", {0, 2 * height}, {0, -1}, 0, 2 * height, MaterialId{1}, {}}};
  def.gravity = {0.0, -9.81};
  def.damping = {1e-4, 10.0};
  def.time_step_fraction = 0.2;
  def.threads = threads;
  return def;
}

void Dense(benchmark::State& state) {
  const int discs = static_cast<int>(state.range(0));
  dem::World world(dense_assembly(discs, static_cast<int>(state.range(1))));
  world.cycle(200);  // let the packing settle into its contacts
  constexpr int kCyclesPerIteration = 10;
  const dem::StepProfile before = world.profile();
  for (auto _ : state) world.cycle(kCyclesPerIteration);
  const dem::StepProfile& after = world.profile();
  const double cycles = static_cast<double>(after.cycles - before.cycles);
  state.counters["rebuild_every"] =
      cycles / static_cast<double>(std::max<std::uint64_t>(after.contact_rebuilds - before.contact_rebuilds, 1));
  state.counters["us_find"] = 1e6 * (after.find_contacts - before.find_contacts) / cycles;
  state.counters["us_forces"] = 1e6 * (after.contact_forces - before.contact_forces) / cycles;
  state.counters["us_motion"] = 1e6 * (after.motion - before.motion) / cycles;
  state.SetItemsProcessed(state.iterations() * kCyclesPerIteration * world.particle_count());
  state.counters["discs"] = world.particle_count();
  state.counters["contacts_per_disc"] =
      static_cast<double>(world.assembly_measures().contacts) / world.particle_count();
  state.counters["threads"] = static_cast<double>(world.threads());
}

// The health check (dem/health.h) of the same assembly, in cycles: what
// dem_run and dem_server spread out to 1/100 of a run (io/pacing.h).
void Health(benchmark::State& state) {
  dem::World world(dense_assembly(static_cast<int>(state.range(0)), 1));
  world.cycle(200);
  constexpr int kCycles = 50;
  const auto start = std::chrono::steady_clock::now();
  world.cycle(kCycles);
  const double cycle_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / kCycles;
  dem::HealthMonitor monitor(world);
  double seconds = 0.0;
  for (auto _ : state) {
    const auto begin = std::chrono::steady_clock::now();
    const dem::StepHealth health = monitor.assess(world);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    if (!health.ok()) state.SkipWithError(health.message.c_str());
  }
  state.counters["cycles_per_assessment"] = seconds / static_cast<double>(state.iterations()) / cycle_seconds;
  state.counters["discs"] = world.particle_count();
}

}  // namespace

BENCHMARK(Health)->ArgNames({"discs"})->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->MinTime(1.0);

BENCHMARK(Dense)
    ->ArgNames({"discs", "threads"})
    ->Args({10000, 1})
    ->Args({10000, 2})
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

BENCHMARK_MAIN();
