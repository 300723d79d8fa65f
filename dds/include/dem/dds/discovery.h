// What DDS discovery knows: the writers (publications) of every
// participant in the domain, local and remote, from the built-in
// DCPSPublication topic - how `ros2 topic list` sees the graph.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/dds/entity.h"
#include "dem/dds/participant.h"

namespace dem::dds {

// A participant's GUID, compared byte by byte: the same order on every
// participant of the domain.
using Guid = std::array<std::uint8_t, 16>;

Guid guid_of(const Participant& participant);

struct Publication {
  std::string topic_name;
  std::string type_name;
  Guid participant{};  // the GUID of the participant the writer belongs to
};

class PublicationMonitor {
 public:
  explicit PublicationMonitor(const Participant& participant);
  // The writers alive now (discovery of remote ones takes a moment after
  // this monitor is created).
  std::vector<Publication> alive() const;

 private:
  Entity entity_;
};

}  // namespace dem::dds
