#include "dem/io/case_conversion.h"

#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "dem/error.h"
#include "dem/io/case_validation.h"
#include "dem/packing.h"
#include "field_path.h"

namespace dem::io {
namespace {

Vec2 to_vec2(const proto::Vector2& v) { return {v.x(), v.y()}; }

WallMotion to_motion(const proto::WallMotion& motion) {
  WallMotion def;
  def.velocity = to_vec2(motion.velocity());
  def.angular_velocity = motion.angular_velocity();
  if (motion.has_servo()) {
    def.servo = ServoDef{motion.servo().target_force(), motion.servo().gain(), motion.servo().max_speed()};
  }
  return def;
}

DampingDef to_damping(const proto::Damping& damping) { return {damping.contact_beta(), damping.global_alpha()}; }

StopConditions to_stop_conditions(const proto::Until& until) {
  StopConditions def;
  if (until.has_kinetic_energy_below()) def.kinetic_energy_below = until.kinetic_energy_below();
  if (until.has_out_of_balance_below()) def.out_of_balance_below = until.out_of_balance_below();
  if (until.has_servo_tolerance()) def.servo_tolerance = until.servo_tolerance();
  def.min_cycles = until.min_cycles();
  if (until.check_interval() > 0) def.check_interval = until.check_interval();
  return def;
}

// Converts a case validate_case accepted, so every name it looks up exists.
class Converter {
 public:
  Converter(const proto::Case& c, const CaseSource& source) : case_(c), source_(source) {}

  CaseDefinition run() {
    CaseDefinition def;
    def.name = case_.name();
    def.description = case_.description();
    // Not default_world_def(): its stand-in material and default contact
    // model would shift the case's material ids and cover pairs the case left out.
    def.world = WorldDef{};
    add_materials(def.world);
    add_contact_models(def.world);
    add_particles(def.world);
    add_walls(def.world);
    def.world.damping = to_damping(case_.damping());
    def.world.gravity = to_vec2(case_.gravity());
    // proto3 cannot tell an unset number from 0, so 0 keeps the engine's default.
    if (case_.time_step().fraction() > 0) def.world.time_step_fraction = case_.time_step().fraction();
    def.world.fixed_time_step = case_.time_step().fixed();
    def.world.contact_tolerance = case_.numerics().contact_tolerance();
    def.world.threads = static_cast<int>(case_.numerics().threads());
    add_stages(def.stages);
    add_output(def.output);
    return def;
  }

 private:
  void add_materials(WorldDef& world) {
    for (int i = 0; i < case_.material_size(); ++i) {
      const proto::Material& material = case_.material(i);
      MaterialDef def;
      def.name = material.name();
      // Density only matters for particles, and validation demands it there;
      // a wall material may leave it out.
      if (material.density() > 0) def.density = material.density();
      def.friction = material.friction();
      def.cohesion = material.cohesion();
      world.materials.push_back(def);
      materials_.emplace(material.name(), i);
    }
  }

  void add_contact_models(WorldDef& world) {
    for (const proto::ContactModel& model : case_.contact_model()) {
      ContactModelDef def;
      if (model.materials_size() > 0) {
        def.material_a = materials_.at(model.materials(0));
        def.material_b = materials_.at(model.materials(model.materials_size() - 1));
      }
      def.linear.normal_stiffness = model.linear().normal_stiffness();
      def.linear.shear_stiffness = model.linear().shear_stiffness();
      if (model.has_friction()) def.friction = model.friction();
      if (model.has_cohesion()) def.cohesion = model.cohesion();
      world.contact_models.push_back(def);
    }
  }

  void add_particles(WorldDef& world) {
    for (int i = 0; i < case_.particles_size(); ++i) {
      const proto::ParticleSource& source = case_.particles(i);
      const std::string path = indexed("particles", i);
      std::vector<ParticleDef> particles;
      try {
        switch (source.source_case()) {
          case proto::ParticleSource::kParticle:
            particles.push_back(to_particle(source.particle()));
            break;
          case proto::ParticleSource::kLattice:
            particles = generate_lattice(to_lattice(source.lattice()));
            break;
          case proto::ParticleSource::kRandomPacking:
            particles = generate_random_packing(to_random_packing(source.random_packing()));
            break;
          case proto::ParticleSource::SOURCE_NOT_SET:
            break;
        }
      } catch (const DefinitionError& error) {
        throw CaseError(describe_problem(source_, path + '.' + source_field(source), error.what()));
      }
      world.particles.insert(world.particles.end(), particles.begin(), particles.end());
    }
  }

  static std::string source_field(const proto::ParticleSource& source) {
    const auto* field = source.GetDescriptor()->FindFieldByNumber(source.source_case());
    return field != nullptr ? field->name() : std::string("source");
  }

  ParticleDef to_particle(const proto::Particle& particle) const {
    ParticleDef def;
    def.position = to_vec2(particle.position());
    def.radius = particle.radius();
    def.material = materials_.at(particle.material());
    def.velocity = to_vec2(particle.velocity());
    def.angular_velocity = particle.angular_velocity();
    return def;
  }

  LatticeDef to_lattice(const proto::Lattice& lattice) const {
    LatticeDef def;
    def.material = materials_.at(lattice.material());
    def.radius = lattice.radius();
    def.origin = to_vec2(lattice.origin());
    def.columns = static_cast<int>(lattice.columns());
    def.rows = static_cast<int>(lattice.rows());
    def.spacing = lattice.spacing() > 0 ? lattice.spacing() : 2 * lattice.radius();
    def.arrangement = lattice.arrangement() == proto::LATTICE_HEXAGONAL ? LatticeArrangement::kHexagonal
                                                                        : LatticeArrangement::kSquare;
    return def;
  }

  RandomPackingDef to_random_packing(const proto::RandomPacking& packing) const {
    RandomPackingDef def;
    def.material = materials_.at(packing.material());
    def.min = to_vec2(packing.min());
    def.max = to_vec2(packing.max());
    for (const proto::SizeClass& size : packing.size()) {
      def.sizes.push_back({size.radius(), static_cast<int>(size.count())});
    }
    def.seed = packing.seed();
    if (packing.max_attempts() > 0) def.max_attempts = static_cast<int>(packing.max_attempts());
    return def;
  }

  void add_walls(WorldDef& world) {
    for (int i = 0; i < case_.wall_size(); ++i) {
      const proto::Wall& wall = case_.wall(i);
      WallDef def;
      def.name = wall.name();
      def.point = to_vec2(wall.point());
      if (wall.orientation_case() == proto::Wall::kAngleDeg) {
        const double angle = wall.angle_deg() * std::numbers::pi / 180.0;
        def.direction = {std::cos(angle), std::sin(angle)};
      } else {
        def.direction = to_vec2(wall.direction()).normalized();
      }
      def.h1 = wall.h1();
      def.h2 = wall.h2();
      def.material = materials_.at(wall.material());
      def.motion = to_motion(wall.motion());
      world.walls.push_back(def);
      walls_.emplace(wall.name(), i);
    }
  }

  void add_stages(std::vector<StageDef>& stages) const {
    for (const proto::Stage& stage : case_.stage()) {
      StageDef def;
      def.name = stage.name();
      for (const proto::WallCommand& command : stage.wall()) {
        def.wall_motions.emplace_back(walls_.at(command.wall()), to_motion(command.motion()));
      }
      if (stage.has_damping()) def.damping = to_damping(stage.damping());
      def.cycles = stage.cycles();
      if (stage.has_until()) def.until = to_stop_conditions(stage.until());
      stages.push_back(def);
    }
  }

  void add_output(OutputSettings& output) const {
    if (case_.output().interval() > 0) output.interval = case_.output().interval();
    output.contacts_file = !case_.output().no_contacts_file();
    for (const proto::ContactProbe& probe : case_.output().probe()) {
      output.probes.push_back(
          {probe.name(), static_cast<ParticleId>(probe.first()), static_cast<ParticleId>(probe.second())});
    }
  }

  const proto::Case& case_;
  const CaseSource& source_;
  std::map<std::string, MaterialId, std::less<>> materials_;
  std::map<std::string, WallId, std::less<>> walls_;
};

}  // namespace

CaseDefinition convert_case(const proto::Case& message, const CaseSource& source) {
  validate_case(message, source);
  return Converter(message, source).run();
}

}  // namespace dem::io
