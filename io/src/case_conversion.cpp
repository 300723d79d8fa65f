#include "dem/io/case_conversion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <string>

#include "case_fields.h"
#include "case_laws.h"
#include "dem/error.h"
#include "dem/io/case_validation.h"
#include "dem/io/file_access.h"
#include "dem/io/particle_file.h"
#include "dem/packing.h"
#include "field_path.h"
#include "problem_list.h"

namespace dem::io {
namespace {

using WallIndex = std::map<std::string, WallId, std::less<>>;

template <int Dim>
Vec<Dim> to_vec(const proto::Vector& v) {
  if constexpr (Dim == 2) {
    return {v.x(), v.y()};
  } else {
    return {v.x(), v.y(), v.z()};
  }
}

// An angular velocity: the scalar about z in 2D, the vector in 3D.
template <int Dim>
Spin<Dim> to_spin(double about_z, const proto::Vector& vector) {
  if constexpr (Dim == 2) {
    return about_z;
  } else {
    return to_vec<3>(vector);
  }
}

template <int Dim>
WallMotionT<Dim> to_motion(const proto::WallMotion& motion) {
  WallMotionT<Dim> def;
  read_fields(motion, def);  // the velocity and the servo when set (case_rules.h)
  def.angular_velocity = to_spin<Dim>(motion.angular_velocity(), motion.angular_velocity_3d());
  return def;
}

DampingDef to_damping(const proto::Damping& damping) {
  DampingDef def;
  read_fields(damping, def);
  return def;
}

// A particle's shape: a superquadric in 2D, an ellipsoid in 3D (validation
// refuses the other dimension's); round when it has none. `Source` is a
// proto::Particle or a proto::SizeClass.
template <int Dim, typename Source>
ShapeDefT<Dim> to_shape(const Source& source) {
  if constexpr (Dim == 2) {
    if (source.has_superquadric()) {
      ShapeDefT<2> def;
      read_fields(source.superquadric(), def);  // a, b, n and the angle in radians (case_rules.h)
      return def;
    }
  } else {
    if (source.has_ellipsoid()) {
      const proto::Ellipsoid& shape = source.ellipsoid();
      ShapeDefT<3> def;
      read_fields(shape, def);  // the semi-axes (case_rules.h)
      if (shape.has_orientation()) {
        const proto::Quaternion& q = shape.orientation();
        def.orientation = Quaternion(q.w(), q.x(), q.y(), q.z()).normalized();
      }
      return def;
    }
  }
  return {};
}

MeasurementRegion to_region(const proto::MeasurementRegion& r);

// A stage's stop conditions: the numbers by their list (case_rules.h), the
// walls and a region by name here; a region is one of the case's output
// regions (validation checked the names), in the case's dimension.
template <int Dim>
StopConditions to_stop_conditions(const proto::Until& until, const WallIndex& walls, const proto::Output& output) {
  StopConditions def;
  read_fields(until, def);
  if (until.has_wall_stress_above()) {
    def.wall_stress_above =
        WallThreshold{walls.at(until.wall_stress_above().wall()), until.wall_stress_above().value()};
  }
  if (until.has_wall_settlement_above()) {
    def.wall_settlement_above =
        WallThreshold{walls.at(until.wall_settlement_above().wall()), until.wall_settlement_above().value()};
  }
  if (until.has_region_out_of_balance_below()) {
    const proto::RegionThreshold& threshold = until.region_out_of_balance_below();
    for (const proto::MeasurementRegion& region : output.region()) {
      if (region.name() != threshold.region()) continue;
      def.region_out_of_balance_below = RegionThreshold{region_for<Dim>(to_region(region)), threshold.value()};
    }
  }
  return def;
}

// Element-test control of a box of walls (validation checked the names and
// that every axis says what drives it); the numbers by their lists (case_rules.h).
template <int Dim>
BoxControlT<Dim> to_box_control(const proto::BoxControl& box, const WallIndex& walls) {
  BoxControlT<Dim> def;
  read_fields(box, def);
  for (int i = 0; i < Dim; ++i) {
    const proto::BoxAxis& axis = box.axis(i);
    BoxAxisDef& a = def.axes[static_cast<std::size_t>(i)];
    read_fields(axis, a);
    a.lower = walls.at(axis.lower_wall());
    a.upper = walls.at(axis.upper_wall());
    switch (axis.control_case()) {
      case proto::BoxAxis::kStrainRate:
        a.control = AxisControl::kStrainRate;
        break;
      case proto::BoxAxis::kStress:
        a.control = AxisControl::kStress;
        break;
      case proto::BoxAxis::kStressPath:
      case proto::BoxAxis::CONTROL_NOT_SET:
        a.control = AxisControl::kStressPath;
        break;
    }
  }
  if (box.path_case() == proto::BoxControl::kConstantMeanStress) {
    def.path = StressPath::kConstantMeanStress;
    def.path_value = box.constant_mean_stress();
  } else if (box.path_case() == proto::BoxControl::kStressRatio) {
    def.path = StressPath::kStressRatio;
    def.path_value = box.stress_ratio();
  }
  return def;
}

template <int Dim>
CentripetalGravityT<Dim> to_centripetal(const proto::CentripetalGravity& field) {
  CentripetalGravityT<Dim> def;
  read_fields(field, def);
  return def;
}

template <int Dim>
BodyForceT<Dim> to_body_force(const proto::BodyForce& body) {
  if (!body.has_centripetal()) return {to_vec<Dim>(body.gravity()), std::nullopt};
  return {to_vec<Dim>(body.gravity()), to_centripetal<Dim>(body.centripetal())};
}

MeasurementRegion to_region(const proto::MeasurementRegion& r) {
  MeasurementRegion region;
  region.name = r.name();
  const auto vec = [](const proto::Vector& v) { return Vec3(v.x(), v.y(), v.z()); };
  switch (r.shape_case()) {
    case proto::MeasurementRegion::kBox:
      region.shape = analysis::RegionShape::kBox;
      region.min = vec(r.box().min());
      region.max = vec(r.box().max());
      break;
    case proto::MeasurementRegion::kBall:
      region.shape = analysis::RegionShape::kBall;
      region.centre = vec(r.ball().centre());
      region.radius = r.ball().radius();
      break;
    case proto::MeasurementRegion::kWhole:
    case proto::MeasurementRegion::SHAPE_NOT_SET:
      region.shape = analysis::RegionShape::kWhole;
      break;
  }
  return region;
}

// The analyses start with the first stage that places the loading plate.
int loading_stage(const proto::Case& c) {
  for (int i = 0; i < c.stage_size(); ++i) {
    const proto::Stage& stage = c.stage(i);
    if (stage.has_place_wall() && stage.place_wall().wall() == c.output().compression().loading_plate()) return i;
  }
  return 0;
}

// The numbers by their lists (case_rules.h), the plates by name here.
analysis::CompressionSettings to_compression(const proto::Case& c, const WallIndex& walls) {
  const proto::CompressionOutput& compression = c.output().compression();
  analysis::CompressionSettings def;
  read_fields(compression, def);
  def.loading_plate = walls.at(compression.loading_plate());
  def.bottom_plate = walls.at(compression.bottom_plate());
  def.loading_stage = loading_stage(c);
  return def;
}

// Converts a case validate_case accepted, so every name it looks up exists.
template <int Dim>
class Converter {
 public:
  Converter(const proto::Case& c, const CaseSource& source, const ResourceLimits& limits)
      : case_(c), source_(source), limits_(limits) {}

  CaseDefinitionT<Dim> run() {
    CaseDefinitionT<Dim> def;
    def.name = case_.name();
    def.description = case_.description();
    // Not default_world_def(): its stand-in material and default contact
    // model would shift the case's material ids and cover pairs the case left out.
    def.world = WorldDefT<Dim>{};
    add_materials(def.world);
    add_contact_models(def.world);
    add_particles(def.world);
    add_walls(def.world);
    def.world.damping = to_damping(case_.damping());
    def.world.gravity = to_vec<Dim>(case_.gravity());
    if (case_.has_centripetal_gravity()) {
      def.world.centripetal_gravity = to_centripetal<Dim>(case_.centripetal_gravity());
    }
    if (case_.has_periodic()) {
      const proto::Periodic& p = case_.periodic();
      read_fields(p, def.world.periodic);  // its bounds (case_rules.h)
      def.world.periodic.axes[0] = p.x();
      def.world.periodic.axes[1] = p.y();
      if constexpr (Dim == 3) def.world.periodic.axes[2] = p.z();
    }
    if (case_.planar_particle() == proto::Case::SPHERE) def.world.planar_particle = PlanarParticle::kSphere;
    // proto3 cannot tell an unset number from 0, so 0 keeps the engine's default.
    if (case_.time_step().fraction() > 0) def.world.time_step_fraction = case_.time_step().fraction();
    def.world.fixed_time_step = case_.time_step().fixed();
    def.world.contact_tolerance = case_.numerics().contact_tolerance();
    check_contact_tolerance(def.world);
    def.world.threads = static_cast<int>(case_.numerics().threads());
    def.world.energy_budget = case_.output().energy_budget();
    if (case_.has_box_control()) def.world.box_control = to_box_control<Dim>(case_.box_control(), walls_);
    add_stages(def.stages);
    add_output(def.output, def.world.particles.size());
    return def;
  }

 private:
  // Validation could not read the particle files' radii; the particles
  // are all known here. A case without files was checked there.
  void check_contact_tolerance(const WorldDefT<Dim>& world) const {
    if (std::ranges::none_of(case_.particles(), [](const auto& source) { return source.has_csv_file(); })) return;
    double largest = 0.0;
    for (const ParticleDefT<Dim>& particle : world.particles) {
      double radius = particle.radius;  // a shaped particle's is set by the engine from its shape
      if constexpr (Dim == 2) {
        if (particle.shape.superquadric()) radius = std::max(particle.shape.a, particle.shape.b);
      } else {
        if (particle.shape.ellipsoid()) radius = particle.shape.axes.maxCoeff();
      }
      largest = std::max(largest, radius);
    }
    if (const auto problem = contact_tolerance_problem(world.contact_tolerance, largest)) {
      throw CaseError(describe_problem(source_, "numerics.contact_tolerance", *problem));
    }
  }

  void add_materials(WorldDefT<Dim>& world) {
    for (int i = 0; i < case_.material_size(); ++i) {
      const proto::Material& material = case_.material(i);
      MaterialDef def;
      read_fields(material, def);  // a wall material's density left out keeps the default (case_rules.h)
      world.materials.push_back(def);
      materials_.emplace(material.name(), i);
    }
  }

  void add_contact_models(WorldDefT<Dim>& world) {
    for (const proto::ContactModel& model : case_.contact_model()) {
      ContactModelDef def;
      if (model.materials_size() > 0) {
        def.material_a = materials_.at(model.materials(0));
        def.material_b = materials_.at(model.materials(model.materials_size() - 1));
      }
      // Validation has named a model without a law, or with one the engine lacks.
      const CaseLaw law = case_law(model);
      if (law.law) def.law = *law.law;
      if (law.parameters != nullptr) set_law_parameters(*law.parameters, def);
      read_fields(model, def);  // restitution, friction, cohesion, rolling (case_rules.h)
      world.contact_models.push_back(def);
    }
  }

  void add_particles(WorldDefT<Dim>& world) {
    for (int i = 0; i < case_.particles_size(); ++i) {
      const proto::ParticleSource& source = case_.particles(i);
      const std::string path = indexed("particles", i) + '.' + source_field(source);
      std::vector<ParticleDefT<Dim>> particles;
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
          case proto::ParticleSource::kCsvFile:
            particles = read_file(source.csv_file());
            break;
          case proto::ParticleSource::SOURCE_NOT_SET:
            break;
        }
      } catch (const DefinitionError& error) {
        throw CaseError(describe_problem(source_, path, error.what()));
      } catch (const CaseError& error) {
        // The particle file's own problems, "FILE:LINE: ...", each under the source that names the file.
        std::vector<std::string> problems;
        for (const std::string& problem : error.problems())
          problems.push_back(describe_problem(source_, path, problem));
        throw CaseError(std::move(problems));
      }
      world.particles.insert(world.particles.end(), particles.begin(), particles.end());
      // Validation could not count the particle files' lines.
      if (const auto problem = particle_count_problem(world.particles.size(), limits_)) {
        throw CaseError(describe_problem(source_, "particles", *problem + " (counting " + path + ")"));
      }
    }
  }

  static std::string source_field(const proto::ParticleSource& source) {
    const auto* field = source.GetDescriptor()->FindFieldByNumber(source.source_case());
    return field != nullptr ? field->name() : std::string("source");
  }

  ParticleDefT<Dim> to_particle(const proto::Particle& particle) const {
    ParticleDefT<Dim> def;
    read_fields(particle, def);  // its position, radius and velocity (case_rules.h)
    def.material = materials_.at(particle.material());
    def.angular_velocity = to_spin<Dim>(particle.angular_velocity(), particle.angular_velocity_3d());
    def.shape = to_shape<Dim>(particle);
    return def;
  }

  LatticeDefT<Dim> to_lattice(const proto::Lattice& lattice) const {
    LatticeDefT<Dim> def;
    read_fields(lattice, def);  // its numbers (case_rules.h)
    def.material = materials_.at(lattice.material());
    def.spacing = lattice.spacing() > 0 ? lattice.spacing() : 2 * lattice.radius();
    def.arrangement = lattice.arrangement() == proto::LATTICE_HEXAGONAL ? LatticeArrangement::kHexagonal
                                                                        : LatticeArrangement::kSquare;
    return def;
  }

  RandomPackingDefT<Dim> to_random_packing(const proto::RandomPacking& packing) const {
    RandomPackingDefT<Dim> def;
    read_fields(packing, def);  // its box, seed and dense generation (case_rules.h)
    def.material = materials_.at(packing.material());
    for (const proto::SizeClass& size : packing.size()) {
      def.sizes.push_back({size.radius(), static_cast<int>(size.count()), to_shape<Dim>(size)});
    }
    // Unset, the engine's default - but no more than the limit allows: a
    // limit below the default (a small server, the fuzz targets) bounds the
    // work of a packing that nearly cannot fit whether or not the case asks.
    def.max_attempts = packing.max_attempts() > 0
                           ? static_cast<int>(packing.max_attempts())
                           : static_cast<int>(std::min<std::uint64_t>(static_cast<std::uint64_t>(def.max_attempts),
                                                                      limits_.max_packing_attempts));
    def.stopped = limits_.stop_packing;
    return def;
  }

  // A relative path starts from the case file's directory; an absolute one stays.
  std::vector<ParticleDefT<Dim>> read_file(const proto::ParticleFile& file) const {
    std::filesystem::path path = source_.directory / file.path();
    if (source_.files) {
      try {
        path = source_.files->readable(file.path(), source_.directory);
      } catch (const FileAccessError& error) {
        throw CaseError(error.what());
      }
    }
    // A server reads it for a client, who may not read it: its errors quote nothing of it.
    std::vector<ParticleDefT<Dim>> particles =
        read_particle_file<Dim>(path, source_.files ? Excerpts::kHidden : Excerpts::kShown);
    const MaterialId material = materials_.at(file.material());
    const Vec<Dim> offset = to_vec<Dim>(file.offset());
    for (ParticleDefT<Dim>& particle : particles) {
      particle.material = material;
      particle.position += offset;
    }
    return particles;
  }

  void add_walls(WorldDefT<Dim>& world) {
    for (int i = 0; i < case_.wall_size(); ++i) {
      const proto::Wall& wall = case_.wall(i);
      WallDefT<Dim> def;
      read_fields(wall, def);  // its name, point and extents (case_rules.h)
      if constexpr (Dim == 2) {
        if (wall.orientation_case() == proto::Wall::kAngleDeg) {
          const double angle = wall.angle_deg() * std::numbers::pi / 180.0;
          def.direction = {std::cos(angle), std::sin(angle)};
        } else {
          def.direction = to_vec<2>(wall.direction()).normalized();
        }
      } else {
        def.direction = to_vec<3>(wall.direction()).normalized();
        // Validation accepts sides perpendicular to a few digits; the
        // engine wants them orthonormal, so the rest of v along u goes.
        const Vec3 v = to_vec<3>(wall.direction2());
        def.direction2 = (v - v.dot(def.direction) * def.direction).normalized();
      }
      if constexpr (Dim == 3) {
        if (wall.face_size() > 0) add_faces(wall, def);
      }
      def.material = materials_.at(wall.material());
      def.motion = to_motion<Dim>(wall.motion());
      world.walls.push_back(def);
      walls_.emplace(wall.name(), i);
    }
  }

  // A wall of triangle faces (Miyata et al. 2002, 2.4(2)): the faces, and
  // their extent along the wall's sides in place of the rectangle's.
  static void add_faces(const proto::Wall& wall, WallDefT<3>& def) {
    def.h1 = def.k1 = std::numeric_limits<double>::infinity();
    def.h2 = def.k2 = -std::numeric_limits<double>::infinity();
    for (const proto::Triangle& face : wall.face()) {
      const std::array<Vec3, 3> corners = {to_vec<3>(face.i()), to_vec<3>(face.j()), to_vec<3>(face.k())};
      for (const Vec3& corner : corners) {
        const Vec3 d = corner - def.point;
        def.h1 = std::min(def.h1, d.dot(def.direction));
        def.h2 = std::max(def.h2, d.dot(def.direction));
        def.k1 = std::min(def.k1, d.dot(def.direction2));
        def.k2 = std::max(def.k2, d.dot(def.direction2));
      }
      def.triangles.push_back(corners);
    }
  }

  void add_stages(std::vector<StageDefT<Dim>>& stages) const {
    for (const proto::Stage& stage : case_.stage()) {
      StageDefT<Dim> def;
      def.name = stage.name();
      for (const proto::WallCommand& command : stage.wall()) {
        def.wall_motions.emplace_back(walls_.at(command.wall()), to_motion<Dim>(command.motion()));
      }
      if (stage.has_damping()) def.damping = to_damping(stage.damping());
      if (stage.has_body_force()) def.body_force = to_body_force<Dim>(stage.body_force());
      if (stage.has_time_step()) {
        const proto::TimeStep& step = stage.time_step();
        def.time_step = step.fixed() > 0 ? TimeStepSetting{0.0, step.fixed()} : TimeStepSetting{step.fraction(), 0.0};
      }
      for (const proto::MaterialFriction& friction : stage.friction()) {
        def.frictions.emplace_back(materials_.at(friction.material()), friction.friction());
      }
      if (stage.has_trim()) read_fields(stage.trim(), def.trim.emplace());  // a smooth cut may leave out the wavelength
      if (stage.has_place_wall()) {
        def.place_wall = PlaceWallDef{walls_.at(stage.place_wall().wall()), stage.place_wall().clearance()};
      }
      for (const std::string& wall : stage.remove_wall()) def.remove_walls.push_back(walls_.at(wall));
      if (stage.has_box_control()) def.box_control = to_box_control<Dim>(stage.box_control(), walls_);
      def.release_box_control = stage.release_box_control();
      def.cycles = stage.cycles();
      if (stage.has_until()) def.until = to_stop_conditions<Dim>(stage.until(), walls_, case_.output());
      stages.push_back(def);
    }
  }

  // Validation could not check probe ids against particle files it does
  // not read; the particles are all known here.
  void add_output(OutputSettings& output, std::size_t particle_count) const {
    if (case_.output().interval() > 0) output.interval = case_.output().interval();
    output.contacts_file = !case_.output().no_contacts_file();
    output.vtk_interval = case_.output().vtk_interval();
    for (const proto::MeasurementRegion& region : case_.output().region()) output.regions.push_back(to_region(region));
    if (case_.output().has_compression()) output.compression = to_compression(case_, walls_);
    std::vector<std::string> problems;
    for (int i = 0; i < case_.output().probe_size(); ++i) {
      const proto::ContactProbe& probe = case_.output().probe(i);
      for (const auto& [field, id] : {std::pair{".first", probe.first()}, std::pair{".second", probe.second()}}) {
        if (id >= particle_count) {
          problems.push_back(
              describe_problem(source_, indexed("output.probe", i) + field, no_particle_with_id(id, particle_count)));
        }
      }
      // Both ids were checked against the particle count above.
      output.probes.push_back({probe.name(), ParticleId{static_cast<std::int32_t>(probe.first())},
                               ParticleId{static_cast<std::int32_t>(probe.second())}});
    }
    if (!problems.empty()) throw CaseError(std::move(problems));
  }

  const proto::Case& case_;
  const CaseSource& source_;
  const ResourceLimits& limits_;
  std::map<std::string, MaterialId, std::less<>> materials_;
  WallIndex walls_;
};

}  // namespace

int case_dimension(const proto::Case& message) { return message.dimension() == 3 ? 3 : 2; }

template <int Dim>
CaseDefinitionT<Dim> convert_case(const proto::Case& message, const CaseSource& source, const ResourceLimits& limits) {
  validate_case(message, source, limits);
  if (const int declared = case_dimension(message); declared != Dim) {
    throw CaseError(describe_problem(
        source, "dimension",
        "the case is " + std::to_string(declared) + "D, but a " + std::to_string(Dim) + "D case is expected here"));
  }
  return Converter<Dim>(message, source, limits).run();
}

template CaseDefinitionT<2> convert_case<2>(const proto::Case&, const CaseSource&, const ResourceLimits&);
template CaseDefinitionT<3> convert_case<3>(const proto::Case&, const CaseSource&, const ResourceLimits&);

AnyCaseDefinition convert_any_case(const proto::Case& message, const CaseSource& source, const ResourceLimits& limits) {
  if (case_dimension(message) == 3) return convert_case<3>(message, source, limits);
  return convert_case<2>(message, source, limits);
}

}  // namespace dem::io
