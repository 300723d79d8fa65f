#include "rtps_packets.h"

#include <algorithm>
#include <array>
#include <chrono>

namespace dem::probe {
namespace {

// Parameter ids (DDSI-RTPS 9.6.2.2 Table 9.12; XTypes 7.6.3.2.2).
constexpr std::uint16_t kPidSentinel = 0x0001;
constexpr std::uint16_t kPidParticipantLeaseDuration = 0x0002;
constexpr std::uint16_t kPidTopicName = 0x0005;
constexpr std::uint16_t kPidTypeName = 0x0007;
constexpr std::uint16_t kPidProtocolVersion = 0x0015;
constexpr std::uint16_t kPidVendorId = 0x0016;
constexpr std::uint16_t kPidReliability = 0x001a;
constexpr std::uint16_t kPidDefaultUnicastLocator = 0x0031;
constexpr std::uint16_t kPidMetatrafficUnicastLocator = 0x0032;
constexpr std::uint16_t kPidParticipantGuid = 0x0050;
constexpr std::uint16_t kPidEndpointGuid = 0x005a;
constexpr std::uint16_t kPidBuiltinEndpointSet = 0x0058;
constexpr std::uint16_t kPidDataRepresentation = 0x0073;
constexpr std::uint16_t kPidTypeInformation = 0x0075;

// The built-in endpoints the fake participant claims (9.3.2 Table 9.4;
// Cyclone's bits for the type-lookup service): SPDP, SEDP both ways and
// the type-lookup request and reply writers and readers.
constexpr std::uint32_t kBuiltinEndpoints = 0x3f | (0xfu << 12);

void put_u16(Bytes& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
}

void put_u32(Bytes& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

// Entity ids go on the wire as four bytes, key then kind (9.3.1.2).
void put_entity(Bytes& out, std::uint32_t entity) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(entity >> shift));
}

void put_sequence_number(Bytes& out, std::int64_t sequence) {
  put_u32(out, static_cast<std::uint32_t>(static_cast<std::uint64_t>(sequence) >> 32));
  put_u32(out, static_cast<std::uint32_t>(sequence));
}

}  // namespace

ParameterList& ParameterList::add(std::uint16_t pid, const Bytes& value) {
  const std::size_t padded = (value.size() + 3) & ~std::size_t{3};
  put_u16(bytes_, pid);
  put_u16(bytes_, static_cast<std::uint16_t>(padded));
  bytes_.insert(bytes_.end(), value.begin(), value.end());
  bytes_.resize(bytes_.size() + padded - value.size(), 0);
  return *this;
}

ParameterList& ParameterList::add_u32(std::uint16_t pid, std::uint32_t value) {
  Bytes bytes;
  put_u32(bytes, value);
  return add(pid, bytes);
}

ParameterList& ParameterList::add_string(std::uint16_t pid, const std::string& text) {
  Bytes bytes;
  put_u32(bytes, static_cast<std::uint32_t>(text.size() + 1));
  bytes.insert(bytes.end(), text.begin(), text.end());
  bytes.push_back(0);
  return add(pid, bytes);
}

ParameterList& ParameterList::add_guid(std::uint16_t pid, const GuidPrefix& prefix, std::uint32_t entity) {
  Bytes bytes(prefix.begin(), prefix.end());
  put_entity(bytes, entity);
  return add(pid, bytes);
}

ParameterList& ParameterList::add_locator(std::uint16_t pid, std::uint16_t port) {
  Bytes bytes;
  put_u32(bytes, 1);  // LOCATOR_KIND_UDPv4
  put_u32(bytes, port);
  bytes.resize(bytes.size() + 12, 0);
  for (const std::uint8_t octet : std::array<std::uint8_t, 4>{127, 0, 0, 1}) bytes.push_back(octet);
  return add(pid, bytes);
}

ParameterList& ParameterList::add_duration(std::uint16_t pid, std::int32_t seconds) {
  Bytes bytes;
  put_u32(bytes, static_cast<std::uint32_t>(seconds));
  put_u32(bytes, 0);
  return add(pid, bytes);
}

Bytes ParameterList::payload() const {
  Bytes out(4 + bytes_.size());
  out[1] = 0x03;  // PL_CDR_LE, no options
  std::copy(bytes_.begin(), bytes_.end(), out.begin() + 4);
  put_u16(out, kPidSentinel);
  put_u16(out, 0);
  return out;
}

RtpsMessage::RtpsMessage(const GuidPrefix& source) {
  bytes_.resize(8 + source.size());
  constexpr std::array<std::uint8_t, 8> kHeader{'R', 'T', 'P', 'S', 2, 1, 0x01, 0x10};  // 2.1, Eclipse Cyclone DDS
  std::copy(kHeader.begin(), kHeader.end(), bytes_.begin());
  std::copy(source.begin(), source.end(), bytes_.begin() + 8);
}

void RtpsMessage::submessage(std::uint8_t id, std::uint8_t flags, const Bytes& body) {
  bytes_.push_back(id);
  bytes_.push_back(static_cast<std::uint8_t>(flags | 0x01));  // little-endian
  put_u16(bytes_, static_cast<std::uint16_t>(body.size()));
  bytes_.insert(bytes_.end(), body.begin(), body.end());
}

RtpsMessage& RtpsMessage::info_timestamp() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  Bytes body;
  put_u32(body, static_cast<std::uint32_t>(std::chrono::duration_cast<std::chrono::seconds>(now).count()));
  put_u32(body, 0);
  submessage(0x09, 0, body);
  return *this;
}

RtpsMessage& RtpsMessage::data(std::uint32_t reader, std::uint32_t writer, std::int64_t sequence,
                               const Bytes& payload) {
  Bytes body;
  put_u16(body, 0);   // extra flags
  put_u16(body, 16);  // octets to inline QoS: right after the sequence number
  put_entity(body, reader);
  put_entity(body, writer);
  put_sequence_number(body, sequence);
  body.insert(body.end(), payload.begin(), payload.end());
  body.resize((body.size() + 3) & ~std::size_t{3}, 0);
  submessage(0x15, 0x04, body);  // DATA with data
  return *this;
}

RtpsMessage& RtpsMessage::heartbeat(std::uint32_t reader, std::uint32_t writer, std::int64_t first, std::int64_t last,
                                    std::uint32_t count) {
  Bytes body;
  put_entity(body, reader);
  put_entity(body, writer);
  put_sequence_number(body, first);
  put_sequence_number(body, last);
  put_u32(body, count);
  submessage(0x07, 0, body);
  return *this;
}

Bytes participant_announcement(const GuidPrefix& prefix, std::uint16_t port, std::int32_t lease_seconds) {
  ParameterList list;
  list.add(kPidProtocolVersion, {2, 1})
      .add(kPidVendorId, {0x01, 0x10})
      .add_guid(kPidParticipantGuid, prefix, kParticipantEntity)
      .add_u32(kPidBuiltinEndpointSet, kBuiltinEndpoints)
      .add_locator(kPidMetatrafficUnicastLocator, port)
      .add_locator(kPidDefaultUnicastLocator, port)
      .add_duration(kPidParticipantLeaseDuration, lease_seconds);
  return list.payload();
}

Bytes endpoint_announcement(const GuidPrefix& prefix, std::uint32_t entity, const std::string& topic,
                            const std::string& type_name, const Bytes& type_information) {
  ParameterList list;
  Bytes reliable;
  put_u32(reliable, 2);  // RELIABLE
  put_u32(reliable, 0);
  put_u32(reliable, 100'000'000);
  Bytes representation;
  put_u32(representation, 2);
  put_u16(representation, 0);  // XCDR1
  put_u16(representation, 2);  // XCDR2
  list.add_guid(kPidEndpointGuid, prefix, entity)
      .add_string(kPidTopicName, topic)
      .add_string(kPidTypeName, type_name)
      .add(kPidReliability, reliable)
      .add(kPidDataRepresentation, representation);
  if (!type_information.empty()) list.add(kPidTypeInformation, type_information);
  return list.payload();
}

Bytes damaged(const Bytes& payload, std::mt19937_64& random) {
  Bytes out = payload;
  const auto anywhere = [&](std::size_t from) {
    return from + static_cast<std::size_t>(random() % std::max<std::size_t>(1, out.size() - from));
  };
  const int damages = 1 + static_cast<int>(random() % 4);
  for (int d = 0; d < damages && out.size() > 8; ++d) {
    switch (random() % 7) {
      case 0:  // a few bits flipped
        for (int i = 0; i < 1 + static_cast<int>(random() % 8); ++i) {
          out[anywhere(4)] ^= static_cast<std::uint8_t>(1u << (random() % 8));
        }
        break;
      case 1:  // a byte made extreme
        out[anywhere(4)] = (random() % 2) ? 0xff : 0x00;
        break;
      case 2: {  // a type identifier's kind changed (XTypes 7.3.4.2: 0xf1 minimal, 0xf2 complete hashes)
        static constexpr std::uint8_t kKinds[] = {0x00, 0x01, 0x0a, 0x20, 0x70, 0x71, 0x80, 0x81, 0x90,
                                                  0x91, 0xa0, 0xa1, 0xb0, 0xf1, 0xf2, 0x51, 0xff};
        std::vector<std::size_t> at;
        for (std::size_t i = 4; i < out.size(); ++i) {
          if (out[i] == 0xf1 || out[i] == 0xf2) at.push_back(i);
        }
        if (!at.empty()) out[at[random() % at.size()]] = kKinds[random() % std::size(kKinds)];
        break;
      }
      case 3:  // a length or count made huge, small or odd
      {
        const std::size_t i = anywhere(4) & ~std::size_t{3};
        if (i + 4 <= out.size()) {
          static constexpr std::uint32_t kCounts[] = {0, 1, 3, 0x7fffffff, 0xffffffff, 0x10000, 255};
          const std::uint32_t count = kCounts[random() % std::size(kCounts)];
          for (int b = 0; b < 4; ++b)
            out[i + static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(count >> (8 * b));
        }
        break;
      }
      case 4:  // cut short
        out.resize(4 + anywhere(4) % (out.size() - 4 + 1));
        break;
      case 5: {  // random bytes appended or inserted
        Bytes noise(random() % 64);
        for (auto& b : noise) b = static_cast<std::uint8_t>(random());
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(anywhere(4)), noise.begin(), noise.end());
        break;
      }
      default:  // a random parameter in front, of any id and a length that may lie
      {
        Bytes parameter;
        put_u16(parameter, static_cast<std::uint16_t>(random()));
        const std::uint16_t length = static_cast<std::uint16_t>(random() % 96);
        put_u16(parameter, length);
        for (std::uint16_t i = 0; i < length; ++i) parameter.push_back(static_cast<std::uint8_t>(random()));
        out.insert(out.begin() + 4, parameter.begin(), parameter.end());
        break;
      }
    }
  }
  return out;
}

}  // namespace dem::probe
