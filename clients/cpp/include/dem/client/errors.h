// What can go wrong when talking to a dem_server, as exceptions a program
// can tell apart (demctl maps each to its own exit code).
#pragma once

#include <stdexcept>
#include <string>

#include "dem/protocol/messages.h"

namespace dem::client {

// No server of that name answered on the domain within the timeout.
class NoSuchServer : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The server was found, but its interface and this client's cannot meet:
// its commands or replies are of a form the other side cannot read (an
// older or newer dem_interfaces). what() names the versions and the fields.
class InterfaceMismatch : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The server was there but its (complete) reply did not arrive in time.
class ReplyTimeout : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file on this machine that a command was to send could not be read
// (missing, a directory, no permission); what() names it and why.
class LocalFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The server answered with an error status; what() is its message.
class ServerError : public std::runtime_error {
 public:
  explicit ServerError(protocol::Reply reply) : std::runtime_error(reply.message), reply_(std::move(reply)) {}
  protocol::ReplyStatus status() const { return reply_.status; }
  const protocol::Reply& reply() const { return reply_; }

 private:
  protocol::Reply reply_;
};

}  // namespace dem::client
