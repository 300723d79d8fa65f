// What DDS discovery knows: the writers (publications) of every
// participant in the domain, local and remote, from the built-in
// DCPSPublication topic - how `ros2 topic list` sees the graph.
#pragma once

#include <string>
#include <vector>

#include "dem/dds/entity.h"
#include "dem/dds/participant.h"

namespace dem::dds {

struct Publication {
  std::string topic_name;
  std::string type_name;
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
