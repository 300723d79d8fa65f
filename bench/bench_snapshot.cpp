// Saving and loading a snapshot of a large world: the conversion between
// the engine's snapshot and dem.proto.Snapshot (io/src/snapshot_conversion*)
// and the serialization around it, for N discs of a square lattice, each
// touching its neighbours (so every neighbour pair is a contact row), in a box
// of three walls. Prints the median of the repeats, in milliseconds:
//   to_proto    engine snapshot -> message
//   serialize   message -> bytes (framed, as dem_server saves them)
//   parse       bytes -> message (frame checked)
//   from_proto  message -> engine snapshot (its checks included)
//   save, load  the two directions whole (serialize_snapshot, parse_snapshot)
//
//   bench_snapshot [--particles N] [--repeats R]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dem/io/snapshot_file.h"
#include "dem/io/snapshot_frame.h"
#include "dem/packing.h"
#include "dem/world.h"

namespace {

dem::WorldDef lattice_world(int particles) {
  using namespace dem;
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(particles))));
  const int rows = (particles + columns - 1) / columns;
  constexpr double r = 0.01, spacing = 2 * r;
  WorldDef def;
  def.materials = {MaterialDef{"disc", 2650.0, 0.5, 0.0}, MaterialDef{"wall", 1.0, 0.3, 0.0}};
  ContactModelDef model;
  model.linear = {1.0e7, 0.7e7};
  def.contact_models = {model};
  LatticeDef lattice;
  lattice.radius = r;
  lattice.origin = {r, r};
  lattice.columns = columns;
  lattice.rows = rows;
  lattice.spacing = spacing;
  def.particles = generate_lattice(lattice);
  def.particles.resize(static_cast<std::size_t>(particles));
  const double width = 2 * r + (columns - 1) * spacing, height = 2 * r + (rows - 1) * spacing;
  def.walls = {WallDef{"bottom", {0, 0}, {1, 0}, 0, width, MaterialId{1}, {}},
               WallDef{"right", {width, 0}, {0, 1}, 0, 2 * height, MaterialId{1}, {}},
               WallDef{"left", {0, 2 * height}, {0, -1}, 0, 2 * height, MaterialId{1}, {}}};
  def.gravity = {0.0, -9.81};
  def.damping = {1e-5, 5.0};
  def.time_step_fraction = 0.2;
  def.threads = 1;
  return def;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <typename F>
double milliseconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Snapshot save and load of a large world"};
  int particles = 100000;
  int repeats = 5;
  app.add_option("--particles", particles, "discs in the lattice")->check(CLI::PositiveNumber);
  app.add_option("--repeats", repeats, "timed repeats of each step")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  dem::World world(lattice_world(particles));
  world.cycle(1);
  const dem::WorldSnapshot snapshot = world.snapshot();
  const dem::io::SnapshotInfo info{"lattice", ""};
  std::vector<double> to_proto, serialize, parse, from_proto, save, load;
  std::size_t bytes = 0;
  for (int k = 0; k < repeats; ++k) {
    dem::proto::Snapshot message;
    to_proto.push_back(milliseconds([&] { message = dem::io::snapshot_to_proto(snapshot, info); }));
    std::string framed;
    serialize.push_back(milliseconds([&] { framed = dem::io::frame_snapshot(message.SerializeAsString()); }));
    dem::proto::Snapshot parsed;
    parse.push_back(milliseconds([&] { parsed = dem::io::parse_snapshot_message(framed); }));
    from_proto.push_back(milliseconds([&] { (void)dem::io::snapshot_from_proto<2>(parsed); }));
    save.push_back(milliseconds([&] { framed = dem::io::serialize_snapshot(snapshot, info); }));
    load.push_back(milliseconds([&] { (void)dem::io::parse_snapshot<2>(framed); }));
    bytes = framed.size();
  }
  std::printf("%zu particles, %zu contact rows, %zu walls: %.1f MB\n", snapshot.def.particles.size(),
              snapshot.contacts.size(), snapshot.def.walls.size(), static_cast<double>(bytes) / 1e6);
  std::printf("median of %d, ms: to_proto %.2f  serialize %.2f  parse %.2f  from_proto %.2f  save %.2f  load %.2f\n",
              repeats, median(to_proto), median(serialize), median(parse), median(from_proto), median(save),
              median(load));
  return 0;
}
