// What one command may ask of a server (docs/RELIABILITY.md): how many
// cycles, how many bytes of case or snapshot, how large a contact query,
// how long a name or path. check_command refuses a command beyond them
// before anything runs, naming the field and the limit.
#pragma once

#include <cstdint>

#include "dem/protocol/messages.h"

namespace dem::service {

struct CommandLimits {
  // cycle's cycles and run_until's max_cycles: about six days at 2,000
  // cycles a second. One command may not hold the server longer.
  std::uint64_t max_cycles = 1'000'000'000;
  // A case's text or bytes, a transferred snapshot's bytes.
  std::uint64_t max_payload_bytes = 256ull << 20;
  // Contacts one query may return (about 100 bytes each on the wire); a
  // larger result must be narrowed by wall, box or force.
  std::uint64_t max_query_contacts = 2'000'000;
  // Contacts in one reply chunk a client may ask for.
  std::uint32_t max_chunk_contacts = 100'000;
  // Any name, path or identifier in a command.
  std::uint64_t max_text_bytes = 4096;
};

// Throws CommandError (BAD_REQUEST) for what is wrong with a command's
// arguments whatever the world: an unknown kind, counts and sizes beyond
// `limits`, numbers that are not finite or beyond what the force
// arithmetic carries (1e30). The checks that need the world (a wall's
// name, a material) stay with the command.
void check_command(const protocol::Command& command, const CommandLimits& limits);

}  // namespace dem::service
