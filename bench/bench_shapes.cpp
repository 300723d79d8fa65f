// Particle-steps per second for Miyata et al.'s (2002) particle shapes:
// 2D superquadrics (n = 4, Table 1's rectangles) and 3D ellipsoids (section
// 3.3's rocks) settling under gravity onto a plate, against discs and
// spheres of the same bounding size. Each world first runs a few thousand
// warm-up cycles; the beds are still loose then (contacts_per_particle is
// printed: well under one), so these figures measure falling and first
// impacts - mostly pairs in the neighbour list whose bounding circles or
// spheres do not meet - not a dense bed's contacts. Figures are printed,
// not asserted; us_forces is the contact force pass (contact detection of
// shaped particles included) per cycle.
//   bench_shapes --benchmark_filter=Ellipsoids
#include <benchmark/benchmark.h>

#include <algorithm>

#include "dem/packing.h"
#include "dem/world.h"

namespace {

using namespace dem;

// Table 2's linear law with restitution in a periodic strip 20 bounding
// diameters wide, particles dropped from up to about 6x the bed height.
WorldDef superquadric_bed(int count, bool shaped, int threads) {
  WorldDef def;
  def.materials = {MaterialDef{"rock", 1650.0, 0.51, 0.0}};
  ContactModelDef model;
  model.law = ContactLaw::kLinearRestitution;
  model.linear = {1e7, 1e7};
  model.restitution = 0.01;
  def.contact_models = {model};
  const double width = 20 * 0.39, height = 4.0 * count / 20 * 0.39;
  RandomPackingDef packing;
  packing.min = {0.0, 0.0};
  packing.max = {width, height};
  SizeClass size;
  size.count = count;
  size.radius = 0.195;
  if (shaped) size.shape = ShapeDefT<2>{0.195, 0.0976, 4.0, 0.0};
  packing.sizes = {size};
  def.particles = generate_random_packing(packing);
  def.walls = {WallDef{"bottom", {0.0, 0.0}, {1, 0}, -1.0, width + 1.0, 0, {}}};
  def.periodic.axes = {true, false};
  def.periodic.max = {width, 0.0};
  def.gravity = {0.0, -9.81};
  def.damping.local_alpha = 0.3;
  def.fixed_time_step = 1.7078e-4;  // Table 2
  def.threads = threads;
  return def;
}

// Section 3.3's ellipsoids (Hertz, E = 70 GPa) in a periodic box 8 bounding
// diameters square.
WorldDef3 ellipsoid_bed(int count, bool shaped, int threads) {
  WorldDef3 def;
  def.materials = {MaterialDef{"rock", 2650.0, 0.6, 0.0, 70e9, 0.2}};
  ContactModelDef model;
  model.law = ContactLaw::kHertzLinearTangential;
  model.hertz.restitution = 0.3;
  def.contact_models = {model};
  const double side = 8 * 2 * 0.371, height = 6.0 * count / 64 * 0.371;
  RandomPackingDef3 packing;
  packing.max = {side, side, height};
  SizeClass3 size;
  size.count = count;
  size.radius = 0.371;
  if (shaped) size.shape.axes = {0.371, 0.260, 0.182};
  packing.sizes = {size};
  def.particles = generate_random_packing(packing);
  WallDef3 floor;
  floor.name = "floor";
  floor.h1 = floor.k1 = -1.0;
  floor.h2 = floor.k2 = side + 1.0;
  def.walls = {floor};
  def.periodic.axes = {true, true, false};
  def.periodic.max = {side, side, 0.0};
  def.gravity = {0.0, 0.0, -9.81};
  def.damping.local_alpha = 0.3;
  def.fixed_time_step = 6.86e-6 * 4;  // section 3.3's step, coarser: the bench measures cost, not accuracy
  def.threads = threads;
  return def;
}

template <int Dim>
void measure(benchmark::State& state, BasicWorld<Dim>& world) {
  world.cycle(3000);  // into a bed
  constexpr int kCyclesPerIteration = 20;
  const StepProfile before = world.profile();
  for (auto _ : state) world.cycle(kCyclesPerIteration);
  const StepProfile& after = world.profile();
  const double cycles = static_cast<double>(after.cycles - before.cycles);
  state.SetItemsProcessed(state.iterations() * kCyclesPerIteration * world.particle_count());
  state.counters["particles"] = world.particle_count();
  state.counters["contacts_per_particle"] =
      static_cast<double>(world.assembly_measures().contacts) / world.particle_count();
  state.counters["us_find"] = 1e6 * (after.find_contacts - before.find_contacts) / cycles;
  state.counters["us_forces"] = 1e6 * (after.contact_forces - before.contact_forces) / cycles;
  state.counters["us_motion"] = 1e6 * (after.motion - before.motion) / cycles;
  state.counters["threads"] = static_cast<double>(world.threads());
}

void Superquadrics(benchmark::State& state) {
  World world(superquadric_bed(static_cast<int>(state.range(0)), state.range(1) != 0, static_cast<int>(state.range(2))));
  measure(state, world);
}

void Ellipsoids(benchmark::State& state) {
  World3 world(ellipsoid_bed(static_cast<int>(state.range(0)), state.range(1) != 0, static_cast<int>(state.range(2))));
  measure(state, world);
}

}  // namespace

BENCHMARK(Superquadrics)
    ->ArgNames({"particles", "shaped", "threads"})
    ->Args({2000, 0, 1})
    ->Args({2000, 1, 1})
    ->Args({2000, 1, 2})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
BENCHMARK(Ellipsoids)
    ->ArgNames({"particles", "shaped", "threads"})
    ->Args({1500, 0, 1})
    ->Args({1500, 1, 1})
    ->Args({1500, 1, 2})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

BENCHMARK_MAIN();
