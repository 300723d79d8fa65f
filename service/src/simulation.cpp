#include "dem/service/simulation.h"

#include <cmath>
#include <filesystem>
#include <variant>

#include "dem/error.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/checkpoint_store.h"
#include "dem/io/snapshot_file.h"
#include "dem/io/world_checks.h"
#include "dem/service/command_error.h"
#include "dem/service/world_snapshots.h"
#include "dem/service/world_steering.h"
#include "dem/service/world_view.h"
#include "format_value.h"

namespace dem::service {

using protocol::ReplyStatus;

namespace {

bool finite(const protocol::Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void require(bool condition, const std::string& message) {
  if (!condition) throw CommandError(ReplyStatus::kBadRequest, message);
}

std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += (text.empty() ? "" : "\n") + line;
  return text;
}

// A case's world built, with what the reply says about it.
template <int Dim>
Simulation::Prepared prepared_case(const io::CaseDefinitionT<Dim>& definition, const io::CaseSource& case_source,
                                   const std::string& source) {
  Simulation::Prepared prepared;
  BasicWorld<Dim> built(definition.world);
  io::check_built_world(built, definition.stages, case_source);
  prepared.world = std::make_unique<WorldSession>(std::move(built), definition.output.regions);
  prepared.programme = CaseProgramme(definition.stages);
  prepared.output = definition.output;
  prepared.case_name = definition.name.empty() ? std::string("unnamed") : definition.name;
  prepared.description = definition.description;
  prepared.contact_models = definition.world.contact_models;
  const WorldSession& world = *prepared.world;
  prepared.message = "loaded case " + prepared.case_name + " from " + source + ": " + std::to_string(Dim) + "D, " +
                     std::to_string(world.particle_count()) + " particles, " + std::to_string(wall_count(world)) +
                     " walls, time step " + format_value(world.time_step()) + " s";
  return prepared;
}

}  // namespace

Simulation::Simulation(std::optional<int> threads, io::ResourceLimits limits, std::uint64_t max_query_contacts,
                       std::shared_ptr<const io::FileAccess> files)
    : threads_(threads),
      limits_(limits),
      files_(files ? std::move(files) : std::make_shared<const io::FileAccess>(std::vector<std::filesystem::path>{})),
      max_query_contacts_(max_query_contacts) {}

std::string Simulation::install(Prepared prepared) {
  if (threads_) on_world(*prepared.world, [&](auto& world) { world.set_threads(*threads_); });
  world_ = std::move(prepared.world);
  case_name_ = std::move(prepared.case_name);
  description_ = std::move(prepared.description);
  contact_models_ = std::move(prepared.contact_models);
  programme_ = std::move(prepared.programme);
  output_ = std::move(prepared.output);
  digest_ = prepared.digest;
  return prepared.message;
}

Simulation::Prepared Simulation::Preparer::prepare_case(const protocol::LoadCaseArgs& args) const {
  const int sources = static_cast<int>(!args.path.empty()) + static_cast<int>(!args.text.empty()) +
                      static_cast<int>(!args.binary.empty());
  require(sources == 1,
          "load_case takes exactly one of a path, a text or a binary case (got " + std::to_string(sources) + ")");
  std::string source;
  try {
    io::LoadedCase loaded;
    if (!args.path.empty()) {
      source = args.path;
      if (files_->roots().empty()) {
        throw CommandError(ReplyStatus::kRefused,
                           "load_case by a path on the server is off: this server reads no files for clients. Start "
                           "dem_server with --read-dir DIR (repeatable) to let it read cases, and the particle files "
                           "they name, from DIR; or send the case itself (demctl load FILE sends the file's text)");
      }
      std::filesystem::path path;
      try {
        path = files_->readable(args.path);
      } catch (const io::FileAccessError& error) {
        throw CommandError(ReplyStatus::kNotFound, "no case file on the server: " + std::string(error.what()));
      }
      loaded = io::load_case_file(path, io::Excerpts::kHidden);
      loaded.source.name = args.path;
    } else if (!args.text.empty()) {
      source = args.source_name.empty() ? "<text>" : args.source_name;
      loaded = io::parse_case_text(args.text, source);
    } else {
      source = args.source_name.empty() ? "<binary>" : args.source_name;
      loaded = io::parse_case_binary(args.binary, source);
    }
    loaded.source.files = files_;
    const io::AnyCaseDefinition definition = io::convert_any_case(loaded.message, loaded.source, limits_);
    Prepared prepared = std::visit([&](const auto& d) { return prepared_case(d, loaded.source, source); }, definition);
    prepared.digest = !args.path.empty() ? io::file_digest(files_->readable(args.path))
                                         : io::bytes_digest(!args.text.empty() ? args.text : args.binary);
    return prepared;
  } catch (const io::CaseError& error) {
    throw CommandError(ReplyStatus::kInvalidCase, join(error.problems()));
  } catch (const DefinitionError& error) {
    throw CommandError(ReplyStatus::kInvalidCase, source + ": " + error.what());
  }
}

Simulation::Prepared Simulation::Preparer::prepare_snapshot(std::string_view bytes, const std::string& source) const {
  try {
    // The dimension the snapshot declares picks the engine.
    const proto::Snapshot message = io::parse_snapshot_message(bytes, source);
    const auto restore = [&](auto dimension) {
      constexpr int kDim = decltype(dimension)::value;
      io::SnapshotInfo info;
      WorldSnapshotT<kDim> snapshot;
      try {
        snapshot = io::snapshot_from_proto<kDim>(message, &info, limits_);
      } catch (const io::SnapshotError& error) {
        throw io::SnapshotError(source + ": " + error.what());
      }
      Prepared prepared;
      prepared.contact_models = snapshot.def.contact_models;
      prepared.world = std::make_unique<WorldSession>(BasicWorld<kDim>(snapshot));
      prepared.case_name = info.case_name;
      prepared.description = info.description;
      const WorldSession& world = *prepared.world;
      prepared.message = "loaded snapshot of " + prepared.case_name + " from " + source + " at cycle " +
                         std::to_string(world.cycle_count()) + ": " + std::to_string(kDim) + "D, " +
                         std::to_string(world.particle_count()) + " particles, " + std::to_string(wall_count(world)) +
                         " walls";
      return prepared;
    };
    if (message.dimension() == 3) return restore(std::integral_constant<int, 3>{});
    return restore(std::integral_constant<int, 2>{});
  } catch (const io::SnapshotError& error) {
    throw CommandError(ReplyStatus::kInvalidSnapshot, error.what());
  } catch (const DefinitionError& error) {
    throw CommandError(ReplyStatus::kInvalidSnapshot, source + ": " + error.what());
  }
}

void Simulation::drop() {
  world_.reset();
  programme_ = CaseProgramme();
  digest_.clear();
}

std::string Simulation::snapshot_bytes() const { return service::snapshot_bytes(world(), snapshot_info()); }

WallId Simulation::find_wall(const std::string& name, std::int32_t id) const {
  const WorldSession& w = world();
  std::string known;
  for (int i = 0; i < wall_count(w); ++i) known += (i == 0 ? "" : ", ") + wall_name(w, WallId{i});
  if (!name.empty()) {
    const WallId found = service::find_wall(w, name);
    if (found == kInvalidId) {
      throw CommandError(ReplyStatus::kNotFound, "no wall \"" + name + "\" (walls: " + known + ")");
    }
    return found;
  }
  if (id < 0 || id >= wall_count(w)) {
    throw CommandError(ReplyStatus::kNotFound, id < 0 ? "no wall given (walls: " + known + ")"
                                                      : "no wall with id " + std::to_string(id) + " (there are " +
                                                            std::to_string(wall_count(w)) + " walls: " + known + ")");
  }
  return WallId{id};
}

std::string Simulation::set_wall_velocity(const protocol::WallVelocityArgs& args) {
  const WallId wall = find_wall(args.wall, args.wall_id);
  require(finite(args.twist.linear) && finite(args.twist.angular), "the wall velocity must be finite");
  service::set_wall_velocity(world(), wall, args.twist.linear, args.twist.angular);
  const protocol::Vector3& v = args.twist.linear;
  const protocol::Vector3& w = args.twist.angular;
  return "wall " + wall_name(world(), wall) + " moves at (" + format_value(v.x) + ", " + format_value(v.y) +
         (dimension() == 3 ? ", " + format_value(v.z) + ") m/s, (" + format_value(w.x) + ", " + format_value(w.y) +
                                 ", " + format_value(w.z) + ")"
                           : ") m/s, " + format_value(w.z)) +
         " rad/s";
}

std::string Simulation::set_wall_servo(const protocol::WallServoArgs& args) {
  const WallId wall = find_wall(args.wall, args.wall_id);
  require(std::isfinite(args.target_stress), "the target stress must be finite");
  require(std::isfinite(args.gain) && args.gain >= 0.0, "the servo gain must be >= 0 (0: the server chooses)");
  require(std::isfinite(args.max_speed) && args.max_speed >= 0.0,
          "the servo's max speed must be >= 0 (0: the server chooses)");
  const double area = wall_area(world(), wall);
  const std::optional<ServoLimits> defaults = default_servo_limits(world(), wall, contact_models_);
  if ((args.gain == 0.0 || args.max_speed == 0.0) && !defaults) {
    throw CommandError(ReplyStatus::kBadRequest,
                       "give the servo's gain and max speed: the defaults need a linear contact law's stiffness");
  }
  ServoDef servo;
  servo.target_force = args.target_stress * area;
  // The wall moves at gain * (target - stress) = (gain / area) * (target force - force).
  servo.gain = args.gain > 0.0 ? args.gain / area : defaults->gain;
  servo.max_speed = args.max_speed > 0.0 ? args.max_speed : defaults->max_speed;
  try {
    service::set_wall_servo(world(), wall, servo);
  } catch (const DefinitionError& error) {
    throw CommandError(ReplyStatus::kBadRequest, error.what());
  }
  return "wall " + wall_name(world(), wall) + " servo-controlled to " + format_value(args.target_stress) +
         " Pa (gain " + format_value(servo.gain * area) + " m/(Pa s), at most " + format_value(servo.max_speed) +
         " m/s)";
}

namespace {

// Damping moves the critical step (the dashpots shorten it); a damping
// that would leave the step above it is refused, and stays as it was.
std::string set_damping_keeping_a_stable_step(WorldSession& w, const DampingDef& damping, const std::string& name) {
  const DampingDef before = service::damping(w);
  service::set_damping(w, damping);
  const double critical = critical_time_step(w);
  if (w.time_step() > critical * (1.0 + 1e-9)) {
    service::set_damping(w, before);
    throw CommandError(ReplyStatus::kBadRequest,
                       name + ": with it the critical step would be " + format_value(critical) +
                           " s, below the time step " + format_value(w.time_step()) +
                           " s: central differences would be unstable; set a smaller time_step_fraction first");
  }
  return "; time step " + format_value(w.time_step()) + " s, critical step " + format_value(critical) + " s";
}

// A fraction of the undamped critical step whose step the damping leaves
// above the critical one is refused, naming the largest that is not.
std::string set_stable_time_step_fraction(WorldSession& w, double fraction) {
  require(fraction > 0.0 && fraction <= 1.0, "time_step_fraction must be in (0, 1]");
  const double critical = critical_time_step(w);
  const double undamped = undamped_critical_time_step(w);
  const double step = fraction * undamped;
  require(step <= critical * (1.0 + 1e-9),
          "time_step_fraction: " + format_value(fraction) + " gives " + format_value(step) +
              " s, above the critical step " + format_value(critical) +
              " s with the damping: central differences would be unstable; use at most " +
              format_value(critical / undamped));
  service::set_time_step_fraction(w, fraction);
  return "time step now " + format_value(w.time_step()) + " s (" + format_value(fraction) +
         " of the undamped critical step; the critical step is " + format_value(critical) + " s)";
}

}  // namespace

std::string Simulation::set_parameter(const protocol::ParameterArgs& args) {
  WorldSession& w = world();
  const std::string& name = args.name;
  const bool vector_parameter = name == "gravity";
  require(vector_parameter ? finite(args.vector) : std::isfinite(args.value), name + ": the value must be finite");
  try {
    if (name == "contact_damping" || name == "global_damping") {
      require(args.value >= 0.0, name + " must be >= 0");
      DampingDef damping = service::damping(w);
      (name == "contact_damping" ? damping.contact_beta : damping.global_alpha) = args.value;
      const std::string step = set_damping_keeping_a_stable_step(w, damping, name);
      return name + " set to " + format_value(args.value) + (name == "contact_damping" ? " s" : " 1/s") + step;
    }
    if (name == "local_damping") {
      require(args.value >= 0.0 && args.value < 1.0, "local_damping must be in [0, 1)");
      DampingDef damping = service::damping(w);
      damping.local_alpha = args.value;
      const std::string step = set_damping_keeping_a_stable_step(w, damping, name);
      return "local_damping set to " + format_value(args.value) + step;
    }
    if (name == "time_step_fraction") return set_stable_time_step_fraction(w, args.value);
    if (name == "friction") {
      require(args.value >= 0.0, "friction must be >= 0");
      const auto& materials = service::materials(w);
      std::string known;
      for (std::size_t i = 0; i < materials.size(); ++i) {
        if (materials[i].name == args.material) {
          service::set_friction(w, MaterialId::from_index(i), args.value);
          return "friction of " + args.material + " set to " + format_value(args.value);
        }
        known += (i == 0 ? "" : ", ") + materials[i].name;
      }
      throw CommandError(ReplyStatus::kNotFound, "no material \"" + args.material + "\" (materials: " + known + ")");
    }
    if (name == "gravity") {
      const protocol::Vector3& g = args.vector;
      service::set_gravity(w, g);
      return "gravity set to (" + format_value(g.x) + ", " + format_value(g.y) +
             (dimension() == 3 ? ", " + format_value(g.z) : "") + ") m/s^2";
    }
  } catch (const DefinitionError& error) {
    throw CommandError(ReplyStatus::kBadRequest, error.what());
  }
  throw CommandError(ReplyStatus::kNotFound, "no parameter \"" + name +
                                                 "\" (parameters: contact_damping, global_damping, "
                                                 "local_damping, time_step_fraction, friction, gravity)");
}

std::vector<protocol::ContactEntry> Simulation::query_contacts(const protocol::ContactQueryArgs& args) const {
  ContactFilter filter;
  if (args.wall_set) filter.wall = find_wall(args.wall, args.wall_id);
  if (args.particle) filter.particle = ParticleId{*args.particle};
  if (args.box_set) {
    require(finite(args.box_min) && finite(args.box_max), "the box must be finite");
    require(args.box_min.x <= args.box_max.x && args.box_min.y <= args.box_max.y && args.box_min.z <= args.box_max.z,
            "the box's minimum corner must not exceed its maximum");
    filter.box_min = args.box_min;
    filter.box_max = args.box_max;
  }
  if (args.min_normal_force) {
    require(std::isfinite(*args.min_normal_force), "the force threshold must be finite");
    filter.min_normal_force = args.min_normal_force;
  }
  std::vector<protocol::ContactEntry> contacts = service::query_contacts(world(), filter);
  if (contacts.size() > max_query_contacts_) {
    throw CommandError(ReplyStatus::kBadRequest,
                       "the query matches " + std::to_string(contacts.size()) + " contacts, more than the " +
                           std::to_string(max_query_contacts_) +
                           " one query may return (--max-query-contacts): narrow it by wall, box or minimum force");
  }
  return contacts;
}

}  // namespace dem::service
