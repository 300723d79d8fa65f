// The service's messages as plain C++ values: what dem_server and its
// clients read and write. They are generated at build time from the IDL,
// idl/dem/*.idl, the one definition of every field (protocol/
// generate_messages.py; the header is <build>/protocol/generated/include/
// dem/protocol/message_types.h): each IDL struct <Name>_ is a struct here,
// member for member, with these departures, listed in the generator's
// tables:
//   - builtin_interfaces Time_ is Stamp, and the arguments of each command
//     kind are <Kind>Args (LoadCaseArgs, RunUntilArgs, ...);
//   - Status.state is a ServerState and Reply.status a ReplyStatus (the
//     <Name>_Constants modules as enums, with to_string and a checked
//     conversion from the wire value: command_kind(), server_state(), ...);
//     Status.state_name is written from state and not kept;
//   - a flag and the value it marks as set (run_until's stress_set and
//     stress, ...) are one std::optional;
//   - sequence<octet> is a std::string of bytes;
//   - ids default to -1 (none) and Reply.last to true.
// Fields<T> lists every member of a message (name, member pointer, the
// IDL's comment). protocol/src/type_support.cpp converts the messages to
// and from the C structs idlc generates (the only code that sees those).
// Units are SI; in 2D, forces are per unit depth and vectors have z = 0
// (spins are about z).
#pragma once

#include "dem/protocol/message_types.h"

namespace dem::protocol {

// Wall-clock time now.
Stamp now_stamp();

}  // namespace dem::protocol
