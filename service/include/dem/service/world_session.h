// The engine behind the service, whatever its dimension: the one interface
// the runner and the commands use to step, steer and read a 2D World or a
// 3D World3, and to run the case's loading programme. WorldSessionT<Dim>
// implements it over the engine and the readout functions
// (engine_readout.h); a call per command or per chunk of cycles, never per
// particle (run_stage's callback excepted: it is how a one-shot run stays
// responsive inside a stage).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dem/analysis/compression_settings.h"
#include "dem/health.h"
#include "dem/io/case_definition.h"
#include "dem/io/checkpoint_store.h"
#include "dem/io/snapshot_conversion.h"
#include "dem/programme.h"
#include "dem/protocol/messages.h"
#include "dem/service/engine_readout.h"
#include "dem/world.h"

namespace dem::service {

class OutputRecorder;

// The whole state at one cycle, copied in memory (the engine's snapshot) so
// it can be written later: a one-shot run that fails writes its last good one.
class StateCheckpoint {
 public:
  virtual ~StateCheckpoint() = default;
  virtual std::uint64_t cycle() const = 0;
  virtual std::string bytes(const io::SnapshotInfo& info) const = 0;  // a serialized dem.proto.Snapshot
};

// A one-stage programme of the engine's (StageRunT) stepped by the runner
// between the commands: cycle() and check() in turn until the stage is over.
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

  virtual std::uint8_t dimension() const = 0;
  virtual void cycle(std::uint64_t cycles) = 0;
  virtual std::uint64_t cycle_count() const = 0;
  virtual double time() const = 0;       // s
  virtual double time_step() const = 0;  // s
  virtual int particle_count() const = 0;
  virtual int wall_count() const = 0;
  virtual std::uint64_t state_hash() const = 0;
  virtual double kinetic_energy() const = 0;  // J (a pass over the particles and the contacts)
  // A motion not finite or a particle flung out (HealthMonitorT::
  // motion_suspect): a pass over the particles alone, cheap enough after
  // every chunk, for what a blow-up reaches between two paced health
  // assessments.
  virtual bool motion_suspect() const = 0;

  virtual WallId find_wall(std::string_view name) const = 0;  // kInvalidId when unknown
  virtual std::string wall_name(WallId wall) const = 0;
  virtual double wall_area(WallId wall) const = 0;
  virtual protocol::WallForce read_wall(WallId wall) const = 0;
  virtual std::vector<protocol::WallForce> read_walls() const = 0;
  virtual protocol::ContactStats read_contact_stats() const = 0;
  // The measures of the case's regions; nothing when it names none.
  virtual std::optional<protocol::RegionTelemetry> read_regions() const = 0;
  virtual std::vector<protocol::ContactEntry> query_contacts(const ContactFilter& filter) const = 0;
  virtual std::optional<ServoLimits> default_servo_limits(WallId wall,
                                                          const std::vector<ContactModelDef>& models) const = 0;

  // Steering. A 2D world refuses out-of-plane vectors (CommandError); the
  // engine's own checks throw DefinitionError.
  virtual void set_wall_velocity(WallId wall, const protocol::Vector3& velocity,
                                 const protocol::Vector3& angular_velocity) = 0;
  virtual void set_wall_servo(WallId wall, const ServoDef& servo) = 0;
  virtual DampingDef damping() const = 0;
  virtual void set_damping(const DampingDef& damping) = 0;
  virtual void set_time_step_fraction(double fraction) = 0;
  virtual const std::vector<MaterialDef>& materials() const = 0;
  virtual void set_friction(MaterialId material, double friction) = 0;
  virtual void set_gravity(const protocol::Vector3& gravity) = 0;
  virtual void set_threads(int threads) = 0;

  virtual std::string snapshot_bytes(const io::SnapshotInfo& info) const = 0;
  virtual std::unique_ptr<StateCheckpoint> checkpoint() const = 0;
  // Puts the world back to a checkpoint this session took (its stages and
  // threads stay); the health monitor starts afresh from it.
  virtual void restore(const StateCheckpoint& checkpoint) = 0;
  // The engine's health status of the state now (a pass over the particles
  // and contacts: HealthWatch paces it).
  virtual StepHealth assess_health() = 0;

  // The case's loading programme: its stages as io converted them (none for
  // a world restored from a snapshot), run by the engine's run_stage.
  virtual std::size_t stage_count() const = 0;
  virtual const std::string& stage_name(std::size_t stage) const = 0;
  virtual std::uint64_t stage_cycles(std::size_t stage) const = 0;  // its length, or its cap when it has conditions
  // Runs one stage; `between_cycles` is called after every cycle and ends
  // the stage early by returning false. Throws what the engine throws.
  // `done`: the stage's cycles run already (a resumed checkpoint's): its
  // start actions are in the state, its length and minimum count from
  // there; the result counts them.
  virtual StageResult run_stage(std::size_t stage, const std::function<bool()>& between_cycles,
                                std::uint64_t done = 0) = 0;
  // A cycle or run_until command as a one-stage programme: `cycles`, ended
  // early by `until` (the engine's stop rule), no start actions. The
  // stepper steps this session's world (valid while this session is).
  virtual std::unique_ptr<StageStepper> begin_run(std::uint64_t cycles, const StopConditions& until) = 0;
  // Whether a checkpoint `stage_cycles` into the stage can be resumed as if
  // never interrupted: before its end, on one of its condition checks, and
  // not one where the conditions hold (dem/programme.h) - the stage
  // ends there, after the row the checkpoint follows.
  virtual bool resumable_at(std::size_t stage, std::uint64_t stage_cycles) const = 0;
  // Replaces the world by a framed snapshot's (a checkpoint of this case);
  // the stages stay. Throws SnapshotError or DefinitionError.
  virtual void restore_bytes(std::string_view snapshot_bytes, const std::string& source) = 0;

  // The per-case tables (the recorder writes them for this world's
  // dimension); `stage`, the stage running, when a programme runs (the
  // plate loading analyses follow programmes only).
  virtual void start_tables(OutputRecorder& recorder, const std::string& case_name,
                            const io::ResumePoint* resume = nullptr) const = 0;
  virtual void record_tables(OutputRecorder& recorder, std::optional<std::size_t> stage = std::nullopt) const = 0;
  virtual void finish_tables(OutputRecorder& recorder) const = 0;
};

// `compression`: the case's plate loading analyses (output.compression), if
// any; `vtk_interval`: the case's cycles between ParaView files of a
// programme (output.vtk_interval; 0 = none); `regions`: the case's
// measurement regions (output.region), published and written each row.
template <int Dim>
std::unique_ptr<WorldSession> make_session(BasicWorld<Dim> world, std::vector<StageDefT<Dim>> stages = {},
                                           std::optional<analysis::CompressionSettings> compression = std::nullopt,
                                           std::uint64_t vtk_interval = 0,
                                           std::vector<io::MeasurementRegion> regions = {});

}  // namespace dem::service
