// The DDS reception thread: takes commands from rt/dem/<server>/command as
// they arrive, ignores those addressed to another server, logs the rest and
// queues them for the engine thread. It never touches the simulation: a
// get_state from a client with nothing queued it answers at once from the
// StateCache, and a command the full queue cannot take it answers "busy".
#pragma once

#include <atomic>
#include <string>
#include <thread>

#include "dem/dds/topic.h"
#include "dem/dds/waitset.h"
#include "dem/protocol/messages.h"
#include "dem/protocol/type_support.h"
#include "dem/service/command_queue.h"
#include "dem/service/reply_sender.h"
#include "dem/service/state_cache.h"

namespace dem::service {

class CommandReceiver {
 public:
  CommandReceiver(const dds::Participant& participant, std::string server_name, CommandQueue& queue,
                  ReplySender& replies, StateCache& cache);
  ~CommandReceiver();  // stops and joins the thread
  CommandReceiver(const CommandReceiver&) = delete;
  CommandReceiver& operator=(const CommandReceiver&) = delete;

  void start();
  void stop();
  std::uint64_t ignored() const { return ignored_.load(); }  // commands for other servers
  // Whether the writer a command came from is still on the domain (any thread).
  bool writer_alive(std::uint64_t writer) const;

 private:
  void receive_loop();
  // Answers a command here, when it may be; false when the engine thread must.
  bool answer_here(const ReceivedCommand& received);

  std::string server_name_;
  CommandQueue& queue_;
  ReplySender& replies_;
  StateCache& cache_;
  dds::Topic<protocol::Command> topic_;
  dds::Reader<protocol::Command> reader_;
  dds::ReadCondition data_;
  dds::GuardCondition wake_;
  dds::WaitSet waitset_;
  std::atomic<bool> running_{false};
  std::atomic<std::uint64_t> ignored_{0};
  std::thread thread_;
};

}  // namespace dem::service
