#include "hopper.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/csv_file.h"
#include "dem/io/csv_writers.h"
#include "dem/packing.h"
#include "dem/programme.h"

namespace dem::validation {

namespace {

constexpr double kWedgeHeight = 0.05;        // m above the orifice
constexpr double kGenerationBottom = 0.008;  // m: the spheres are generated above this
constexpr double kGenerationTop = 0.054;     // m

WallId wall_named(const WorldDef& def, const std::string& name) {
  for (std::size_t w = 0; w < def.walls.size(); ++w) {
    if (def.walls[w].name == name) return WallId::from_index(w);
  }
  throw std::runtime_error("hopper case: no wall named \"" + name + "\"");
}

struct Line {
  double slope = 0.0, r_squared = 0.0;
  double x_intercept = 0.0;  // where the line meets y = 0
};

// The least-squares line of y on x.
Line fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<double>(x.size());
  if (x.size() < 3) return {};
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  const double slope = sxx > 0 ? sxy / sxx : 0.0;
  return {slope, syy > 0 ? slope * sxy / syy : 1.0, slope != 0.0 ? mx - my / slope : 0.0};
}

}  // namespace

HopperRun run_hopper(const std::filesystem::path& case_file, double half_angle_deg, double orifice,
                     const std::optional<std::filesystem::path>& out) {
  const io::LoadedCase loaded = io::load_case_file(case_file);
  io::CaseDefinition def = io::convert_case(loaded.message, loaded.source);
  HopperRun run;
  run.half_angle = half_angle_deg * std::numbers::pi / 180.0;
  run.orifice = orifice;
  char name[64];
  std::snprintf(name, sizeof name, "%g deg, %g mm", half_angle_deg, 1e3 * orifice);
  run.name = name;

  // The wedge: walls from the orifice's edges at the half-angle from the
  // vertical, facing in (a wall's normal is its direction turned
  // counter-clockwise).
  const double s = std::sin(run.half_angle), c = std::cos(run.half_angle);
  const double length = kWedgeHeight / c;
  WallDef& left = def.world.walls[wall_named(def.world, "left").index()];
  left.point = {-0.5 * orifice, 0.0};
  left.direction = {s, -c};
  left.h1 = -length;
  left.h2 = 0.0;
  WallDef& right = def.world.walls[wall_named(def.world, "right").index()];
  right.point = {0.5 * orifice, 0.0};
  right.direction = {s, c};
  right.h1 = 0.0;
  right.h2 = length;
  WallDef& gate = def.world.walls[wall_named(def.world, "orifice").index()];
  gate.h1 = -0.5 * orifice;
  gate.h2 = 0.5 * orifice;
  // The spheres, generated again in the rectangle as wide as the wedge at
  // its bottom, with the case's sizes, material and seed.
  const proto::RandomPacking& packing = loaded.message.particles(0).random_packing();
  RandomPackingDef generation;
  generation.material = def.world.particles.front().material;
  const double half_width = 0.5 * orifice + kGenerationBottom * std::tan(run.half_angle);
  generation.min = {-half_width, kGenerationBottom};
  generation.max = {half_width, kGenerationTop};
  for (const proto::SizeClass& size : packing.size())
    generation.sizes.push_back({size.radius(), static_cast<int>(size.count())});
  generation.seed = packing.seed();
  def.world.particles = generate_random_packing(generation);

  const auto start = std::chrono::steady_clock::now();
  World world(def.world);
  run.particles = world.particle_count();
  const StageResult fill = run_stage(world, def.stages.at(0));
  run.filled = fill.condition_met;
  run.fill_seconds = world.time();

  const double opened = world.time();
  const double radius = world.particles().radius[ParticleId{0}];
  bool written = false;
  const auto count = [&](const World& w) {
    int below = 0;
    for (const Vec2& x : w.particles().position) below += x.y() < -radius ? 1 : 0;
    run.time.push_back(w.time() - opened);
    run.discharged.push_back(below);
    if (out && !written && 3 * below >= run.particles) {
      io::write_particles_csv(*out / run.name, w);
      written = true;
    }
    return below < run.particles;  // stop once every sphere has left
  };
  count(world);
  run_stage(world, def.stages.at(1), 2000, count);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The steady discharge: between 20 % and 70 % gone.
  std::vector<double> t, n;
  for (std::size_t k = 0; k < run.time.size(); ++k) {
    const double share = static_cast<double>(run.discharged[k]) / run.particles;
    if (share >= 0.2 && run.steady_from == 0.0) run.steady_from = run.time[k];
    if (share >= 0.2 && share <= 0.7) {
      t.push_back(run.time[k]);
      n.push_back(run.discharged[k]);
    }
  }
  const Line steady = fit_line(t, n);
  run.rate = steady.slope;
  run.rate_r_squared = steady.r_squared;
  run.acceleration_lag = steady.x_intercept;
  return run;
}

void print_hopper(std::FILE* out, const std::vector<HopperRun>& runs) {
  std::fprintf(out, "Hopper discharge (Randall 6.2, Platts): %d spheres of 0.3 mm\n",
               runs.empty() ? 0 : runs.front().particles);
  std::fprintf(
      out,
      "  run              filled in  steady from  acceleration lag  rate (spheres/s)  R^2 (20-70 %%)  left in  "
      "wall clock\n");
  for (const HopperRun& r : runs) {
    std::fprintf(out, "  %-15s  %.4f s   %.4f s     %.4f s          %9.1f        %.4f         %.3f s  %.0f s%s\n",
                 r.name.c_str(), r.fill_seconds, r.steady_from, r.acceleration_lag, r.rate, r.rate_r_squared,
                 r.time.empty() ? 0.0 : r.time.back(), r.seconds, r.filled ? "" : " (NOT at rest when opened)");
  }
}

void write_hopper_csv(const std::filesystem::path& out, const std::vector<HopperRun>& runs) {
  io::CsvFile series(out, "hopper.csv", "run,half_angle_deg,orifice,time,discharged");
  io::CsvFile rates(
      out, "hopper_rates.csv",
      "run,half_angle_deg,orifice,particles,fill_time,steady_from,acceleration_lag,rate,r_squared,empty_after");
  for (const HopperRun& r : runs) {
    const double degrees = r.half_angle * 180.0 / std::numbers::pi;
    for (std::size_t k = 0; k < r.time.size(); ++k)
      series.write_row(r.name, degrees, r.orifice, r.time[k], r.discharged[k]);
    rates.write_row(r.name, degrees, r.orifice, r.particles, r.fill_seconds, r.steady_from, r.acceleration_lag, r.rate,
                    r.rate_r_squared, r.time.empty() ? 0.0 : r.time.back());
  }
}

Verdict judge_hopper(const std::vector<HopperRun>& runs) {
  Verdict v;
  for (const HopperRun& r : runs) {
    v.expect(r.name + ": at rest before the orifice opened", r.filled);
    v.above(r.name + ": discharge rate, spheres/s", r.rate, 0.0);
    // "reaches a constant discharge rate which is maintained until the
    // remaining particles are no longer sufficient".
    v.above(r.name + ": R^2 of the discharge between 20 and 70 % (steady)", r.rate_r_squared, 0.98);
    v.at_least(r.name + ": spheres discharged", r.discharged.empty() ? 0 : r.discharged.back(), r.particles);
  }
  // "increasing the half-angle reduced the constant discharge rate";
  // "increasing the orifice width increased the discharge rate".
  for (const HopperRun& a : runs) {
    for (const HopperRun& b : runs) {
      if (a.orifice == b.orifice && a.half_angle < b.half_angle) {
        v.above("rate at " + a.name + " over at " + b.name, a.rate, b.rate);
        // "there was a reduction in the time elapsed until constant
        // discharge was achieved" as the half-angle grew.
        v.above("acceleration lag at " + a.name + " over at " + b.name, a.acceleration_lag, b.acceleration_lag);
      }
      if (a.half_angle == b.half_angle && a.orifice > b.orifice) {
        v.above("rate at " + a.name + " over at " + b.name, a.rate, b.rate);
        // "it did not seem to affect the duration of the initial
        // acceleration stage": the lags within a quarter of each other.
        v.near("acceleration lag at " + a.name + " over at " + b.name, a.acceleration_lag / b.acceleration_lag, 1.0,
               0.25);
      }
    }
  }
  return v;
}

}  // namespace dem::validation
