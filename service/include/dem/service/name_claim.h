// A server's name is its address on the domain: two servers of one name
// would both execute every command. Before it publishes anything, a server
// looks for another's status writer under its name and refuses to start
// while one is there. A server that died without leaving (SIGKILL) stays
// visible until its DDS lease runs out (10 s by default), so the check
// waits that long for such a name to come free before refusing. Two
// servers started within the discovery time of each other are not told
// apart (docs/RELIABILITY.md).
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>

#include "dem/dds/participant.h"

namespace dem::service {

class NameInUse : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws NameInUse when a server named `name` is on the participant's domain
// after `discovery` and still after `wait` more.
void claim_name(const dds::Participant& participant, const std::string& name, std::uint32_t domain,
                std::chrono::milliseconds discovery, std::chrono::milliseconds wait);

}  // namespace dem::service
