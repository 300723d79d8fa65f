// Commands on their way from the DDS reception thread to the engine
// thread, in arrival order, and the request to shut down (from a signal or
// the shutdown command). The only state the two threads share.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <vector>

#include "dem/protocol/messages.h"

namespace dem::service {

struct ReceivedCommand {
  protocol::Command command;
  std::chrono::steady_clock::time_point arrived;  // replies report the time from here
};

class CommandQueue {
 public:
  void push(ReceivedCommand command);
  // The next command; waits up to `timeout` for one. Returns nothing on
  // timeout, or at once when a shutdown is requested.
  std::optional<ReceivedCommand> pop(std::chrono::milliseconds timeout);
  // Everything queued, without waiting.
  std::vector<ReceivedCommand> take_all();

  void request_shutdown();
  bool shutdown_requested() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<ReceivedCommand> commands_;
  bool shutdown_ = false;
};

}  // namespace dem::service
