// A keyed type's descriptor without its keys: the same type name, fields
// and wire form (plain CDR carries no key of its own), one instance. It is
// what idlc makes of the IDL with the @key annotations left out, derived
// from the descriptor idlc made of the IDL as it is, so the type stays
// defined once (idl/dem/command.idl).
//
// Why: Cyclone DDS matches a keyed writer with keyed readers and a keyless
// one with keyless readers only (RTPS keeps the two kinds of endpoint
// apart by their entity ids), and a ROS 2 node's reader is keyless
// (rmw_cyclonedds registers its types without keys: a .msg has none). A
// program that keys a topic for its own peers writes to ROS 2 nodes with a
// second, keyless writer of the same topic (docs/DDS.md, "Replies to ROS 2
// nodes").
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <vector>

namespace dem::dds {

class KeylessDescriptor {
 public:
  // Throws DdsError for a descriptor with XTypes type information (which
  // would describe the keyed type: the project's types have none,
  // idl/CMakeLists.txt) or with a key inside a nested struct.
  explicit KeylessDescriptor(const dds_topic_descriptor_t& keyed);
  KeylessDescriptor(const KeylessDescriptor&) = delete;
  KeylessDescriptor& operator=(const KeylessDescriptor&) = delete;

  const dds_topic_descriptor_t& get() const { return descriptor_; }

 private:
  std::vector<std::uint32_t> ops_;
  dds_topic_descriptor_t descriptor_;
};

}  // namespace dem::dds
