// One round of the discovery probe as an ordinary DDS peer would play it
// (discovery_probe.cpp runs each round in a process of its own, so every
// round starts with an empty type library and asks the server for types
// again): a participant that describes the server's type names in another
// way for each of its topics - other members, another extensibility, keys,
// no type information at all, as ROS 2's rmw_cyclonedds does - with readers
// and writers on the server's topics, that asks the server for the type
// objects of its endpoints (type-lookup requests), and that leaves cleanly
// or dies without a word (its proxies then linger until their lease ends).
#pragma once

#include <cstdint>
#include <string>

namespace dem::probe {

struct ParticipantRound {
  std::uint32_t domain = 0;
  std::string server;      // the dem_server whose topics are probed
  std::uint64_t seed = 0;  // picks the descriptions, the QoS and how the round ends
  int lookup_timeout_ms = 200;
};

// Runs the round in this process; returns the process exit code (0), or
// does not return when the round ends by dying (_exit).
int run_participant_round(const ParticipantRound& round);

}  // namespace dem::probe
