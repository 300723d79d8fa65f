#include "dem/service/world_session.h"

#include "dem/service/command_error.h"

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
  WorldSessionT(BasicWorld<Dim> world, const std::vector<io::MeasurementRegion>& regions)
      : world_(std::move(world)), health_(world_) {
    for (const io::MeasurementRegion& r : regions) regions_.push_back(io::region_for<Dim>(r));
  }

  std::uint8_t dimension() const override { return Dim; }
  WorldView view() const override { return &world_; }
  std::uint64_t cycle_count() const override { return world_.cycle_count(); }
  double time() const override { return world_.time(); }
  double time_step() const override { return world_.time_step(); }
  int particle_count() const override { return world_.particle_count(); }
  std::uint64_t state_hash() const override { return world_.state_hash(); }
  bool motion_suspect() const override { return health_.motion_suspect(world_); }
  StepHealth assess_health() override { return health_.assess(world_); }

  std::optional<protocol::RegionTelemetry> read_regions() const override {
    if (regions_.empty()) return std::nullopt;
    return service::read_regions(world_, regions_);
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
  void set_damping(const DampingDef& damping) override { world_.set_damping(damping); }
  void set_time_step_fraction(double fraction) override { world_.set_time_step_fraction(fraction); }
  void set_friction(MaterialId material, double friction) override { world_.set_friction(material, friction); }
  void set_gravity(const protocol::Vector3& gravity) override {
    world_.set_gravity(vector_of(gravity, kDim, "gravity"));
  }
  void set_threads(int threads) override { world_.set_threads(threads); }

  void restore(const AnyWorldSnapshot& state) override {
    const int threads = world_.threads();
    // The world it replaces goes first: a restore after memory ran out
    // needs no more than the world it puts back. If building it fails, the
    // session is left without a world, for the caller to drop.
    const WorldSnapshotT<Dim>& snapshot = std::get<WorldSnapshotT<Dim>>(state);
    { const BasicWorld<Dim> replaced = std::move(world_); }
    world_ = BasicWorld<Dim>(snapshot);
    world_.set_threads(threads);
    health_ = HealthMonitorT<Dim>(world_);
  }

  std::unique_ptr<StageStepper> begin_stage(AnyStageDef stage) override {
    return std::make_unique<StageStepperT<Dim>>(world_, std::get<StageDefT<Dim>>(std::move(stage)));
  }

 private:
  static constexpr std::integral_constant<int, Dim> kDim{};
  BasicWorld<Dim> world_;
  HealthMonitorT<Dim> health_;
  std::vector<analysis::RegionT<Dim>> regions_;
};

}  // namespace

template <int Dim>
std::unique_ptr<WorldSession> make_session(BasicWorld<Dim> world, std::vector<io::MeasurementRegion> regions) {
  return std::make_unique<WorldSessionT<Dim>>(std::move(world), regions);
}

template std::unique_ptr<WorldSession> make_session<2>(BasicWorld<2>, std::vector<io::MeasurementRegion>);
template std::unique_ptr<WorldSession> make_session<3>(BasicWorld<3>, std::vector<io::MeasurementRegion>);

}  // namespace dem::service
