// The server's lifecycle (the idea of rclcpp_lifecycle's states): the
// states, the named transitions between them, and which commands each
// state accepts. SimulationRunner changes state only through a Lifecycle.
//
//   state     meaning                         transitions out
//   idle      no case                         install -> loaded
//   loaded    a case, at rest                 install -> loaded, start_run -> running
//   running   a cycle, run_until or programme end_run -> loaded, fail_run -> error
//             is stepping the world
//   error     the last run failed; the world  install -> loaded
//             is back at its last good state
//   shutdown  the final status                (none)
//   any state but shutdown: shut_down -> shutdown
//
// Accepted commands (stop, get_state and shutdown in every state):
//   idle      load_case, load_snapshot
//   loaded    every command
//   running   set_wall_velocity, set_wall_servo, query_contacts, save_snapshot
//             (the world is steered and read between cycles, not reloaded,
//             re-parameterised or run again)
//   error     load_case, load_snapshot, query_contacts, save_snapshot
//   shutdown  none
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "dem/protocol/messages.h"

namespace dem::service {

enum class Transition {
  kInstall,    // a case or snapshot loaded: a new world
  kStartRun,   // a cycle, run_until or programme begins
  kEndRun,     // it completed or was stopped
  kFailRun,    // it failed (the engine threw, the world is unhealthy, an output failed)
  kLoseWorld,  // after a failure, the world could not be kept (no memory to restore it): idle
  kShutDown,   // the server stops
};

std::string_view to_string(Transition transition);

// The state `transition` leads to from `from`, or nothing when `from` has no such transition.
std::optional<protocol::ServerState> next_state(protocol::ServerState from, Transition transition);

// Why `kind` is refused in `state`, or nothing when it is accepted.
std::optional<std::string> refusal(protocol::ServerState state, protocol::CommandKind kind);

class Lifecycle {
 public:
  protocol::ServerState state() const { return state_; }
  bool running() const { return state_ == protocol::ServerState::kRunning; }
  // Takes a transition; one the state does not have is a bug of the
  // caller's: std::logic_error, the state unchanged.
  void take(Transition transition);
  std::optional<std::string> refusal(protocol::CommandKind kind) const { return service::refusal(state_, kind); }

 private:
  protocol::ServerState state_ = protocol::ServerState::kIdle;
};

}  // namespace dem::service
