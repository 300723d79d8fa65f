#include "dem/protocol/command_cdr.h"

#include <dds/dds.h>
#include <dds/ddsi/ddsi_cdrstream.h>
#include <dds/ddsi/q_protocol.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "c_conversions.h"
#include "c_sample.h"
#include "dem/protocol/type_support.h"

namespace dem::protocol {
namespace {

constexpr bool kLittleEndianHost = std::endian::native == std::endian::little;

// The two header bytes that name the encoding (big-endian on the wire).
std::uint16_t encoding_of(std::string_view bytes) {
  return static_cast<std::uint16_t>((static_cast<unsigned char>(bytes[0]) << 8) | static_cast<unsigned char>(bytes[1]));
}

}  // namespace

template <Message T>
std::string encode_cdr(const T& message) {
  // TypeSupport converts into a C sample and writes it; here the sample goes
  // to a stream instead, through the same conversion (type_support.cpp).
  std::string out;
  const dds_topic_descriptor_t* descriptor = dds::TypeSupport<T>::descriptor();
  with_c_sample(message, [&](const void* c_sample) {
    dds_ostream_t stream;
    dds_ostream_init(&stream, 0, CDR_ENC_VERSION_1);
    dds_stream_write(&stream, static_cast<const char*>(c_sample), descriptor->m_ops);
    out.assign("\x00\x01\x00\x00", 4);  // CDR_LE, no options
    out.append(reinterpret_cast<const char*>(stream.m_buffer), stream.m_index);
    dds_ostream_fini(&stream);
  });
  return out;
}

template <Message T>
std::optional<T> decode_cdr(std::string_view bytes) {
  if (bytes.size() < 4 || bytes.size() - 4 > UINT32_MAX) return std::nullopt;
  bool little = false;
  std::uint32_t version = CDR_ENC_VERSION_1;
  switch (encoding_of(bytes)) {
    case 0x0000:
      break;  // CDR_BE
    case 0x0001:
      little = true;
      break;  // CDR_LE
    case 0x0006:
      version = CDR_ENC_VERSION_2;
      break;  // CDR2_BE
    case 0x0007:
      little = true;
      version = CDR_ENC_VERSION_2;
      break;  // CDR2_LE
    default:
      return std::nullopt;
  }
  // Cyclone normalizes in place, in a buffer aligned for any primitive.
  const auto size = static_cast<std::uint32_t>(bytes.size() - 4);
  std::vector<std::uint64_t> buffer((size + 7) / 8 + 1);
  std::memcpy(buffer.data(), bytes.data() + 4, size);
  char* data = reinterpret_cast<char*>(buffer.data());
  const dds_topic_descriptor_t* descriptor = dds::TypeSupport<T>::descriptor();
  std::uint32_t offset = 0;
  if (dds_stream_normalize_data(data, &offset, size, little != kLittleEndianHost, version, descriptor->m_ops) ==
      nullptr) {
    return std::nullopt;
  }
  dds_istream_t stream{reinterpret_cast<const unsigned char*>(data), size, 0, version};
  auto sample = std::unique_ptr<void, decltype(&std::free)>(std::calloc(1, descriptor->m_size), &std::free);
  dds_stream_read(&stream, static_cast<char*>(sample.get()), descriptor->m_ops);
  T message = dds::TypeSupport<T>::from_sample(sample.get());
  dds_stream_free_sample(sample.get(), descriptor->m_ops);
  return message;
}

#define DEM_INSTANTIATE(T)                   \
  template std::string encode_cdr(const T&); \
  template std::optional<T> decode_cdr(std::string_view);
DEM_PROTOCOL_FOR_EACH_MESSAGE(DEM_INSTANTIATE)
#undef DEM_INSTANTIATE

std::string encode_command(const Command& command) { return encode_cdr(command); }

std::optional<Command> decode_command(std::string_view bytes) { return decode_cdr<Command>(bytes); }

}  // namespace dem::protocol
