// The server's lifecycle (the idea of rclcpp_lifecycle's states): which
// commands each state accepts.
//
//   idle     no case            -> loaded by load_case / load_snapshot
//   loaded   a case, at rest    -> running by cycle / run_until
//   running  stepping the world -> loaded when the command ends or is stopped
//   error    the last run failed (the world is not trustworthy)
//            -> loaded by load_case / load_snapshot
//   shutdown the final status of a server that has stopped
//
// Always accepted: stop, get_state, shutdown. While running, the world can
// be steered (wall velocity, servo) and read (contacts, snapshot) between
// chunks of cycles, but not reloaded, re-parameterised or cycled again.
#pragma once

#include <optional>
#include <string>

#include "dem/protocol/messages.h"

namespace dem::service {

// Why `kind` is refused in `state`, or nothing when it is accepted.
std::optional<std::string> refusal(protocol::ServerState state, protocol::CommandKind kind);

}  // namespace dem::service
