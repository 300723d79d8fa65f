#include "dem/service/command_limits.h"

#include <cmath>
#include <string>

#include "dem/service/command_error.h"

namespace dem::service {
namespace {

using protocol::CommandKind;
using protocol::ReplyStatus;

// The same bound case validation puts on every number (io/src/problem_list.h).
constexpr double kLargestMagnitude = 1e30;

void require(bool condition, const std::string& message) {
  if (!condition) throw CommandError(ReplyStatus::kBadRequest, message);
}

void number(const std::string& field, double value) {
  require(std::isfinite(value) && std::abs(value) <= kLargestMagnitude,
          field + ": must be a finite number of magnitude at most 1e30");
}

void vector(const std::string& field, const protocol::Vector3& v) {
  number(field + ".x", v.x);
  number(field + ".y", v.y);
  number(field + ".z", v.z);
}

void text(const std::string& field, const std::string& value, const CommandLimits& limits) {
  require(value.size() <= limits.max_text_bytes, field + ": " + std::to_string(value.size()) +
                                                     " bytes, more than the limit of " +
                                                     std::to_string(limits.max_text_bytes));
}

void payload(const std::string& field, const std::string& value, const CommandLimits& limits) {
  require(value.size() <= limits.max_payload_bytes,
          field + ": " + std::to_string(value.size()) + " bytes, more than the server's limit of " +
              std::to_string(limits.max_payload_bytes) + " bytes (--max-payload-bytes)");
}

void cycles(const std::string& field, std::int64_t value, const CommandLimits& limits) {
  require(value > 0, field + ": must be > 0, got " + std::to_string(value));
  require(static_cast<std::uint64_t>(value) <= limits.max_cycles,
          field + ": " + std::to_string(value) + " cycles, more than the server's limit of " +
              std::to_string(limits.max_cycles) + " a command (--max-cycles)");
}

void check_run_until(const protocol::RunUntilArgs& r, const CommandLimits& limits) {
  text("run_until.wall", r.wall, limits);
  cycles("run_until.max_cycles", r.max_cycles, limits);
  require(r.check_interval >= 0 && r.check_interval <= r.max_cycles,
          "run_until.check_interval: must be from 0 to max_cycles, got " + std::to_string(r.check_interval));
  if (r.stress) number("run_until.stress", *r.stress);
  if (r.settlement) number("run_until.settlement", *r.settlement);
  if (r.kinetic_energy) number("run_until.kinetic_energy", *r.kinetic_energy);
}

void check_query(const protocol::ContactQueryArgs& q, const CommandLimits& limits) {
  text("query.wall", q.wall, limits);
  if (q.box_set) {
    vector("query.box_min", q.box_min);
    vector("query.box_max", q.box_max);
  }
  if (q.min_normal_force) number("query.min_normal_force", *q.min_normal_force);
  require(q.chunk_size <= limits.max_chunk_contacts, "query.chunk_size: " + std::to_string(q.chunk_size) +
                                                         " contacts a chunk, more than the limit of " +
                                                         std::to_string(limits.max_chunk_contacts));
}

}  // namespace

void check_command(const protocol::Command& c, const CommandLimits& limits) {
  const std::optional<CommandKind> kind = protocol::command_kind(c.kind);
  require(kind.has_value(), "unknown command kind " + std::to_string(c.kind));
  text("client_id", c.client_id, limits);
  switch (*kind) {
    case CommandKind::kLoadCase:
      text("load_case.path", c.load_case.path, limits);
      text("load_case.source_name", c.load_case.source_name, limits);
      payload("load_case.text", c.load_case.text, limits);
      payload("load_case.binary", c.load_case.binary, limits);
      break;
    case CommandKind::kSetWallVelocity:
      text("wall_velocity.wall", c.wall_velocity.wall, limits);
      vector("wall_velocity.twist.linear", c.wall_velocity.twist.linear);
      vector("wall_velocity.twist.angular", c.wall_velocity.twist.angular);
      break;
    case CommandKind::kSetWallServo:
      text("wall_servo.wall", c.wall_servo.wall, limits);
      number("wall_servo.target_stress", c.wall_servo.target_stress);
      number("wall_servo.gain", c.wall_servo.gain);
      number("wall_servo.max_speed", c.wall_servo.max_speed);
      break;
    case CommandKind::kCycle:
      cycles("cycle.cycles", c.cycle.cycles, limits);
      break;
    case CommandKind::kRunUntil:
      check_run_until(c.run_until, limits);
      break;
    case CommandKind::kQueryContacts:
      check_query(c.query, limits);
      break;
    case CommandKind::kSaveSnapshot:
    case CommandKind::kLoadSnapshot:
      text("snapshot.path", c.snapshot.path, limits);
      payload("snapshot.data", c.snapshot.data, limits);
      break;
    case CommandKind::kSetParameter:
      text("parameter.name", c.parameter.name, limits);
      text("parameter.material", c.parameter.material, limits);
      number("parameter.value", c.parameter.value);
      vector("parameter.vector", c.parameter.vector);
      break;
    case CommandKind::kStop:
    case CommandKind::kGetState:
    case CommandKind::kShutdown:
    case CommandKind::kRunProgramme:
      break;
  }
}

}  // namespace dem::service
