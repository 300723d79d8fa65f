#include "dem/service/lifecycle.h"

#include <cstdint>
#include <stdexcept>

namespace dem::service {

using protocol::CommandKind;
using protocol::ServerState;

namespace {

constexpr std::uint32_t bit(CommandKind kind) { return std::uint32_t{1} << static_cast<unsigned>(kind); }
template <typename... Kinds>
constexpr std::uint32_t kinds(Kinds... k) {
  return (bit(k) | ... | 0u);
}

constexpr std::uint32_t kAlways = kinds(CommandKind::kStop, CommandKind::kGetState, CommandKind::kShutdown);
constexpr std::uint32_t kRuns = kinds(CommandKind::kCycle, CommandKind::kRunUntil, CommandKind::kRunProgramme);

// The table in lifecycle.h: what each state accepts besides kAlways, and
// why it refuses the rest.
struct StateRule {
  std::uint32_t accepts;
  const char* refusal;
};

StateRule rule(ServerState state) {
  switch (state) {
    case ServerState::kIdle:
      return {kinds(CommandKind::kLoadCase, CommandKind::kLoadSnapshot),
              "no case is loaded: load a case or a snapshot first"};
    case ServerState::kLoaded:
      return {~0u, ""};
    case ServerState::kRunning:
      return {kinds(CommandKind::kSetWallVelocity, CommandKind::kSetWallServo, CommandKind::kQueryContacts,
                    CommandKind::kSaveSnapshot),
              "not while a command is running: stop it first"};
    case ServerState::kError:
      // The world is back at the last good state: it may be read and saved.
      return {kinds(CommandKind::kLoadCase, CommandKind::kLoadSnapshot, CommandKind::kQueryContacts,
                    CommandKind::kSaveSnapshot),
              "the server is in error after a failed run (its world is back at the last good state, which "
              "save_snapshot saves): load a case or a snapshot"};
    case ServerState::kShutdown:
      return {0u, "the server is shutting down"};
  }
  return {0u, "unknown server state"};
}

}  // namespace

std::string_view to_string(Transition transition) {
  switch (transition) {
    case Transition::kInstall:
      return "install";
    case Transition::kStartRun:
      return "start_run";
    case Transition::kEndRun:
      return "end_run";
    case Transition::kFailRun:
      return "fail_run";
    case Transition::kLoseWorld:
      return "lose_world";
    case Transition::kShutDown:
      return "shut_down";
  }
  return "unknown";
}

std::optional<ServerState> next_state(ServerState from, Transition transition) {
  if (from == ServerState::kShutdown) return std::nullopt;
  switch (transition) {
    case Transition::kInstall:
      if (from == ServerState::kRunning) return std::nullopt;
      return ServerState::kLoaded;
    case Transition::kStartRun:
      if (from != ServerState::kLoaded) return std::nullopt;
      return ServerState::kRunning;
    case Transition::kEndRun:
      if (from != ServerState::kRunning) return std::nullopt;
      return ServerState::kLoaded;
    case Transition::kFailRun:
      if (from != ServerState::kRunning) return std::nullopt;
      return ServerState::kError;
    case Transition::kLoseWorld:
      if (from != ServerState::kError) return std::nullopt;
      return ServerState::kIdle;
    case Transition::kShutDown:
      return ServerState::kShutdown;
  }
  return std::nullopt;
}

std::optional<std::string> refusal(ServerState state, CommandKind kind) {
  const StateRule r = rule(state);
  if ((kAlways | r.accepts) & bit(kind)) return std::nullopt;
  if (state == ServerState::kRunning && (kRuns & bit(kind))) {
    return "a command is already running: wait for it or stop it";
  }
  return r.refusal;
}

void Lifecycle::take(Transition transition) {
  const std::optional<ServerState> next = next_state(state_, transition);
  if (!next) {
    throw std::logic_error("lifecycle: no transition " + std::string(to_string(transition)) + " from " +
                           std::string(protocol::to_string(state_)));
  }
  state_ = *next;
}

}  // namespace dem::service
