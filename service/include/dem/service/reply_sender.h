// Replies on rt/dem/<server>/reply: each command gets exactly one, addressed
// to its client (split into chunks - a sequence number and a last flag -
// when it carries many contacts or a snapshot's bytes). Every reply is
// logged with its status and how long the command took.
//
// The reply is keyed by client (idl/dem/command.idl) and reaches the
// project's clients, whose readers are keyed. A ROS 2 node's reader knows
// the type without its key, and Cyclone matches keyless readers with
// keyless writers only: a second writer, of the type without its key, sends
// the replies to such readers - only while one is matched, so the
// project's clients cost nothing more (docs/DDS.md, "Replies to ROS 2
// nodes").
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "dem/dds/topic.h"
#include "dem/protocol/messages.h"
#include "dem/protocol/type_support.h"
#include "dem/service/command_queue.h"

namespace dem::service {

class ReplySender {
 public:
  ReplySender(const dds::Participant& participant, std::string server_name, std::uint32_t contact_chunk,
              std::uint32_t data_chunk);

  // Fills in the addressing (server, client, request id, kind), the duration
  // since the command arrived and the stamp, and sends the reply; contacts
  // and data beyond one chunk go out in several samples. A command's
  // query.chunk_size, when set, replaces the default contact chunk.
  void send(const ReceivedCommand& command, protocol::Reply reply);

  // Waits until the clients acknowledged every reply (at shutdown).
  bool flush(std::chrono::milliseconds timeout);

 private:
  // A client's own reply writer, in its partition (protocol::reply_partition).
  struct OwnWriter {
    dds::Writer<protocol::Reply> writer;
    std::chrono::steady_clock::time_point made;
    bool matched = false;  // its client's reader was matched once
  };

  // The client's own writer once its reader matched it, else none: its
  // replies go by the shared writer (a new client's own writer is made
  // then, for its next replies). Shared, as a sweep may forget it meanwhile.
  std::shared_ptr<OwnWriter> own_writer(const std::string& client);
  void forget_departed_clients(std::chrono::steady_clock::time_point now);
  void write(dds::Writer<protocol::Reply>& writer, protocol::Reply& reply);

  std::string server_name_;
  std::uint32_t contact_chunk_;
  std::uint32_t data_chunk_;
  dds::Topic<protocol::Reply> topic_;
  dds::Writer<protocol::Reply> writer_;
  dds::Topic<protocol::Reply> keyless_topic_;
  dds::Writer<protocol::Reply> keyless_writer_;
  const dds::Participant& participant_;
  std::mutex own_mutex_;  // the reception and engine threads both reply
  std::map<std::string, std::shared_ptr<OwnWriter>> own_writers_;
  std::chrono::steady_clock::time_point last_sweep_;
  bool own_writers_refused_ = false;  // by DDS Security permissions
};

}  // namespace dem::service
