// dds::TypeSupport for the service's messages (see dem/dds/type_support.h):
// every struct of dem/protocol/messages.h travels as the C struct idlc
// generates from the same IDL; protocol/src/type_support.cpp converts.
#pragma once

#include <string>

#include "dem/dds/type_support.h"
#include "dem/protocol/interface_check.h"
#include "dem/protocol/messages.h"

namespace dem::protocol::detail {

// Defined for every message in type_support.cpp.
template <class T>
const dds_topic_descriptor_t* descriptor_of();
template <class T>
dds_return_t write_sample(dds_entity_t writer, const T& value);
template <class T>
T read_sample(const void* sample);

}  // namespace dem::protocol::detail

namespace dem::dds {

template <protocol::Message T>
struct TypeSupport<T> {
  static const dds_topic_descriptor_t* descriptor() { return protocol::detail::descriptor_of<T>(); }
  static dds_return_t write(dds_entity_t writer, const T& value) {
    return protocol::detail::write_sample(writer, value);
  }
  static T from_sample(const void* sample) { return protocol::detail::read_sample<T>(sample); }
  // Every endpoint declares its type's hash and the interface's version.
  static std::string user_data() { return protocol::endpoint_user_data(descriptor()->m_typename); }
};

}  // namespace dem::dds
