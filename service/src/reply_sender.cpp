#include "dem/service/reply_sender.h"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"
#include "dem/protocol/type_support.h"

namespace dem::service {

ReplySender::ReplySender(const dds::Participant& participant, std::string server_name, std::uint32_t contact_chunk,
                         std::uint32_t data_chunk)
    : server_name_(std::move(server_name)),
      contact_chunk_(std::max<std::uint32_t>(contact_chunk, 1)),
      data_chunk_(std::max<std::uint32_t>(data_chunk, 1)),
      topic_(participant, protocol::topic_name(server_name_, protocol::TopicKind::kReply)),
      writer_(participant, topic_, protocol::reply_qos()),
      keyless_topic_(participant, topic_.name(), dds::Keys::kNone),
      keyless_writer_(participant, keyless_topic_, protocol::reply_qos()) {}

void ReplySender::send(const ReceivedCommand& received, protocol::Reply reply) {
  const protocol::Command& command = received.command;
  reply.server = server_name_;
  reply.client_id = command.client_id;
  reply.request_id = command.request_id;
  reply.kind = command.kind;
  reply.duration = std::chrono::duration<double>(std::chrono::steady_clock::now() - received.arrived).count();
  reply.stamp = protocol::now_stamp();

  const auto kind = protocol::command_kind(command.kind);
  const std::string_view kind_name = kind ? protocol::to_string(*kind) : "unknown";
  const auto log_level =
      reply.ok() || reply.status == protocol::ReplyStatus::kCancelled ? spdlog::level::info : spdlog::level::warn;
  spdlog::log(log_level, "replied to request {} from {}: {} -> {} in {:.3f} s: {}", command.request_id,
              command.client_id, kind_name, protocol::to_string(reply.status), reply.duration, reply.message);

  const std::uint32_t contact_chunk = command.query.chunk_size > 0 ? command.query.chunk_size : contact_chunk_;
  if (reply.contacts.size() <= contact_chunk && reply.data.size() <= data_chunk_) {
    reply.chunk = 0;
    reply.last = true;
    write(reply);
    return;
  }
  // Split the payload; every chunk repeats the small fields, so any one of
  // them says what the reply is about.
  std::vector<protocol::ContactEntry> contacts = std::move(reply.contacts);
  std::string data = std::move(reply.data);
  std::size_t next_contact = 0;
  std::size_t next_byte = 0;
  for (std::uint32_t chunk = 0;; ++chunk) {
    const std::size_t contact_end = std::min(contacts.size(), next_contact + contact_chunk);
    const std::size_t byte_end = std::min(data.size(), next_byte + data_chunk_);
    reply.contacts.assign(contacts.begin() + static_cast<std::ptrdiff_t>(next_contact),
                          contacts.begin() + static_cast<std::ptrdiff_t>(contact_end));
    reply.data.assign(data, next_byte, byte_end - next_byte);
    next_contact = contact_end;
    next_byte = byte_end;
    reply.chunk = chunk;
    reply.last = next_contact == contacts.size() && next_byte == data.size();
    write(reply);
    if (reply.last) return;
    // The writer keeps the last 256 samples of each client (protocol/src/qos.cpp): every
    // 32 chunks, let the readers catch up - for at most 2 s, as a stalled
    // reader never does.
    if ((chunk + 1) % 32 == 0) {
      writer_.wait_for_acks(std::chrono::seconds(2));
      if (keyless_writer_.matched_readers() > 0) keyless_writer_.wait_for_acks(std::chrono::seconds(2));
    }
  }
}

void ReplySender::write(protocol::Reply& reply) {
  if (!writer_.write(reply)) {
    spdlog::error("reply to request {} from {} given up: the client did not take it in time", reply.request_id,
                  reply.client_id);
  }
  // A ROS 2 node's keyless reader: its replies keep the one history of 256
  // for all such readers together (protocol/src/qos.cpp).
  if (keyless_writer_.matched_readers() > 0 && !keyless_writer_.write(reply)) {
    spdlog::error("reply to request {} from {} given up for keyless readers: one did not take it in time",
                  reply.request_id, reply.client_id);
  }
}

bool ReplySender::flush(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  const bool keyed = writer_.wait_for_acks(timeout);
  const auto left = std::max(std::chrono::nanoseconds(0), deadline - std::chrono::steady_clock::now());
  return keyless_writer_.wait_for_acks(left) && keyed;
}

}  // namespace dem::service
