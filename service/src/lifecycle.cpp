#include "dem/service/lifecycle.h"

namespace dem::service {

using protocol::CommandKind;
using protocol::ServerState;

std::optional<std::string> refusal(ServerState state, CommandKind kind) {
  switch (kind) {
    case CommandKind::kStop:
    case CommandKind::kGetState:
    case CommandKind::kShutdown:
      return std::nullopt;
    default:
      break;
  }
  switch (state) {
    case ServerState::kIdle:
      if (kind == CommandKind::kLoadCase || kind == CommandKind::kLoadSnapshot) return std::nullopt;
      return "no case is loaded: load a case or a snapshot first";
    case ServerState::kLoaded:
      return std::nullopt;
    case ServerState::kRunning:
      switch (kind) {
        case CommandKind::kSetWallVelocity:
        case CommandKind::kSetWallServo:
        case CommandKind::kQueryContacts:
        case CommandKind::kSaveSnapshot:
          return std::nullopt;
        case CommandKind::kCycle:
        case CommandKind::kRunUntil:
        case CommandKind::kRunProgramme:
          return "a command is already running: wait for it or stop it";
        default:
          return "not while a command is running: stop it first";
      }
    case ServerState::kError:
      // The world is back at the last good state: it may be read and saved.
      if (kind == CommandKind::kLoadCase || kind == CommandKind::kLoadSnapshot || kind == CommandKind::kQueryContacts ||
          kind == CommandKind::kSaveSnapshot) {
        return std::nullopt;
      }
      return "the server is in error after a failed run (its world is back at the last good state, which "
             "save_snapshot saves): load a case or a snapshot";
    case ServerState::kShutdown:
      return "the server is shutting down";
  }
  return "unknown server state";
}

}  // namespace dem::service
