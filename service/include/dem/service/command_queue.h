// Commands on their way from the DDS reception thread to the engine
// thread, in arrival order, and the request to shut down (from a signal or
// the shutdown command). The only state the two threads share besides the
// StateCache. The queue is bounded: a command beyond its capacity is not
// queued (the receiver answers it "busy"), so a flood of commands cannot
// grow the server's memory or the wait of everyone behind it. It also
// counts each client's commands not yet done, so a read-only command may
// skip the queue only when that client has nothing in it (a client always
// sees its own earlier commands done).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "dem/protocol/messages.h"

namespace dem::service {

struct ReceivedCommand {
  protocol::Command command;
  std::chrono::steady_clock::time_point arrived;  // replies report the time from here
  // The DDS writer it came from (its publication handle): who started a
  // run, as DDS knows it rather than by the client id it claims; 0 when
  // not from DDS (the one-shot programme).
  std::uint64_t writer = 0;
};

class CommandQueue {
 public:
  explicit CommandQueue(std::size_t capacity = 1024) : capacity_(capacity) {}

  // Queues the command; false, leaving it out, when the queue is full.
  bool push(ReceivedCommand command);
  // The next command; waits up to `timeout` for one. Returns nothing on
  // timeout, or at once when a shutdown is requested.
  std::optional<ReceivedCommand> pop(std::chrono::milliseconds timeout);
  // Everything queued, without waiting.
  std::vector<ReceivedCommand> take_all();
  // Puts commands taken but not yet done back in front, in their order
  // (they are still pending, and may exceed the capacity).
  void put_back(std::vector<ReceivedCommand> commands);

  // A command taken from the queue has been done (its reply sent, or for a
  // cycle, run_until or run_programme, it has started).
  void done(const std::string& client);
  // The client's commands queued or being done.
  std::size_t pending(const std::string& client) const;

  std::size_t capacity() const { return capacity_; }

  void request_shutdown();
  bool shutdown_requested() const;

 private:
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<ReceivedCommand> commands_;
  std::map<std::string, std::size_t, std::less<>> pending_;
  bool shutdown_ = false;
};

}  // namespace dem::service
