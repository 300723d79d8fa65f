// What DDS discovery knows: the writers (publications) and readers
// (subscriptions) of every participant in the domain, local and remote,
// from the built-in DCPSPublication and DCPSSubscription topics - how
// `ros2 topic list` sees the graph - with each one's USER_DATA.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/dds/entity.h"
#include "dem/dds/participant.h"
#include "dem/dds/topic.h"

namespace dem::dds {

// A participant's GUID, compared byte by byte: the same order on every
// participant of the domain.
using Guid = std::array<std::uint8_t, 16>;

Guid guid_of(const Participant& participant);

struct Endpoint {
  std::string topic_name;
  std::string type_name;
  Guid participant{};     // the GUID of the participant the endpoint belongs to
  std::string user_data;  // its QoS's USER_DATA (empty when it has none)
  bool writer = true;     // a writer (publication), or a reader (subscription)
};
using Publication = Endpoint;

class EndpointMonitor {
 public:
  enum class Kind { kWriters, kReaders };
  EndpointMonitor(const Participant& participant, Kind kind);
  // The endpoints of that kind alive now (discovery of remote ones takes a
  // moment after this monitor is created).
  std::vector<Endpoint> alive() const;
  dds_entity_t handle() const { return entity_.handle(); }

 private:
  Kind kind_;
  Entity entity_;
  mutable LoanSlots slots_;
};

// The writers (DCPSPublication).
class PublicationMonitor : public EndpointMonitor {
 public:
  explicit PublicationMonitor(const Participant& participant) : EndpointMonitor(participant, Kind::kWriters) {}
};

}  // namespace dem::dds
