// Software prefetches, of single lines and over whole address ranges, for
// the force pass on large beds (contact_batch.h, and the set-aside shares
// in contact_forces.cpp), where what it needs next lies farther ahead than
// the hardware's prefetchers look.
#pragma once

#include <cstdint>

namespace dem {

// How long a fetched line is worth keeping: through every cache level
// (read again soon), or only in the first-level cache and not handed down
// to the others when it leaves (prefetchnta: read once a step, so that it
// does not push out of the shared cache what is read again).
enum class Keep { kReused = 3, kOnce = 0 };

// Fetches the cache line that holds `address`.
template <Keep kKeep = Keep::kReused>
inline void fetch_line(const void* address) {
  __builtin_prefetch(address, 0, static_cast<int>(kKeep));
}

// Fetches every cache line of [from, to).
template <Keep kKeep>
inline void fetch_lines(const void* from, const void* to) {
  constexpr std::uintptr_t kLine = 64;
  const auto end = reinterpret_cast<std::uintptr_t>(to);
  for (auto line = reinterpret_cast<std::uintptr_t>(from) & ~(kLine - 1); line < end; line += kLine) {
    fetch_line<kKeep>(reinterpret_cast<const void*>(line));
  }
}

}  // namespace dem
