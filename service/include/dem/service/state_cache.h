// What the reception thread may answer without the engine thread: the
// server's status and, with a world loaded, the get_state reply as of the
// engine's last chunk boundary (at most one chunk, about 20 ms, old; the
// reply's cycle says when). The engine thread publishes it between chunks
// and after every command; get_state is then answered at once, without
// waiting for the chunk boundary (docs/RELIABILITY.md). It also counts the
// commands answered by either thread.
#pragma once

#include <atomic>
#include <mutex>
#include <optional>

#include "dem/protocol/messages.h"

namespace dem::service {

class StateCache {
 public:
  // Engine thread: get_state's reply now (its `state` the status).
  void publish(protocol::Reply get_state);
  // Nothing before the first publish. A client whose command the cache
  // does not show yet is kept from it by CommandQueue::pending: the engine
  // thread marks such commands done only after its next publish.
  std::optional<protocol::Reply> get_state() const;

  // Every reply sent counts one, from either thread.
  std::uint64_t count_reply() { return ++served_; }
  std::uint64_t served() const { return served_.load(); }

 private:
  mutable std::mutex mutex_;
  std::optional<protocol::Reply> get_state_;
  std::atomic<std::uint64_t> served_{0};
};

}  // namespace dem::service
