// How a C++ value type travels as a Cyclone DDS sample (the idea of
// rclcpp's TypeAdapter): a specialization names the idlc-generated topic
// descriptor and converts between the value type and the generated C
// struct, so the generated code stays behind one seam and the rest of the
// program sees plain C++ types.
#pragma once

#include <dds/dds.h>

#include <concepts>

namespace dem::dds {

// Specialize for each message type T:
//   static const dds_topic_descriptor_t* descriptor();
//   // Converts `value` to its C sample (borrowing T's memory where it can)
//   // and returns dds_write's result.
//   static dds_return_t write(dds_entity_t writer, const T& value);
//   // Converts a received C sample (of descriptor()'s type) to T.
//   static T from_sample(const void* sample);
template <class T>
struct TypeSupport;

template <class T>
concept SupportedType = requires(const T& value, const void* sample, dds_entity_t writer) {
  { TypeSupport<T>::descriptor() } -> std::same_as<const dds_topic_descriptor_t*>;
  { TypeSupport<T>::write(writer, value) } -> std::same_as<dds_return_t>;
  { TypeSupport<T>::from_sample(sample) } -> std::same_as<T>;
};

}  // namespace dem::dds
