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
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "dem/packing.h"
#include "dem/world.h"
#include "ellipsoid.h"
#include "superquadric.h"

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
  def.walls = {WallDef{"bottom", {0.0, 0.0}, {1, 0}, -1.0, width + 1.0, MaterialId{0}, {}}};
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

// warm_up cycles first: 3,000 leave the bed falling; EllipsoidsAtRest's
// settle it into a dense bed like the loading stage's.
template <int Dim>
void measure(benchmark::State& state, BasicWorld<Dim>& world, std::uint64_t warm_up = 3000) {
  world.cycle(warm_up);
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
  // The force pass per touching contact: what a shape's contact costs
  // against a sphere's (issue 33 item 6), neighbours apart included.
  state.counters["ns_forces_per_contact"] =
      1e9 * (after.contact_forces - before.contact_forces) / cycles / world.assembly_measures().contacts;
  state.counters["threads"] = static_cast<double>(world.threads());
}

void Superquadrics(benchmark::State& state) {
  World world(
      superquadric_bed(static_cast<int>(state.range(0)), state.range(1) != 0, static_cast<int>(state.range(2))));
  measure(state, world);
}

void Ellipsoids(benchmark::State& state) {
  World3 world(ellipsoid_bed(static_cast<int>(state.range(0)), state.range(1) != 0, static_cast<int>(state.range(2))));
  measure(state, world);
}

// Beds at rest, as Miyata's loading stages have them, shaped against round
// of the same bounding size (issue 33 item 6 compares ns_forces_per_contact):
// 2D, 1,000 superquadrics or discs settled for 20,000 cycles (about 1.5
// contacts per particle); 3D, 512 ellipsoids or spheres settled for 100,000
// (about 2.3 and 2.0).
void SuperquadricsAtRest(benchmark::State& state) {
  World world(superquadric_bed(1000, state.range(0) != 0, 1));
  measure(state, world, 20000);
}

void EllipsoidsAtRest(benchmark::State& state) {
  World3 world(ellipsoid_bed(512, state.range(0) != 0, 1));
  measure(state, world, 100000);
}

// Contact detection alone, per contact: pairs of touching shapes (Table 1's
// rectangles, section 3.3's rocks) at random orientations, each pair moved
// and turned a little before every search, as a time step would, and the
// search started from where the last one ended, as the force pass does.
struct Jiggle {
  std::mt19937_64 random{20021};
  std::uniform_real_distribution<double> unit{-1.0, 1.0};
  double operator()() { return unit(random); }
};

void SuperquadricContactSearch(benchmark::State& state) {
  const Superquadric shape{0.195, 0.0976, 4.0};
  Jiggle jiggle;
  struct Pair {
    PlacedSuperquadric i, j;
    double alpha_i = 0.0, alpha_j = 0.0;
    bool hinted = false;
  };
  std::vector<Pair> pairs(256);
  for (Pair& p : pairs) {
    p.i = {shape, Vec2::Zero(), 3.2 * jiggle()};
    const double direction = 3.2 * jiggle();
    p.j = {shape, 0.27 * Vec2(std::cos(direction), std::sin(direction)), 3.2 * jiggle()};
  }
  std::int64_t touching = 0;
  for (auto _ : state) {
    for (Pair& p : pairs) {
      p.j.centre += 1e-5 * Vec2(jiggle(), jiggle());
      p.j.angle += 1e-4 * jiggle();
      const SuperquadricContact c = superquadric_contact(p.i, p.j, p.alpha_i, p.alpha_j, p.hinted);
      p.alpha_i = c.alpha_i;
      p.alpha_j = c.alpha_j;
      p.hinted = true;
      touching += c.overlap > 0.0;
      benchmark::DoNotOptimize(c);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.size()));
  state.counters["ns_per_contact"] = benchmark::Counter(static_cast<double>(state.iterations() * pairs.size()),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["touching_fraction"] =
      static_cast<double>(touching) / static_cast<double>(state.iterations() * pairs.size());
}

// The ellipsoid searches' bed: 256 pairs of Miyata's ellipsoids, each
// second body moved at every step by a table made beforehand.
// loading false: settling steps (1e-5 m, 1e-4 rad per step); true: the
// loading stage of Miyata's 3D case (0.02 m/s for 6.86e-6 s: about
// 1.4e-7 m and 5e-7 rad per step).
struct EllipsoidPairs {
  struct Pair {
    PlacedEllipsoid i, j;
    EllipsoidFrame frame_i;
    double mu_i = 0.0, mu_j = 0.0;
  };
  struct Step {
    Vec3 shift;
    Quaternion turn;
  };
  std::vector<Pair> pairs = std::vector<Pair>(256);
  std::vector<Step> steps = std::vector<Step>(4099);  // not a multiple of the pair count
  std::size_t next = 0;

  explicit EllipsoidPairs(bool loading) {
    const Vec3 axes(0.371, 0.260, 0.182);
    const double shift = loading ? 1.4e-7 : 1e-5, angle = loading ? 5e-7 : 1e-4;
    Jiggle jiggle;
    auto turn = [&](double size) {
      return Quaternion(Eigen::AngleAxisd(size, Vec3(jiggle(), jiggle(), jiggle()).normalized()));
    };
    for (Pair& p : pairs) {
      p.i = {axes, Vec3::Zero(), turn(3.2)};
      p.j = {axes, 0.45 * Vec3(jiggle(), jiggle(), jiggle()).normalized(), turn(3.2)};
      p.frame_i = ellipsoid_frame(p.i.axes, p.i.orientation);
    }
    for (Step& s : steps) s = {shift * Vec3(jiggle(), jiggle(), jiggle()), turn(angle * jiggle())};
  }
  // Moves pair p's second body by the next step of the table.
  void move(Pair& p) {
    const Step& step = steps[next];
    next = next + 1 == steps.size() ? 0 : next + 1;
    p.j.centre += step.shift;
    p.j.orientation = (step.turn * p.j.orientation).normalized();
  }
};

// The step's motion comes from a table made beforehand, so the figure is
// the search's (and a vector sum and a quaternion product per pair). The
// turned body's matrices are worked out at every step, as the force pass
// does once per body (so here once per contact, in a bed about once per
// five). range(0) 0: settling steps, 1: loading steps (EllipsoidPairs).
void EllipsoidContactSearch(benchmark::State& state) {
  EllipsoidPairs bed(state.range(0) != 0);
  std::vector<EllipsoidPairs::Pair>& pairs = bed.pairs;
  std::int64_t touching = 0;
  for (auto _ : state) {
    for (EllipsoidPairs::Pair& p : pairs) {
      bed.move(p);
      const EllipsoidContact c = ellipsoid_contact(p.frame_i, p.i.centre, ellipsoid_frame(p.j.axes, p.j.orientation),
                                                   p.j.centre, p.mu_i, p.mu_j);
      p.mu_i = c.multiplier_i;
      p.mu_j = c.multiplier_j;
      touching += c.overlap > 0.0;
      benchmark::DoNotOptimize(c);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.size()));
  state.counters["ns_per_contact"] = benchmark::Counter(static_cast<double>(state.iterations() * pairs.size()),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["touching_fraction"] =
      static_cast<double>(touching) / static_cast<double>(state.iterations() * pairs.size());
}

// EllipsoidContactSearch with the searches made by ellipsoid_contacts,
// several contacts at once across the lanes of a vector: each group of
// pairs is moved and its frames worked out (four at a time,
// ellipsoid_frames), then searched together, as a force pass would take a
// batch of rows whose bounding spheres meet.
void EllipsoidContactBatch(benchmark::State& state) {
  EllipsoidPairs bed(state.range(0) != 0);
  std::vector<EllipsoidPairs::Pair>& pairs = bed.pairs;
  constexpr int kGroup = 16;
  EllipsoidFrame frames_j[kGroup];
  EllipsoidQuery queries[kGroup];
  EllipsoidContact contacts[kGroup];
  std::int64_t touching = 0;
  for (auto _ : state) {
    for (std::size_t first = 0; first < pairs.size(); first += kGroup) {
      for (int k = 0; k < kGroup; ++k) {
        EllipsoidPairs::Pair& p = pairs[first + k];
        bed.move(p);
        queries[k] = {&p.frame_i, &frames_j[k], p.i.centre, p.j.centre, p.mu_i, p.mu_j};
      }
      for (int k = 0; k < kGroup; k += 4) {
        std::array<Vec3, 4> axes_j;
        std::array<Quaternion, 4> orientation_j;
        for (int m = 0; m < 4; ++m) {
          axes_j[m] = pairs[first + k + m].j.axes;
          orientation_j[m] = pairs[first + k + m].j.orientation;
        }
        ellipsoid_frames(axes_j, orientation_j, frames_j + k);
      }
      ellipsoid_contacts(queries, contacts, kGroup);
      for (int k = 0; k < kGroup; ++k) {
        EllipsoidPairs::Pair& p = pairs[first + k];
        p.mu_i = contacts[k].multiplier_i;
        p.mu_j = contacts[k].multiplier_j;
        touching += contacts[k].overlap > 0.0;
      }
      benchmark::DoNotOptimize(contacts);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.size()));
  state.counters["ns_per_contact"] = benchmark::Counter(static_cast<double>(state.iterations() * pairs.size()),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["touching_fraction"] =
      static_cast<double>(touching) / static_cast<double>(state.iterations() * pairs.size());
}

}  // namespace

BENCHMARK(SuperquadricContactSearch)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(EllipsoidContactSearch)->ArgName("loading")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(EllipsoidContactBatch)->ArgName("loading")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
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

BENCHMARK(SuperquadricsAtRest)->ArgName("shaped")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(EllipsoidsAtRest)->ArgName("shaped")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

BENCHMARK_MAIN();
