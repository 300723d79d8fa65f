#include "dem/service/world_session.h"

#include "dem/io/snapshot_file.h"
#include "dem/service/command_error.h"
#include "dem/service/output_recorder.h"

namespace dem::service {

namespace {

// Wire vectors as engine quantities: a 2D world has no z, and turns about z only.
Vec2 vector_of(const protocol::Vector3& v, std::integral_constant<int, 2>, const std::string& what) {
  if (v.z != 0.0) {
    throw CommandError(protocol::ReplyStatus::kBadRequest, what + " has a z component, but the simulation is 2D");
  }
  return {v.x, v.y};
}
Vec3 vector_of(const protocol::Vector3& v, std::integral_constant<int, 3>, const std::string&) {
  return {v.x, v.y, v.z};
}
double spin_of(const protocol::Vector3& w, std::integral_constant<int, 2>, const std::string& what) {
  if (w.x != 0.0 || w.y != 0.0) {
    throw CommandError(protocol::ReplyStatus::kBadRequest, what + ": a 2D wall turns about z only, x and y must be 0");
  }
  return w.z;
}
Vec3 spin_of(const protocol::Vector3& w, std::integral_constant<int, 3>, const std::string&) { return {w.x, w.y, w.z}; }

template <int Dim>
class CheckpointT final : public StateCheckpoint {
 public:
  explicit CheckpointT(WorldSnapshotT<Dim> snapshot) : snapshot_(std::move(snapshot)) {}
  std::uint64_t cycle() const override { return snapshot_.cycle; }
  std::string bytes(const io::SnapshotInfo& info) const override { return io::serialize_snapshot(snapshot_, info); }
  const WorldSnapshotT<Dim>& snapshot() const { return snapshot_; }

 private:
  WorldSnapshotT<Dim> snapshot_;
};

template <int Dim>
class StageStepperT final : public StageStepper {
 public:
  StageStepperT(BasicWorld<Dim>& world, StageDefT<Dim> stage) : run_(world, std::move(stage)) {}
  std::uint64_t cycles_to_next_stop() const override { return run_.cycles_to_next_stop(); }
  void cycle(std::uint64_t cycles) override { run_.cycle(cycles); }
  bool check() override { return run_.check(); }
  const StageResult& result() const override { return run_.result(); }

 private:
  StageRunT<Dim> run_;
};

template <int Dim>
class WorldSessionT final : public WorldSession {
 public:
  WorldSessionT(BasicWorld<Dim> world, std::vector<StageDefT<Dim>> stages,
                std::optional<analysis::CompressionSettings> compression, std::uint64_t vtk_interval,
                std::vector<io::MeasurementRegion> regions)
      : world_(std::move(world)),
        health_(world_),
        stages_(std::move(stages)),
        compression_(std::move(compression)),
        vtk_interval_(vtk_interval),
        region_settings_(std::move(regions)) {
    for (const io::MeasurementRegion& r : region_settings_) regions_.push_back(io::region_for<Dim>(r));
  }

  std::uint8_t dimension() const override { return Dim; }
  void cycle(std::uint64_t cycles) override { world_.cycle(cycles); }
  std::uint64_t cycle_count() const override { return world_.cycle_count(); }
  double time() const override { return world_.time(); }
  double time_step() const override { return world_.time_step(); }
  int particle_count() const override { return world_.particle_count(); }
  int wall_count() const override { return world_.wall_count(); }
  std::uint64_t state_hash() const override { return world_.state_hash(); }
  double kinetic_energy() const override { return world_.assembly_measures().kinetic_energy; }
  bool motion_suspect() const override { return health_.motion_suspect(world_); }

  WallId find_wall(std::string_view name) const override { return world_.find_wall(name); }
  std::string wall_name(WallId wall) const override { return world_.wall(wall).name; }
  double wall_area(WallId wall) const override { return world_.wall_area(wall); }
  protocol::WallForce read_wall(WallId wall) const override { return service::read_wall(world_, wall); }
  std::vector<protocol::WallForce> read_walls() const override { return service::read_walls(world_); }
  protocol::ContactStats read_contact_stats() const override { return service::read_contact_stats(world_); }
  std::optional<protocol::RegionTelemetry> read_regions() const override {
    if (regions_.empty()) return std::nullopt;
    return service::read_regions(world_, regions_);
  }
  std::vector<protocol::ContactEntry> query_contacts(const ContactFilter& filter) const override {
    return service::query_contacts(world_, filter);
  }
  std::optional<ServoLimits> default_servo_limits(WallId wall,
                                                  const std::vector<ContactModelDef>& models) const override {
    return service::default_servo_limits(world_, wall, models);
  }

  void set_wall_velocity(WallId wall, const protocol::Vector3& velocity,
                         const protocol::Vector3& angular_velocity) override {
    WallMotionT<Dim> motion;
    motion.velocity = vector_of(velocity, kDim, "the velocity");
    motion.angular_velocity = spin_of(angular_velocity, kDim, "the angular velocity");
    world_.set_wall_motion(wall, motion);
  }
  void set_wall_servo(WallId wall, const ServoDef& servo) override {
    WallMotionT<Dim> motion;
    motion.servo = servo;
    world_.set_wall_motion(wall, motion);
  }
  DampingDef damping() const override { return world_.damping(); }
  void set_damping(const DampingDef& damping) override { world_.set_damping(damping); }
  void set_time_step_fraction(double fraction) override { world_.set_time_step_fraction(fraction); }
  const std::vector<MaterialDef>& materials() const override { return world_.materials(); }
  void set_friction(MaterialId material, double friction) override { world_.set_friction(material, friction); }
  void set_gravity(const protocol::Vector3& gravity) override {
    world_.set_gravity(vector_of(gravity, kDim, "gravity"));
  }
  void set_threads(int threads) override { world_.set_threads(threads); }

  std::string snapshot_bytes(const io::SnapshotInfo& info) const override {
    return io::serialize_snapshot(world_.snapshot(), info);
  }
  std::unique_ptr<StateCheckpoint> checkpoint() const override {
    return std::make_unique<CheckpointT<Dim>>(world_.snapshot());
  }
  void restore(const StateCheckpoint& checkpoint) override {
    const int threads = world_.threads();
    world_ = BasicWorld<Dim>(dynamic_cast<const CheckpointT<Dim>&>(checkpoint).snapshot());
    world_.set_threads(threads);
    health_ = HealthMonitorT<Dim>(world_);
  }
  StepHealth assess_health() override { return health_.assess(world_); }

  std::size_t stage_count() const override { return stages_.size(); }
  const std::string& stage_name(std::size_t stage) const override { return stages_.at(stage).name; }
  std::uint64_t stage_cycles(std::size_t stage) const override { return stages_.at(stage).cycles; }
  StageResult run_stage(std::size_t stage, const std::function<bool()>& between_cycles, std::uint64_t done) override {
    // Resumed: the start actions are done and in the state.
    const StageDefT<Dim> running = done > 0 ? stage_remainder(stages_.at(stage), done) : stages_.at(stage);
    // An observer interval of one cycle: the caller decides what is due
    // (rows, telemetry, commands); run_stage alone decides the stage's end.
    StageResult result = dem::run_stage(world_, running, 1, [&](const BasicWorld<Dim>&) { return between_cycles(); });
    result.cycles_run += done;
    return result;
  }
  std::unique_ptr<StageStepper> begin_run(std::uint64_t cycles, const StopConditions& until) override {
    StageDefT<Dim> stage;
    stage.cycles = cycles;
    stage.until = until;
    return std::make_unique<StageStepperT<Dim>>(world_, std::move(stage));
  }
  bool resumable_at(std::size_t stage, std::uint64_t stage_cycles) const override {
    const StageDefT<Dim>& s = stages_.at(stage);
    if (stage_cycles >= s.cycles || stage_cycles % std::max<std::uint64_t>(s.until.check_interval, 1) != 0) {
      return false;
    }
    return !(has_stop_condition(s.until) && stage_cycles >= s.until.min_cycles &&
             dem::stop_conditions_hold(world_, s.until));
  }
  void restore_bytes(std::string_view snapshot_bytes, const std::string& source) override {
    const int threads = world_.threads();
    world_ = BasicWorld<Dim>(io::parse_snapshot<Dim>(snapshot_bytes, source).snapshot);
    world_.set_threads(threads);
    health_ = HealthMonitorT<Dim>(world_);
  }

  void start_tables(OutputRecorder& recorder, const std::string& case_name,
                    const io::ResumePoint* resume) const override {
    recorder.start(case_name, world_, compression_, vtk_interval_, resume, region_settings_);
  }
  void record_tables(OutputRecorder& recorder, std::optional<std::size_t> stage) const override {
    recorder.record(world_, stage);
  }
  void finish_tables(OutputRecorder& recorder) const override { recorder.finish(world_); }

 private:
  static constexpr std::integral_constant<int, Dim> kDim{};
  BasicWorld<Dim> world_;
  HealthMonitorT<Dim> health_;
  std::vector<StageDefT<Dim>> stages_;
  std::optional<analysis::CompressionSettings> compression_;
  std::uint64_t vtk_interval_;
  std::vector<io::MeasurementRegion> region_settings_;
  std::vector<analysis::RegionT<Dim>> regions_;
};

}  // namespace

template <int Dim>
std::unique_ptr<WorldSession> make_session(BasicWorld<Dim> world, std::vector<StageDefT<Dim>> stages,
                                           std::optional<analysis::CompressionSettings> compression,
                                           std::uint64_t vtk_interval, std::vector<io::MeasurementRegion> regions) {
  return std::make_unique<WorldSessionT<Dim>>(std::move(world), std::move(stages), std::move(compression), vtk_interval,
                                              std::move(regions));
}

template std::unique_ptr<WorldSession> make_session<2>(BasicWorld<2>, std::vector<StageDefT<2>>,
                                                       std::optional<analysis::CompressionSettings>, std::uint64_t,
                                                       std::vector<io::MeasurementRegion>);
template std::unique_ptr<WorldSession> make_session<3>(BasicWorld<3>, std::vector<StageDefT<3>>,
                                                       std::optional<analysis::CompressionSettings>, std::uint64_t,
                                                       std::vector<io::MeasurementRegion>);

}  // namespace dem::service
