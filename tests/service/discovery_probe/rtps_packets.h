// Hand-made RTPS discovery messages (DDSI-RTPS 2.5, sections 8.3 and 9.4;
// the participant and endpoint parameters of 9.6.2) for the discovery
// probe: the announcement of a participant that exists only in these
// bytes, and of its readers and writers on the server's topics - valid,
// then damaged in the ways a broken or hostile peer's would be.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace dem::probe {

using Bytes = std::vector<std::uint8_t>;
using GuidPrefix = std::array<std::uint8_t, 12>;

// Entity ids of the built-in endpoints (9.3.1.3) and the type-lookup service (XTypes 7.6.3.3.4).
inline constexpr std::uint32_t kParticipantEntity = 0x000001c1;
inline constexpr std::uint32_t kSpdpWriter = 0x000100c2;
inline constexpr std::uint32_t kSpdpReader = 0x000100c7;
inline constexpr std::uint32_t kPublicationsWriter = 0x000003c2;
inline constexpr std::uint32_t kPublicationsReader = 0x000003c7;
inline constexpr std::uint32_t kSubscriptionsWriter = 0x000004c2;
inline constexpr std::uint32_t kSubscriptionsReader = 0x000004c7;

// A parameter list (PL_CDR_LE), ended by sentinel().
class ParameterList {
 public:
  ParameterList& add(std::uint16_t pid, const Bytes& value);
  ParameterList& add_u32(std::uint16_t pid, std::uint32_t value);
  ParameterList& add_string(std::uint16_t pid, const std::string& text);
  ParameterList& add_guid(std::uint16_t pid, const GuidPrefix& prefix, std::uint32_t entity);
  ParameterList& add_locator(std::uint16_t pid, std::uint16_t port);  // UDPv4 127.0.0.1
  ParameterList& add_duration(std::uint16_t pid, std::int32_t seconds);
  // Ends the list; the payload with its encapsulation header (PL_CDR_LE).
  Bytes payload() const;

 private:
  Bytes bytes_;
};

// One RTPS message from `source`: a header, then submessages.
class RtpsMessage {
 public:
  explicit RtpsMessage(const GuidPrefix& source);
  RtpsMessage& info_timestamp();
  RtpsMessage& data(std::uint32_t reader, std::uint32_t writer, std::int64_t sequence, const Bytes& payload);
  RtpsMessage& heartbeat(std::uint32_t reader, std::uint32_t writer, std::int64_t first, std::int64_t last,
                         std::uint32_t count);
  const Bytes& bytes() const { return bytes_; }

 private:
  void submessage(std::uint8_t id, std::uint8_t flags, const Bytes& body);
  Bytes bytes_;
};

// The announcement (SPDP) of a participant at `prefix` that offers SEDP
// and the type-lookup service, reached at 127.0.0.1:`port`, with a lease of
// `lease_seconds`.
Bytes participant_announcement(const GuidPrefix& prefix, std::uint16_t port, std::int32_t lease_seconds);

// The announcement (SEDP) of a writer or reader `entity` of `prefix` on a
// topic, with `type_information` (XTypes 7.6.3.2.2; empty: none).
Bytes endpoint_announcement(const GuidPrefix& prefix, std::uint32_t entity, const std::string& topic,
                            const std::string& type_name, const Bytes& type_information);

// A parameter list damaged at random: bytes flipped, a parameter's length
// made wrong, a parameter added with random content, the list cut short
// or extended, a string without its end. Keeps the encapsulation header
// mostly, so the receiver parses into the damage.
Bytes damaged(const Bytes& payload, std::mt19937_64& random);

}  // namespace dem::probe
