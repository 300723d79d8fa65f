// The engine behind the service, whatever its dimension: the one interface
// the runner and the commands use to step and steer a 2D World or a 3D
// World3 and to hold its state (its cycle, time, hash, health; a state put
// back). WorldSessionT<Dim> implements it over the engine; a call per
// command or per chunk of cycles, never per particle. What only reads a
// world works on its read view (view()): the readers of world_view.h, the
// case's tables (OutputRecorder), snapshots and checkpoints
// (world_snapshots.h) and the case's loading programme (case_programme.h).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "dem/health.h"
#include "dem/io/case_definition.h"
#include "dem/programme.h"
#include "dem/protocol/messages.h"
#include "dem/service/world_view.h"
#include "dem/snapshot.h"
#include "dem/world.h"

namespace dem::service {

// A whole state of either dimension, as the engine copies it.
using AnyWorldSnapshot = std::variant<WorldSnapshotT<2>, WorldSnapshotT<3>>;
// A stage of the engine's of either dimension.
using AnyStageDef = std::variant<StageDefT<2>, StageDefT<3>>;

// A stage of the engine's (StageRunT) stepped by the runner between the
// commands: cycle() and check() in turn until the stage is over.
class StageStepper {
 public:
  virtual ~StageStepper() = default;
  virtual std::uint64_t cycles_to_next_stop() const = 0;
  virtual void cycle(std::uint64_t cycles) = 0;
  virtual bool check() = 0;
  virtual const StageResult& result() const = 0;
};

class WorldSession {
 public:
  virtual ~WorldSession() = default;

  // State.
  virtual std::uint8_t dimension() const = 0;
  virtual WorldView view() const = 0;
  virtual std::uint64_t cycle_count() const = 0;
  virtual double time() const = 0;       // s
  virtual double time_step() const = 0;  // s
  virtual int particle_count() const = 0;
  virtual std::uint64_t state_hash() const = 0;
  // A motion not finite or a particle flung out (HealthMonitorT::
  // motion_suspect): a pass over the particles alone, cheap enough after
  // every chunk, for what a blow-up reaches between two paced health
  // assessments.
  virtual bool motion_suspect() const = 0;
  // The engine's health status of the state now (a pass over the particles
  // and contacts: HealthWatch paces it).
  virtual StepHealth assess_health() = 0;
  // The measures of the case's regions; nothing when it names none.
  virtual std::optional<protocol::RegionTelemetry> read_regions() const = 0;

  // Steering. A 2D world refuses out-of-plane vectors (CommandError); the
  // engine's own checks throw DefinitionError.
  virtual void set_wall_velocity(WallId wall, const protocol::Vector3& velocity,
                                 const protocol::Vector3& angular_velocity) = 0;
  virtual void set_wall_servo(WallId wall, const ServoDef& servo) = 0;
  virtual void set_damping(const DampingDef& damping) = 0;
  virtual void set_time_step_fraction(double fraction) = 0;
  virtual void set_friction(MaterialId material, double friction) = 0;
  virtual void set_gravity(const protocol::Vector3& gravity) = 0;
  virtual void set_threads(int threads) = 0;
  // Replaces the world by a state of its dimension (std::bad_variant_access
  // for the other); its threads stay and the health monitor starts afresh
  // from it. The old world is freed first, so going back to a state needs
  // no more memory than that state; if building the new one throws
  // (std::bad_alloc), the session is left without a world and must be
  // dropped (Simulation::drop).
  virtual void restore(const AnyWorldSnapshot& state) = 0;

  // Stepping: a stage of the engine's on this session's world, its start
  // actions done (std::bad_variant_access for a stage of the other
  // dimension). The stepper steps this session's world (valid while this
  // session is).
  virtual std::unique_ptr<StageStepper> begin_stage(AnyStageDef stage) = 0;
};

// `regions`: the case's measurement regions (output.region), read for the
// telemetry (read_regions).
template <int Dim>
std::unique_ptr<WorldSession> make_session(BasicWorld<Dim> world, std::vector<io::MeasurementRegion> regions = {});

}  // namespace dem::service
