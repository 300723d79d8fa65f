// TypeSupport for every message, over the conversions generated from the
// IDL (c_conversions.h, from protocol/generate_messages.py).
#include "dem/protocol/type_support.h"

#include <dds/dds.h>

#include "c_conversions.h"
#include "c_sample.h"

namespace dem::protocol {

namespace detail {

template <class T>
const dds_topic_descriptor_t* descriptor_of() {
  return CType<T>::descriptor;
}

template <class T>
dds_return_t write_sample(dds_entity_t writer, const T& value) {
  Borrowed borrowed;
  typename CType<T>::type sample{};
  to_c(value, sample, borrowed);
  return dds_write(writer, &sample);
}

template <class T>
T read_sample(const void* sample) {
  T value;
  from_c(*static_cast<const typename CType<T>::type*>(sample), value);
  return value;
}

}  // namespace detail

template <Message T>
void with_c_sample(const T& message, const std::function<void(const void*)>& use) {
  Borrowed borrowed;
  typename CType<T>::type sample{};
  to_c(message, sample, borrowed);
  use(&sample);
}

#define DEM_INSTANTIATE(T)                                            \
  template const dds_topic_descriptor_t* detail::descriptor_of<T>();  \
  template dds_return_t detail::write_sample(dds_entity_t, const T&); \
  template T detail::read_sample<T>(const void*);                     \
  template void with_c_sample(const T&, const std::function<void(const void*)>&);
DEM_PROTOCOL_FOR_EACH_MESSAGE(DEM_INSTANTIATE)
#undef DEM_INSTANTIATE

}  // namespace dem::protocol
