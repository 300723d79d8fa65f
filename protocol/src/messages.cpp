#include "dem/protocol/messages.h"

#include <chrono>

namespace dem::protocol {

Stamp now_stamp() {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(since_epoch);
  const auto nanoseconds = std::chrono::duration_cast<std::chrono::nanoseconds>(since_epoch - seconds);
  return {static_cast<std::int32_t>(seconds.count()), static_cast<std::uint32_t>(nanoseconds.count())};
}

}  // namespace dem::protocol
