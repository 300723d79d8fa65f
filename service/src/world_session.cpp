#include "dem/service/world_session.h"

#include "dem/service/engine_readout.h"

namespace dem::service {

template <int Dim>
WorldSession::Held<Dim>::Held(BasicWorld<Dim> w, const std::vector<io::MeasurementRegion>& case_regions)
    : world(std::move(w)), health(world) {
  for (const io::MeasurementRegion& r : case_regions) regions.push_back(io::region_for<Dim>(r));
}

template <int Dim>
WorldSession::WorldSession(BasicWorld<Dim> world, const std::vector<io::MeasurementRegion>& regions)
    : held_(std::in_place_type<Held<Dim>>, std::move(world), regions) {}

std::uint64_t WorldSession::cycle_count() const {
  return on_world(*this, [](const auto& world) { return world.cycle_count(); });
}

double WorldSession::time() const {
  return on_world(*this, [](const auto& world) { return world.time(); });
}

double WorldSession::time_step() const {
  return on_world(*this, [](const auto& world) { return world.time_step(); });
}

int WorldSession::particle_count() const {
  return on_world(*this, [](const auto& world) { return world.particle_count(); });
}

std::uint64_t WorldSession::state_hash() const {
  return on_world(*this, [](const auto& world) { return world.state_hash(); });
}

bool WorldSession::motion_suspect() const {
  return std::visit([](const auto& held) { return held.health.motion_suspect(held.world); }, held_);
}

StepHealth WorldSession::assess_health() {
  return std::visit([](auto& held) { return held.health.assess(held.world); }, held_);
}

std::optional<protocol::RegionTelemetry> WorldSession::read_regions() const {
  return std::visit(
      [](const auto& held) -> std::optional<protocol::RegionTelemetry> {
        if (held.regions.empty()) return std::nullopt;
        return service::read_regions(held.world, held.regions);
      },
      held_);
}

template <int Dim>
void WorldSession::restore(const WorldSnapshotT<Dim>& state) {
  Held<Dim>& held = std::get<Held<Dim>>(held_);
  const int threads = held.world.threads();
  // The world it replaces goes first: a restore after memory ran out
  // needs no more than the world it puts back. If building it fails, the
  // session is left without a world, for the caller to drop.
  { const BasicWorld<Dim> replaced = std::move(held.world); }
  held.world = BasicWorld<Dim>(state);
  held.world.set_threads(threads);
  held.health = HealthMonitorT<Dim>(held.world);
}

template <int Dim>
StageStepper WorldSession::begin_stage(StageDefT<Dim> stage) {
  return StageStepper(std::get<Held<Dim>>(held_).world, std::move(stage));
}

template WorldSession::WorldSession(BasicWorld<2>, const std::vector<io::MeasurementRegion>&);
template WorldSession::WorldSession(BasicWorld<3>, const std::vector<io::MeasurementRegion>&);
template void WorldSession::restore(const WorldSnapshotT<2>&);
template void WorldSession::restore(const WorldSnapshotT<3>&);
template StageStepper WorldSession::begin_stage(StageDefT<2>);
template StageStepper WorldSession::begin_stage(StageDefT<3>);

}  // namespace dem::service
