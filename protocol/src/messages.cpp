#include "dem/protocol/messages.h"

#include <chrono>

namespace dem::protocol {

Stamp now_stamp() {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(since_epoch);
  const auto nanoseconds = std::chrono::duration_cast<std::chrono::nanoseconds>(since_epoch - seconds);
  return {static_cast<std::int32_t>(seconds.count()), static_cast<std::uint32_t>(nanoseconds.count())};
}

// Every name below is a string literal, so the views are NUL-terminated
// (type_support.cpp hands state names to C).
std::string_view to_string(ServerState state) {
  switch (state) {
    case ServerState::kIdle: return "idle";
    case ServerState::kLoaded: return "loaded";
    case ServerState::kRunning: return "running";
    case ServerState::kError: return "error";
    case ServerState::kShutdown: return "shutdown";
  }
  return "error";
}

std::string_view to_string(CommandKind kind) {
  switch (kind) {
    case CommandKind::kLoadCase: return "load_case";
    case CommandKind::kSetWallVelocity: return "set_wall_velocity";
    case CommandKind::kSetWallServo: return "set_wall_servo";
    case CommandKind::kCycle: return "cycle";
    case CommandKind::kRunUntil: return "run_until";
    case CommandKind::kStop: return "stop";
    case CommandKind::kGetState: return "get_state";
    case CommandKind::kShutdown: return "shutdown";
    case CommandKind::kQueryContacts: return "query_contacts";
    case CommandKind::kSaveSnapshot: return "save_snapshot";
    case CommandKind::kLoadSnapshot: return "load_snapshot";
    case CommandKind::kSetParameter: return "set_parameter";
    case CommandKind::kRunProgramme: return "run_programme";
  }
  return "unknown";
}

std::string_view to_string(ReplyStatus status) {
  switch (status) {
    case ReplyStatus::kOk: return "ok";
    case ReplyStatus::kCancelled: return "cancelled";
    case ReplyStatus::kBadRequest: return "bad_request";
    case ReplyStatus::kNotFound: return "not_found";
    case ReplyStatus::kInvalidCase: return "invalid_case";
    case ReplyStatus::kInvalidSnapshot: return "invalid_snapshot";
    case ReplyStatus::kRefused: return "refused";
    case ReplyStatus::kFailed: return "failed";
    case ReplyStatus::kShuttingDown: return "shutting_down";
    case ReplyStatus::kBusy: return "busy";
  }
  return "unknown";
}

std::optional<CommandKind> command_kind(std::uint8_t value) {
  if (value < static_cast<std::uint8_t>(CommandKind::kLoadCase) ||
      value > static_cast<std::uint8_t>(CommandKind::kRunProgramme)) {
    return std::nullopt;
  }
  return static_cast<CommandKind>(value);
}

}  // namespace dem::protocol
