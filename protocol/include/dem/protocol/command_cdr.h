// Commands (and any other message) as the bytes that travel in a DDS sample: the 4-byte CDR
// encapsulation header (CDR_BE, CDR_LE, CDR2_BE or CDR2_LE) and the
// serialized Command_. Decoding takes the path Cyclone DDS takes for every
// sample it receives - the data normalized (validated) against the type's
// serialization ops, then read into the generated C struct - and then
// TypeSupport's conversion, so it is the server's command decoder, callable
// without a network: the fuzz target (tests/fuzz) feeds it any bytes.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "dem/protocol/messages.h"

namespace dem::protocol {

// Little-endian XCDR1 (CDR_LE), as Cyclone writes by default.
std::string encode_command(const Command& command);

// The command, or nothing when the bytes are not a valid serialized Command_
// (Cyclone would drop such a sample before any reader saw it).
std::optional<Command> decode_command(std::string_view bytes);

// The same for any message (dem/protocol/messages.h).
template <Message T>
std::string encode_cdr(const T& message);
template <Message T>
std::optional<T> decode_cdr(std::string_view bytes);

}  // namespace dem::protocol
