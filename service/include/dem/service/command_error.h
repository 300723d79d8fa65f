// Why a command cannot be done: a reply status and a message for people.
// Command handlers throw it; the runner turns it into the command's reply
// (the one place where failures become replies), leaving the simulation as
// it was.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

#include "dem/protocol/messages.h"

namespace dem::service {

class CommandError : public std::runtime_error {
 public:
  CommandError(protocol::ReplyStatus status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  protocol::ReplyStatus status() const { return status_; }

 private:
  protocol::ReplyStatus status_;
};

// A bad request unless `condition` holds.
inline void require_argument(bool condition, const std::string& message) {
  if (!condition) throw CommandError(protocol::ReplyStatus::kBadRequest, message);
}

// What a command, a run or the work between them ran into, for its reply:
// memory running out (std::bad_alloc) is said as such, with the limit the
// process started under; anything else by its own message.
std::string failure_reason(const std::exception& error);

}  // namespace dem::service
