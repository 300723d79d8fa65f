// The interface every endpoint declares, and what a peer's declaration says
// about meeting it (docs/DDS.md, "Evolving the wire"). Each writer and
// reader of a dem type carries USER_DATA "typehash=RIHS01_<sha256>;
// dem_interfaces=<version>;": the first part is ROS 2's own (REP-2016, which
// ROS 2 nodes since Iron send too), computed from the message files; the
// version is the package's. A peer's hash is judged against the
// interface's recorded history (idl/interface_history.json): the same
// form, an older one that still reads or is read (fields appended at the
// end of a message), or one that does not meet this one.
#pragma once

#include <string>
#include <string_view>

#include "dem/dds/discovery.h"

namespace dem::protocol {

// "typehash=RIHS01_...;dem_interfaces=0.2.0;" for a dem type ("" for another).
std::string endpoint_user_data(std::string_view type_name);
// The ROS 2 type hash of a dem type, "" for another.
std::string_view type_hash_of(std::string_view type_name);
// The "typehash=" value in an endpoint's USER_DATA, "" when it has none.
std::string_view peer_type_hash(std::string_view user_data);

struct PeerVerdict {
  enum class Kind {
    kSame,             // the same form of its type
    kOlderCompatible,  // an older form; the samples one writes, the other reads
    kIncompatible,     // a form whose samples the other cannot read
    kUnknownForm,      // a type hash the history does not know: built from other message files
    kNoTypeHash,       // no hash: dem before 0.2.0, ROS 2 before Iron, or another DDS program
    kNotOurs,          // not a dem type, or not a topic this process uses
  };
  Kind kind = Kind::kNotOurs;
  std::string text;  // for people: the topic, the peer, its version and what differs
  dds::Endpoint peer;
};

// `peer`: an endpoint discovery found on one of this process's topics;
// `self`: "this server" or "this client", for the message.
PeerVerdict judge_peer(const dds::Endpoint& peer, std::string_view self);

}  // namespace dem::protocol
