#include "dem/io/case_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string_view>
#include <utility>

#include "field_path.h"
#include "format_number.h"
#include "problem_list.h"

namespace dem::io {
namespace {

std::string quoted(std::string_view name) { return '"' + std::string(name) + '"'; }

// A pair of material indices in the order a contact model's key uses.
std::pair<int, int> unordered_pair(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

std::string point(const proto::Vector2& v) { return '(' + format_number(v.x()) + ", " + format_number(v.y()) + ')'; }

// Names a case can refer to (materials, walls), each with the index of its
// first definition.
using NameIndex = std::map<std::string, int, std::less<>>;

// "(the case defines "a", "b")", so an unknown name comes with the known ones.
std::string defined_names(const NameIndex& names) {
  if (names.empty()) return "(the case defines none)";
  std::string text = "(the case defines ";
  for (const auto& [name, index] : names) {
    if (text.back() != ' ') text += ", ";
    text += quoted(name);
  }
  return text + ')';
}

// One pass over a case. Cross-references (materials, walls, particle ids) are
// resolved against the definitions as they are read.
class CaseChecker {
 public:
  explicit CaseChecker(const proto::Case& c) : case_(c) { note_material_uses(); }

  std::vector<CaseProblem> run() {
    check_materials();
    check_contact_models();
    check_particle_sources();
    check_walls();
    check_damping("damping", case_.damping());
    check_time_step();
    problems_.finite("gravity", case_.gravity());
    check_stages();
    check_output();
    check_numerics();
    return problems_.take();
  }

 private:
  // Which materials particles and walls are made of, needed before the
  // materials themselves are checked (density) and for the contact pairs.
  void note_material_uses() {
    for (const proto::ParticleSource& source : case_.particles()) {
      switch (source.source_case()) {
        case proto::ParticleSource::kParticle:
          particle_materials_.insert(source.particle().material());
          break;
        case proto::ParticleSource::kLattice:
          particle_materials_.insert(source.lattice().material());
          break;
        case proto::ParticleSource::kRandomPacking:
          particle_materials_.insert(source.random_packing().material());
          break;
        case proto::ParticleSource::SOURCE_NOT_SET:
          break;
      }
    }
    for (const proto::Wall& wall : case_.wall()) wall_materials_.insert(wall.material());
  }

  void check_materials() {
    for (int i = 0; i < case_.material_size(); ++i) {
      const proto::Material& material = case_.material(i);
      const std::string path = indexed("material", i);
      if (material.name().empty()) {
        problems_.add(path + ".name",
                      "must not be empty (particles, walls and contact models refer to materials by name)");
      } else if (const auto [first, inserted] = materials_.emplace(material.name(), i); !inserted) {
        problems_.add(path + ".name", "duplicate material name " + quoted(material.name()) + " (" +
                                          indexed("material", first->second) + " has it too)");
      }
      if (problems_.non_negative(path + ".density", material.density()) && material.density() == 0 &&
          particle_materials_.contains(material.name())) {
        problems_.add(path + ".density", "must be > 0 for a material particles are made of (got 0)");
      }
      problems_.non_negative(path + ".friction", material.friction());
      problems_.non_negative(path + ".cohesion", material.cohesion());
    }
  }

  // Returns the material's index, or -1 after reporting why there is none.
  int material_reference(const std::string& path, const std::string& name) {
    if (name.empty()) {
      problems_.add(path, "must name a material " + defined_names(materials_));
      return -1;
    }
    const auto found = materials_.find(name);
    if (found == materials_.end()) {
      problems_.add(path, "unknown material " + quoted(name) + ' ' + defined_names(materials_));
      return -1;
    }
    return found->second;
  }

  void check_contact_models() {
    // Unordered material pairs (by index) to the model that covers them;
    // {-1, -1} is the default model.
    std::map<std::pair<int, int>, int> covered;
    for (int i = 0; i < case_.contact_model_size(); ++i) {
      const proto::ContactModel& model = case_.contact_model(i);
      const std::string path = indexed("contact_model", i);
      const int named = model.materials_size();
      if (named > 2) {
        problems_.add(path + ".materials", "names " + std::to_string(named) +
                                               " materials; name none (the default law), one (a material with itself) "
                                               "or two (a mixed pair)");
      }
      std::vector<int> ids;
      for (int j = 0; j < named; ++j) {
        ids.push_back(material_reference(indexed(path + ".materials", j), model.materials(j)));
      }
      if (model.law_case() == proto::ContactModel::kLinear) {
        problems_.positive(path + ".linear.normal_stiffness", model.linear().normal_stiffness());
        problems_.non_negative(path + ".linear.shear_stiffness", model.linear().shear_stiffness());
      } else {
        problems_.add(path, "has no law; set linear { normal_stiffness: ... shear_stiffness: ... }");
      }
      if (model.has_friction()) problems_.non_negative(path + ".friction", model.friction());
      if (model.has_cohesion()) problems_.non_negative(path + ".cohesion", model.cohesion());

      if (named > 2 || std::ranges::count(ids, -1) > 0) continue;
      const std::pair<int, int> pair = named == 0   ? std::pair{-1, -1}
                                       : named == 1 ? std::pair{ids[0], ids[0]}
                                                    : unordered_pair(ids[0], ids[1]);
      const auto [first, inserted] = covered.emplace(pair, i);
      if (inserted) continue;
      if (named == 0) {
        problems_.add(path, "is a second default model (one naming no materials); " +
                                indexed("contact_model", first->second) + " is the first");
      } else {
        problems_.add(path + ".materials", "a second contact model for " + quoted(model.materials(0)) + " and " +
                                               quoted(model.materials(named - 1)) + "; " +
                                               indexed("contact_model", first->second) + " already covers the pair");
      }
    }
    if (!covered.contains({-1, -1})) check_pairs_covered(covered);
  }

  // Without a default model, every pair of materials that can touch needs
  // its own: particle with particle (including the same material) and
  // particle with wall. Walls never touch each other.
  void check_pairs_covered(const std::map<std::pair<int, int>, int>& covered) {
    std::set<int> particle_ids;
    std::set<int> wall_ids;
    for (const auto& name : particle_materials_) {
      if (const auto found = materials_.find(name); found != materials_.end()) particle_ids.insert(found->second);
    }
    for (const auto& name : wall_materials_) {
      if (const auto found = materials_.find(name); found != materials_.end()) wall_ids.insert(found->second);
    }
    std::set<std::pair<int, int>> touching;
    for (const int a : particle_ids) {
      for (const int b : particle_ids) touching.insert(unordered_pair(a, b));
      for (const int w : wall_ids) touching.insert(unordered_pair(a, w));
    }
    for (const auto& [a, b] : touching) {
      if (covered.contains({a, b})) continue;
      const std::string& name_a = case_.material(a).name();
      const std::string& name_b = case_.material(b).name();
      problems_.add("contact_model", "no contact model for " +
                                         (a == b ? "material " + quoted(name_a) + " with itself"
                                                 : "materials " + quoted(name_a) + " and " + quoted(name_b)) +
                                         ", which can touch; add one naming " + (a == b ? "it" : "both") +
                                         ", or a default model naming no materials");
    }
  }

  void check_particle_sources() {
    if (case_.particles_size() == 0) {
      problems_.add("particles", "the case defines no particles; add a particle, lattice or random_packing source");
      return;
    }
    for (int i = 0; i < case_.particles_size(); ++i) {
      const proto::ParticleSource& source = case_.particles(i);
      const std::string path = indexed("particles", i);
      switch (source.source_case()) {
        case proto::ParticleSource::kParticle:
          check_particle(path + ".particle", source.particle());
          break;
        case proto::ParticleSource::kLattice:
          check_lattice(path + ".lattice", source.lattice());
          break;
        case proto::ParticleSource::kRandomPacking:
          check_random_packing(path + ".random_packing", source.random_packing());
          break;
        case proto::ParticleSource::SOURCE_NOT_SET:
          problems_.add(path, "is empty; set particle, lattice or random_packing");
          break;
      }
    }
    if (particle_count_ > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max())) {
      problems_.add("particles", "define " + std::to_string(particle_count_) +
                                     " particles, more than particle ids can number (2147483647)");
    }
  }

  void check_particle(const std::string& path, const proto::Particle& particle) {
    problems_.finite(path + ".position", particle.position());
    problems_.positive(path + ".radius", particle.radius());
    material_reference(path + ".material", particle.material());
    problems_.finite(path + ".velocity", particle.velocity());
    problems_.finite(path + ".angular_velocity", particle.angular_velocity());
    particle_count_ += 1;
  }

  void check_lattice(const std::string& path, const proto::Lattice& lattice) {
    material_reference(path + ".material", lattice.material());
    const bool radius_ok = problems_.positive(path + ".radius", lattice.radius());
    problems_.finite(path + ".origin", lattice.origin());
    if (lattice.columns() == 0) problems_.add(path + ".columns", "must be > 0");
    if (lattice.rows() == 0) problems_.add(path + ".rows", "must be > 0");
    // 0 means the default, touching neighbours at 2 * radius.
    if (problems_.non_negative(path + ".spacing", lattice.spacing()) && radius_ok && lattice.spacing() > 0 &&
        lattice.spacing() < 2 * lattice.radius()) {
      problems_.add(path + ".spacing", "must be at least 2 * radius (" + format_number(2 * lattice.radius()) +
                                           ") so neighbours do not overlap (got " + format_number(lattice.spacing()) +
                                           "); leave it out for touching neighbours");
    }
    particle_count_ += std::uint64_t{lattice.columns()} * lattice.rows();
  }

  void check_random_packing(const std::string& path, const proto::RandomPacking& packing) {
    material_reference(path + ".material", packing.material());
    const bool min_ok = problems_.finite(path + ".min", packing.min());
    const bool max_ok = problems_.finite(path + ".max", packing.max());
    const double width = packing.max().x() - packing.min().x();
    const double height = packing.max().y() - packing.min().y();
    const bool box_ok = min_ok && max_ok && width > 0 && height > 0;
    if (min_ok && max_ok && !box_ok) {
      problems_.add(path + ".max", "must lie above and to the right of min (min " + point(packing.min()) + ", max " +
                                       point(packing.max()) + ")");
    }
    if (packing.size_size() == 0) {
      problems_.add(path + ".size", "lists no size classes; add at least one size { radius: ... count: ... }");
    }
    for (int j = 0; j < packing.size_size(); ++j) {
      const proto::SizeClass& size = packing.size(j);
      const std::string size_path = indexed(path + ".size", j);
      if (problems_.positive(size_path + ".radius", size.radius()) && box_ok &&
          2 * size.radius() > std::min(width, height)) {
        problems_.add(size_path + ".radius", "discs of radius " + format_number(size.radius()) +
                                                 " do not fit in the box (" + format_number(width) + " x " +
                                                 format_number(height) + ")");
      }
      if (size.count() == 0) problems_.add(size_path + ".count", "must be > 0");
      particle_count_ += size.count();
    }
    if (packing.max_attempts() > static_cast<std::uint32_t>(std::numeric_limits<int>::max())) {
      problems_.add(path + ".max_attempts", "must be at most " + std::to_string(std::numeric_limits<int>::max()));
    }
  }

  void check_walls() {
    for (int i = 0; i < case_.wall_size(); ++i) {
      const proto::Wall& wall = case_.wall(i);
      const std::string path = indexed("wall", i);
      if (wall.name().empty()) {
        problems_.add(path + ".name", "must not be empty (stages and outputs refer to walls by name)");
      } else if (const auto [first, inserted] = walls_.emplace(wall.name(), i); !inserted) {
        problems_.add(path + ".name", "duplicate wall name " + quoted(wall.name()) + " (" +
                                          indexed("wall", first->second) + " has it too)");
      }
      problems_.finite(path + ".point", wall.point());
      switch (wall.orientation_case()) {
        case proto::Wall::kDirection:
          if (problems_.finite(path + ".direction", wall.direction()) &&
              std::hypot(wall.direction().x(), wall.direction().y()) == 0) {
            problems_.add(path + ".direction", "must not be zero-length");
          }
          break;
        case proto::Wall::kAngleDeg:
          problems_.finite(path + ".angle_deg", wall.angle_deg());
          break;
        case proto::Wall::ORIENTATION_NOT_SET:
          problems_.add(path, "has no orientation; set direction { x: ... y: ... } or angle_deg");
          break;
      }
      const bool h1_ok = problems_.finite(path + ".h1", wall.h1());
      if (problems_.finite(path + ".h2", wall.h2()) && h1_ok && wall.h2() <= wall.h1()) {
        problems_.add(path + ".h2",
                      "must be greater than h1 (" + format_number(wall.h2()) + " <= " + format_number(wall.h1()) + ")");
      }
      material_reference(path + ".material", wall.material());
      check_motion(path + ".motion", wall.motion());
    }
  }

  void check_motion(const std::string& path, const proto::WallMotion& motion) {
    problems_.finite(path + ".velocity", motion.velocity());
    problems_.finite(path + ".angular_velocity", motion.angular_velocity());
    if (!motion.has_servo()) return;
    problems_.finite(path + ".servo.target_force", motion.servo().target_force());
    problems_.positive(path + ".servo.gain", motion.servo().gain());
    problems_.positive(path + ".servo.max_speed", motion.servo().max_speed());
    if (motion.velocity().x() != 0 || motion.velocity().y() != 0 || motion.angular_velocity() != 0) {
      problems_.add(path, "sets both servo and velocity/angular_velocity; the servo replaces them, so drop one");
    }
  }

  void check_damping(const std::string& path, const proto::Damping& damping) {
    problems_.non_negative(path + ".contact_beta", damping.contact_beta());
    problems_.non_negative(path + ".global_alpha", damping.global_alpha());
  }

  void check_time_step() {
    const double fraction = case_.time_step().fraction();
    // 0 means the default, 0.1.
    if (problems_.finite("time_step.fraction", fraction) && fraction != 0 && !(fraction > 0 && fraction <= 1)) {
      problems_.add("time_step.fraction",
                    "must be in (0, 1] (got " + format_number(fraction) + "); leave it out for the default 0.1");
    }
    problems_.non_negative("time_step.fixed", case_.time_step().fixed());
  }

  void check_stages() {
    // Which walls are servo-controlled as the programme goes, for servo_tolerance.
    std::vector<bool> servo(case_.wall_size());
    for (int i = 0; i < case_.wall_size(); ++i) servo[i] = case_.wall(i).motion().has_servo();

    for (int i = 0; i < case_.stage_size(); ++i) {
      const proto::Stage& stage = case_.stage(i);
      const std::string path = indexed("stage", i);
      std::map<std::string, int, std::less<>> commanded;
      for (int j = 0; j < stage.wall_size(); ++j) {
        const proto::WallCommand& command = stage.wall(j);
        const std::string command_path = indexed(path + ".wall", j);
        const auto wall = walls_.find(command.wall());
        if (command.wall().empty()) {
          problems_.add(command_path + ".wall", "must name a wall " + defined_names(walls_));
        } else if (wall == walls_.end()) {
          problems_.add(command_path + ".wall", "unknown wall " + quoted(command.wall()) + ' ' + defined_names(walls_));
        } else if (const auto [first, inserted] = commanded.emplace(command.wall(), j); !inserted) {
          problems_.add(command_path + ".wall", "wall " + quoted(command.wall()) + " is already commanded by " +
                                                    indexed(path + ".wall", first->second));
        } else {
          servo[wall->second] = command.motion().has_servo();
        }
        check_motion(command_path + ".motion", command.motion());
      }
      if (stage.cycles() == 0) {
        problems_.add(path + ".cycles", "must be > 0 (the stage's length, or its cap when until is set)");
      }
      if (stage.has_damping()) check_damping(path + ".damping", stage.damping());
      if (stage.has_until()) {
        check_until(path, stage, std::ranges::count(servo, true) > 0);
      }
    }
  }

  void check_until(const std::string& stage_path, const proto::Stage& stage, bool any_servo) {
    const proto::Until& until = stage.until();
    const std::string path = stage_path + ".until";
    if (!until.has_kinetic_energy_below() && !until.has_out_of_balance_below() && !until.has_servo_tolerance()) {
      problems_.add(path,
                    "sets no stop condition; set kinetic_energy_below, out_of_balance_below or "
                    "servo_tolerance, or leave until out");
    }
    if (until.has_kinetic_energy_below()) {
      problems_.positive(path + ".kinetic_energy_below", until.kinetic_energy_below());
    }
    if (until.has_out_of_balance_below()) {
      problems_.positive(path + ".out_of_balance_below", until.out_of_balance_below());
    }
    if (until.has_servo_tolerance() && problems_.positive(path + ".servo_tolerance", until.servo_tolerance()) &&
        !any_servo) {
      problems_.add(path + ".servo_tolerance", "no wall is servo-controlled during this stage");
    }
    if (stage.cycles() > 0 && until.min_cycles() > stage.cycles()) {
      problems_.add(path + ".min_cycles", "must not exceed the stage's cycles (" + std::to_string(until.min_cycles()) +
                                              " > " + std::to_string(stage.cycles()) + ")");
    }
  }

  void check_output() {
    const bool count_known = particle_count_ <= static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max());
    std::map<std::string, int, std::less<>> names;
    for (int i = 0; i < case_.output().probe_size(); ++i) {
      const proto::ContactProbe& probe = case_.output().probe(i);
      const std::string path = indexed("output.probe", i);
      if (probe.name().empty()) {
        problems_.add(path + ".name", "must not be empty (it labels the probe's rows in probes.csv)");
      } else if (const auto [first, inserted] = names.emplace(probe.name(), i); !inserted) {
        problems_.add(path + ".name", "duplicate probe name " + quoted(probe.name()) + " (" +
                                          indexed("output.probe", first->second) + " has it too)");
      }
      const auto check_id = [&](const std::string& id_path, std::uint32_t id) {
        if (!count_known || id < particle_count_) return;
        problems_.add(id_path, "no particle with id " + std::to_string(id) + " (the case defines " +
                                   std::to_string(particle_count_) + " particles" +
                                   (particle_count_ > 0 ? ", ids 0 to " + std::to_string(particle_count_ - 1) : "") +
                                   ")");
      };
      check_id(path + ".first", probe.first());
      check_id(path + ".second", probe.second());
      if (probe.first() == probe.second()) {
        problems_.add(path + ".second", "must differ from first (both are " + std::to_string(probe.first()) + ")");
      }
    }
  }

  void check_numerics() {
    problems_.non_negative("numerics.contact_tolerance", case_.numerics().contact_tolerance());
    if (case_.numerics().threads() > static_cast<std::uint32_t>(std::numeric_limits<int>::max())) {
      problems_.add("numerics.threads", "must be at most " + std::to_string(std::numeric_limits<int>::max()));
    }
  }

  const proto::Case& case_;
  ProblemList problems_;
  NameIndex materials_;
  NameIndex walls_;
  std::set<std::string> particle_materials_;
  std::set<std::string> wall_materials_;
  std::uint64_t particle_count_ = 0;
};

}  // namespace

std::vector<CaseProblem> find_case_problems(const proto::Case& message) { return CaseChecker(message).run(); }

void validate_case(const proto::Case& message, const CaseSource& source) {
  const std::vector<CaseProblem> problems = find_case_problems(message);
  if (problems.empty()) return;
  std::vector<std::string> lines;
  lines.reserve(problems.size());
  for (const CaseProblem& problem : problems) {
    lines.push_back(describe_problem(source, problem.path, problem.message));
  }
  throw CaseError(std::move(lines));
}

}  // namespace dem::io
