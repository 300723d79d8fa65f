// Disc-steps per second of the calculation cycle for a dense 2D assembly:
// N discs in a hexagonal packing whose neighbours overlap by 0.05% of the
// diameter, in a box under gravity, so every disc has about six contacts
// from the first cycle. Figures are printed, not asserted.
//   bench_cycle --benchmark_filter=Dense
#include <benchmark/benchmark.h>

#include <cmath>

#include "dem/packing.h"
#include "dem/world.h"

namespace {

dem::WorldDef dense_assembly(int discs, int threads) {
  using namespace dem;
  const int columns = static_cast<int>(std::sqrt(discs * 2.0));
  const int rows = discs / columns;
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.5, 0.0}, MaterialDef{"wall", 1.0, 0.3, 0.0}};
  def.contact_models = {ContactModelDef{kInvalidId, kInvalidId, {1.0e6, 0.7e6}, {}, {}}};
  LatticeDef lattice;
  lattice.radius = 0.01;
  lattice.origin = {0.011, 0.011};
  lattice.columns = columns;
  lattice.rows = rows;
  lattice.spacing = 0.02;
  lattice.arrangement = LatticeArrangement::kHexagonal;
  def.particles = generate_lattice(lattice);
  for (dem::ParticleDef& p : def.particles) p.radius *= 1.0005;  // neighbours overlap slightly
  const double width = columns * 0.02 + 0.011, height = rows * 0.02;
  def.walls = {WallDef{"bottom", {0, 0}, {1, 0}, 0, width, 1, {}}, WallDef{"right", {width, 0}, {0, 1}, 0, 2 * height, 1, {}},
               WallDef{"left", {0, 2 * height}, {0, -1}, 0, 2 * height, 1, {}}};
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
  for (auto _ : state) world.cycle(kCyclesPerIteration);
  state.SetItemsProcessed(state.iterations() * kCyclesPerIteration * world.particle_count());
  state.counters["discs"] = world.particle_count();
  state.counters["contacts_per_disc"] =
      static_cast<double>(world.assembly_measures().contacts) / world.particle_count();
  state.counters["threads"] = static_cast<double>(world.threads());
}

}  // namespace

BENCHMARK(Dense)
    ->ArgNames({"discs", "threads"})
    ->Args({10000, 1})
    ->Args({10000, 2})
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

BENCHMARK_MAIN();
