// How a C++ value type travels as a Cyclone DDS sample (the idea of
// rclcpp's TypeAdapter): a specialization names the idlc-generated topic
// descriptor and converts between the value type and the generated C
// struct, so the generated code stays behind one seam and the rest of the
// program sees plain C++ types.
#pragma once

#include <dds/dds.h>

#include <concepts>

#include "dem/dds/qos.h"

namespace dem::dds {

// Specialize for each message type T:
//   static const dds_topic_descriptor_t* descriptor();
//   // Converts `value` to its C sample (borrowing T's memory where it can)
//   // and returns dds_write's result.
//   static dds_return_t write(dds_entity_t writer, const T& value);
//   // Converts a received C sample (of descriptor()'s type) to T.
//   static T from_sample(const void* sample);
// and optionally
//   // USER_DATA every writer and reader of T carries (its type's hash).
//   static std::string user_data();
template <class T>
struct TypeSupport;

template <class T>
concept SupportedType = requires(const T& value, const void* sample, dds_entity_t writer) {
  { TypeSupport<T>::descriptor() } -> std::same_as<const dds_topic_descriptor_t*>;
  { TypeSupport<T>::write(writer, value) } -> std::same_as<dds_return_t>;
  { TypeSupport<T>::from_sample(sample) } -> std::same_as<T>;
};

// The QoS an endpoint of T is created with: `qos`, with T's USER_DATA when
// its TypeSupport gives one.
template <class T>
Qos endpoint_qos(const Qos& qos) {
  Qos with = qos;
  if constexpr (requires { TypeSupport<T>::user_data(); }) with.user_data(TypeSupport<T>::user_data());
  return with;
}

}  // namespace dem::dds
