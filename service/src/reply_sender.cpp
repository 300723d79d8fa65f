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
      keyless_writer_(participant, keyless_topic_, protocol::reply_qos()),
      participant_(participant) {}

namespace {
// Own writers at most: beyond, new clients' replies go by the shared writer.
constexpr std::size_t kMaxOwnWriters = 256;
// An own writer whose client's reader never matched it is dropped after this.
constexpr auto kUnmatchedLifetime = std::chrono::seconds(30);
}  // namespace

std::shared_ptr<ReplySender::OwnWriter> ReplySender::own_writer(const std::string& client) {
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard lock(own_mutex_);
  if (now - last_sweep_ > std::chrono::seconds(1)) forget_departed_clients(now);
  const auto found = own_writers_.find(client);
  if (found != own_writers_.end()) {
    // Read each time: a client that connects again under the same id has
    // a new reader, which the writer may not have matched yet.
    OwnWriter& own = *found->second;
    if (own.writer.matched_readers() > 0) {
      own.matched = true;
      return found->second;
    }
  } else if (own_writers_.size() < kMaxOwnWriters && !own_writers_refused_) {
    try {
      own_writers_.emplace(
          client, std::make_shared<OwnWriter>(
                      OwnWriter{dds::Writer<protocol::Reply>(
                                    participant_, topic_,
                                    dds::Qos(protocol::reply_qos()).partitions({protocol::reply_partition(client)})),
                                now, false}));
    } catch (const dds::DdsError& error) {
      if (error.code() != DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) throw;
      // Permissions without a <partitions> rule grant the default partition alone.
      own_writers_refused_ = true;
      spdlog::info("replies go by the shared writer alone: the DDS Security permissions grant no partition {}",
                   protocol::reply_partition(client));
    }
  }
  return nullptr;
}

void ReplySender::forget_departed_clients(std::chrono::steady_clock::time_point now) {
  last_sweep_ = now;
  std::erase_if(own_writers_, [&](const auto& entry) {
    const OwnWriter& own = *entry.second;
    const bool present = own.writer.matched_readers() > 0;
    return own.matched ? !present : !present && now - own.made > kUnmatchedLifetime;
  });
}

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

  const std::shared_ptr<OwnWriter> own = own_writer(command.client_id);
  dds::Writer<protocol::Reply>& writer = own ? own->writer : writer_;
  const std::uint32_t contact_chunk = command.query.chunk_size > 0 ? command.query.chunk_size : contact_chunk_;
  if (reply.contacts.size() <= contact_chunk && reply.data.size() <= data_chunk_) {
    reply.chunk = 0;
    reply.last = true;
    write(writer, reply);
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
    write(writer, reply);
    if (reply.last) return;
    // The writer keeps the last 256 samples of each client (protocol/src/qos.cpp): every
    // 32 chunks, let the readers catch up - for at most 2 s, as a stalled
    // reader never does.
    if ((chunk + 1) % 32 == 0) {
      writer.wait_for_acks(std::chrono::seconds(2));
      if (keyless_writer_.matched_readers() > 0) keyless_writer_.wait_for_acks(std::chrono::seconds(2));
    }
  }
}

void ReplySender::write(dds::Writer<protocol::Reply>& writer, protocol::Reply& reply) {
  if (!writer.write(reply)) {
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
  const auto left = [&] { return std::max(std::chrono::nanoseconds(0), deadline - std::chrono::steady_clock::now()); };
  bool all = writer_.wait_for_acks(timeout);
  all = keyless_writer_.wait_for_acks(left()) && all;
  std::lock_guard lock(own_mutex_);
  for (const auto& [client, own] : own_writers_) all = own->writer.wait_for_acks(left()) && all;
  return all;
}

}  // namespace dem::service
