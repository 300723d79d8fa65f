// The engine behind the service, whatever its dimension: a session holds a
// 2D World or a 3D World3 - one std::variant, the one place the dimension
// is hidden - with what the service keeps beside it (the engine's health
// monitor, the case's measurement regions). on_world(session, act) is the
// one visit over it: the readers (world_view.h), the steering
// (world_steering.h), the tables (OutputRecorder), snapshots
// (world_snapshots.h) and the programme (case_programme.h) each act on the
// world in its own dimension through it. The session itself only steps (a stage begun on
// its world) and holds the state (its cycle, time, hash, health; a state
// put back). A call per command or per chunk of cycles, never per particle.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "dem/health.h"
#include "dem/io/case_definition.h"
#include "dem/programme.h"
#include "dem/protocol/messages.h"
#include "dem/service/stage_stepper.h"
#include "dem/snapshot.h"
#include "dem/world.h"

namespace dem::service {

class WorldSession {
 public:
  // `regions`: the case's measurement regions (output.region), read for the
  // telemetry (read_regions).
  template <int Dim>
  explicit WorldSession(BasicWorld<Dim> world, const std::vector<io::MeasurementRegion>& regions = {});
  // Its world keeps its address: a stage begun on it steps it in place.
  WorldSession(const WorldSession&) = delete;
  WorldSession& operator=(const WorldSession&) = delete;

  // `act(world)` on the session's world, whatever its dimension.
  template <class Act>
  friend decltype(auto) on_world(const WorldSession& session, Act&& act) {
    return std::visit([&](const auto& held) -> decltype(auto) { return act(held.world); }, session.held_);
  }
  template <class Act>
  friend decltype(auto) on_world(WorldSession& session, Act&& act) {
    return std::visit([&](auto& held) -> decltype(auto) { return act(held.world); }, session.held_);
  }

  // The world, for what knows its dimension already (a stage of the
  // programme's): std::bad_variant_access when it is of the other.
  template <int Dim>
  const BasicWorld<Dim>& world() const {
    return std::get<Held<Dim>>(held_).world;
  }

  // State.
  std::uint8_t dimension() const { return held_.index() == 0 ? 2 : 3; }
  std::uint64_t cycle_count() const;
  double time() const;       // s
  double time_step() const;  // s
  int particle_count() const;
  std::uint64_t state_hash() const;
  // A motion not finite or a particle flung out (HealthMonitorT::
  // motion_suspect): a pass over the particles alone, cheap enough after
  // every chunk, for what a blow-up reaches between two paced health
  // assessments.
  bool motion_suspect() const;
  // The engine's health status of the state now (a pass over the particles
  // and contacts: HealthWatch paces it).
  StepHealth assess_health();
  // The measures of the case's regions; nothing when it names none.
  std::optional<protocol::RegionTelemetry> read_regions() const;

  // Replaces the world by a state of its dimension (std::bad_variant_access
  // for the other, with nothing changed); its threads stay and the health
  // monitor starts afresh from it. The old world is freed first, so going
  // back to a state needs no more memory than that state; if building the
  // new one throws (std::bad_alloc), the session is left without a world
  // and must be dropped (Simulation::drop).
  template <int Dim>
  void restore(const WorldSnapshotT<Dim>& state);

  // Stepping: a stage of the engine's on this session's world, its start
  // actions done (std::bad_variant_access for a stage of the other
  // dimension). The stepper steps this session's world in place (valid
  // while this session is and its world is not restored).
  template <int Dim>
  StageStepper begin_stage(StageDefT<Dim> stage);

 private:
  // The world of one dimension and what is kept beside it.
  template <int Dim>
  struct Held {
    Held(BasicWorld<Dim> w, const std::vector<io::MeasurementRegion>& case_regions);
    BasicWorld<Dim> world;
    HealthMonitorT<Dim> health;
    std::vector<analysis::RegionT<Dim>> regions;
  };
  std::variant<Held<2>, Held<3>> held_;
};

}  // namespace dem::service
