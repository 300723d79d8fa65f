#include "dem/service/world_snapshots.h"

#include "dem/io/snapshot_file.h"

namespace dem::service {

std::string snapshot_bytes(const WorldSession& world, const io::SnapshotInfo& info) {
  return on_world(world, [&](const auto& w) { return io::serialize_snapshot(w.snapshot(), info); });
}

void restore_bytes(WorldSession& world, std::string_view bytes, const std::string& source) {
  if (world.dimension() == 3) {
    world.restore(io::parse_snapshot<3>(bytes, source).snapshot);
  } else {
    world.restore(io::parse_snapshot<2>(bytes, source).snapshot);
  }
}

StateCheckpoint::StateCheckpoint(const WorldSession& world)
    : state_(on_world(world, [](const auto& w) { return decltype(state_)(w.snapshot()); })) {}

std::uint64_t StateCheckpoint::cycle() const {
  return std::visit([](const auto& state) { return state.cycle; }, state_);
}

void StateCheckpoint::restore(WorldSession& world) const {
  std::visit([&](const auto& state) { world.restore(state); }, state_);
}

std::string StateCheckpoint::bytes(const io::SnapshotInfo& info) const {
  return std::visit([&](const auto& state) { return io::serialize_snapshot(state, info); }, state_);
}

}  // namespace dem::service
