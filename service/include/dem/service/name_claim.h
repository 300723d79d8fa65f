// A server's name is its address on the domain: two servers of one name
// would both execute every command. A server claims its name before it
// publishes anything and holds the claim as long as it lives:
// 1. It announces its claim at once - a writer, which never writes, on
//    rt/dem/<name>/_name_claim - and waits `discovery` for the domain to
//    see it and for it to see the domain.
// 2. A server that holds the name already (its status writer is there)
//    keeps it: the claim waits up to `wait` for it to leave - a server
//    that died (SIGKILL) stays visible until its DDS lease runs out, 10 s
//    by default - and then refuses.
// 3. Of servers claiming the name at the same time, the one whose DDS
//    participant has the lowest GUID takes it: each other claimant waits
//    until that one holds the name and then refuses, or goes on claiming
//    if it leaves first (it may have refused for another reason).
// Two servers both start only when discovery between them takes longer
// than `discovery` (docs/RELIABILITY.md, "Ownership and names").
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>

#include "dem/dds/participant.h"
#include "dem/dds/topic.h"
#include "dem/protocol/messages.h"
#include "dem/protocol/type_support.h"

namespace dem::service {

// Exit code 5 of dem_server.
class NameInUse : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class NameClaim {
 public:
  // Throws NameInUse when another server holds `name` on the participant's
  // domain after `discovery` and still after `wait` more, or when a server
  // claiming it at the same time takes it.
  NameClaim(const dds::Participant& participant, const std::string& name, std::chrono::milliseconds discovery,
            std::chrono::milliseconds wait);

 private:
  dds::Topic<protocol::Status> topic_;
  dds::Writer<protocol::Status> writer_;
};

}  // namespace dem::service
