#include "dem/service/command_receiver.h"

#include <spdlog/spdlog.h>

#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"
#include "dem/protocol/type_support.h"

namespace dem::service {

namespace {
constexpr std::intptr_t kData = 1;
constexpr std::intptr_t kWake = 2;
}  // namespace

CommandReceiver::CommandReceiver(const dds::Participant& participant, std::string server_name, CommandQueue& queue,
                                 ReplySender& replies, StateCache& cache)
    : server_name_(std::move(server_name)),
      queue_(queue),
      replies_(replies),
      cache_(cache),
      topic_(participant, protocol::topic_name(server_name_, protocol::TopicKind::kCommand)),
      reader_(participant, topic_, protocol::command_qos()),
      data_(reader_.handle()),
      wake_(participant),
      waitset_(participant) {
  waitset_.attach(data_, kData);
  waitset_.attach(wake_, kWake);
}

CommandReceiver::~CommandReceiver() { stop(); }

void CommandReceiver::start() {
  running_ = true;
  thread_ = std::thread([this] { receive_loop(); });
}

void CommandReceiver::stop() {
  if (!thread_.joinable()) return;
  running_ = false;
  wake_.trigger();
  thread_.join();
}

void CommandReceiver::receive_loop() {
  using namespace std::chrono_literals;
  while (running_) {
    try {
      waitset_.wait(1s);  // the guard condition ends the wait at stop()
      for (dds::Received<protocol::Command>& sample : reader_.take_with_writers()) {
        protocol::Command& command = sample.value;
        const auto arrived = std::chrono::steady_clock::now();
        if (command.server != server_name_) {
          ++ignored_;
          spdlog::debug("ignored request {} from {}: addressed to server \"{}\"", command.request_id, command.client_id,
                        command.server);
          continue;
        }
        const auto kind = protocol::command_kind(command.kind);
        const std::string what =
            kind ? std::string(protocol::to_string(*kind)) : "unknown kind " + std::to_string(command.kind);
        spdlog::info("received request {} from {}: {}", command.request_id, command.client_id, what);
        ReceivedCommand received{std::move(command), arrived, sample.writer};
        if (answer_here(received)) continue;
        if (!queue_.push(received)) {
          protocol::Reply busy;
          busy.status = protocol::ReplyStatus::kBusy;
          busy.message = "busy: the server's command queue is full (" + std::to_string(queue_.capacity()) +
                         " commands, --queue-capacity); send it again later";
          if (const auto state = cache_.get_state()) busy.state = state->state;
          busy.state.commands_served = cache_.count_reply();
          replies_.send(received, std::move(busy));
        }
      }
    } catch (const std::exception& error) {
      // A DDS failure here must not end reception for good; say so and go on.
      spdlog::error("receiving commands: {}", error.what());
      std::this_thread::sleep_for(100ms);
    }
  }
}

bool CommandReceiver::writer_alive(std::uint64_t writer) const {
  try {
    return reader_.writer_matched(writer);
  } catch (const std::exception&) {
    return true;  // when DDS cannot say, the run keeps its owner
  }
}

bool CommandReceiver::answer_here(const ReceivedCommand& received) {
  const protocol::Command& command = received.command;
  if (command.kind != static_cast<std::uint8_t>(protocol::CommandKind::kGetState)) return false;
  if (queue_.shutdown_requested() || queue_.pending(command.client_id) > 0) return false;
  std::optional<protocol::Reply> reply = cache_.get_state();
  if (!reply) return false;
  reply->state.commands_served = cache_.count_reply();
  replies_.send(received, std::move(*reply));
  return true;
}

}  // namespace dem::service
