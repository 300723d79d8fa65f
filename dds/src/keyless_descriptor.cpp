#include "dem/dds/keyless_descriptor.h"

#include <string>

#include "dem/dds/error.h"

// Exported by libddsc 0.10 (dds/ddsi/ddsi_cdrstream.h): the length in
// words of a descriptor's program with the key lists of the keys given, as
// Cyclone copies it into a topic's type.
extern "C" uint32_t dds_stream_countops(const uint32_t* ops, uint32_t nkeys, const dds_key_descriptor_t* keys);

namespace dem::dds {

namespace {

// The descriptor's serialization program (Cyclone 0.10.2, dds_opcodes.h):
// the type's ops, then one key-offset list per key - DDS_OP_KOF | n and n
// indices of the ops that lead to the key member, the first an index into
// the whole program, the next ones relative to the nested type the one
// before it jumps to - which the key descriptors point at (m_offset).
// Without keys the lists are not read (dds_stream_countops counts them only
// for the keys named), and the key members' ops lose the flags that make
// them keys: DDS_OP_FLAG_KEY and DDS_OP_FLAG_MU (idlc marks every key
// "must understand"), as idlc writes them for the IDL without @key.
std::vector<std::uint32_t> ops_without_keys(const dds_topic_descriptor_t& keyed) {
  const std::string type = keyed.m_typename;
  if ((keyed.m_flagset & DDS_TOPIC_XTYPES_METADATA) != 0) {
    throw DdsError(
        DDS_RETCODE_BAD_PARAMETER,
        type + ": a keyless form of a type with XTypes type information is not made (it would name the keyed type)");
  }
  std::vector<std::uint32_t> ops(keyed.m_ops,
                                 keyed.m_ops + dds_stream_countops(keyed.m_ops, keyed.m_nkeys, keyed.m_keys));
  for (std::uint32_t k = 0; k < keyed.m_nkeys; ++k) {
    const std::string key = keyed.m_keys[k].m_name;
    const std::uint32_t list = keyed.m_keys[k].m_offset;
    if (DDS_OP(ops.at(list)) != DDS_OP_KOF || (ops[list] & 0xffffu) != 1) {
      throw DdsError(DDS_RETCODE_BAD_PARAMETER,
                     type + ": key " + key +
                         " is not a member of the type itself (a key in a nested struct has no keyless form here)");
    }
    std::uint32_t& member = ops.at(ops.at(list + 1));
    if (DDS_OP(member) != DDS_OP_ADR)
      throw DdsError(DDS_RETCODE_BAD_PARAMETER, type + ": key " + key + " names no member");
    member &= ~(DDS_OP_FLAG_KEY | DDS_OP_FLAG_MU);
  }
  return ops;
}

}  // namespace

KeylessDescriptor::KeylessDescriptor(const dds_topic_descriptor_t& keyed)
    : ops_(ops_without_keys(keyed)),
      descriptor_{.m_size = keyed.m_size,
                  .m_align = keyed.m_align,
                  .m_flagset = keyed.m_flagset & ~(DDS_TOPIC_FIXED_KEY | DDS_TOPIC_FIXED_KEY_XCDR2),
                  .m_nkeys = 0,
                  .m_typename = keyed.m_typename,
                  .m_keys = nullptr,
                  .m_nops = keyed.m_nops,
                  .m_ops = ops_.data(),
                  .m_meta = keyed.m_meta,
                  .type_information = {},
                  .type_mapping = {},
                  .restrict_data_representation = keyed.restrict_data_representation} {}

}  // namespace dem::dds
