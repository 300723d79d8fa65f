// A connection to one dem_server (docs/SERVICE.md): send a command, await
// its reply, read the server's status. Thread-safe; replies and status are
// received on a thread of the client's own.
//
//   dem::client::Client server({.server = "a", .domain = 42});
//   server.load_case_file("cases/ball/nine_disc_damped.case.txtpb");
//   server.cycle(1000);
//   auto state = server.get_state();
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "dem/client/errors.h"
#include "dem/dds/discovery.h"
#include "dem/dds/instance_filter.h"
#include "dem/dds/participant.h"
#include "dem/dds/topic.h"
#include "dem/dds/waitset.h"
#include "dem/protocol/interface_watch.h"
#include "dem/protocol/messages.h"
#include "dem/protocol/type_support.h"

namespace dem::client {

using namespace std::chrono_literals;

struct ConnectOptions {
  std::string server = "dem";
  std::uint32_t domain = 0;
  std::string dds_config;                         // empty: $CYCLONEDDS_URI, else the repository's loopback-only file
  std::chrono::milliseconds timeout = 5s;         // to find the server
  std::chrono::milliseconds reply_timeout = 60s;  // default wait for a reply (not for cycle, which waits as asked)
  std::string client_id;                          // empty: "<host>-<pid>-<n>"
  // Called at connection with each of interface_notes() (a program tells its user).
  std::function<void(const std::string&)> on_interface_note;
  // Requests sent and not yet answered, at most: send() waits for a reply
  // beyond them. The server keeps the last 256 replies of each client
  // (replies are keyed by client; protocol/src/qos.cpp), so a client at
  // this bound never has a reply pushed out before it was delivered, also
  // while its process falls behind and other clients flood the server
  // (docs/RELIABILITY.md, "No lost reply").
  std::size_t max_outstanding = 64;
};

class Client {
 public:
  // Finds the server (its status) and makes one round trip with it, so the
  // first command cannot be lost to discovery; throws NoSuchServer, or
  // InterfaceMismatch when the server's interface cannot meet this client's.
  explicit Client(ConnectOptions options);
  ~Client();
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  const std::string& server() const { return options_.server; }
  const std::string& client_id() const { return options_.client_id; }
  const ConnectOptions& options() const { return options_; }
  const dds::Participant& participant() const { return participant_; }
  // What discovery said of the server's endpoints at connection, when not
  // all of them are of this client's form (docs/DDS.md, "Evolving the
  // wire"): an older form the client still reads, or telemetry it cannot
  // read. Empty when the server is of this client's interface.
  const std::vector<std::string>& interface_notes() const { return interface_notes_; }

  // Addresses a command (server, client id, a new request id, stamp) and
  // sends it; returns its request id. With max_outstanding requests
  // unanswered it first waits for a reply (stop and shutdown do not wait),
  // up to reply_timeout, then throws ReplyTimeout.
  std::uint64_t send(protocol::Command command);
  // The complete reply to a request (chunks joined); nothing on timeout,
  // when the request stops counting as unanswered.
  std::optional<protocol::Reply> await(std::uint64_t request_id, std::chrono::milliseconds timeout);
  // Requests sent whose reply has not come (nor been given up on).
  std::size_t outstanding() const;
  // send and await. Throws ReplyTimeout, and ServerError for any status
  // but OK (and CANCELLED when `cancelled_is_ok`).
  protocol::Reply call(protocol::Command command, std::optional<std::chrono::milliseconds> timeout = std::nullopt,
                       bool cancelled_is_ok = false);

  // The server's latest status.
  protocol::Status status() const;
  // Waits until the status satisfies `condition`; the status, or nothing on timeout.
  std::optional<protocol::Status> wait_for_status(const std::function<bool(const protocol::Status&)>& condition,
                                                  std::chrono::milliseconds timeout) const;
  // Whether the server is still there (its status writer is matched).
  bool server_alive() const;

  // One call per command; each throws as call() does.
  protocol::Reply load_case_file(const std::filesystem::path& local_file);  // sends the text, named by the file
  protocol::Reply load_case_text(std::string text, std::string source_name = "<text>");
  protocol::Reply load_case_binary(std::string bytes, std::string source_name = "<binary>");
  protocol::Reply load_case_on_server(std::string path);
  protocol::Reply set_wall_velocity(std::string wall, protocol::Vector3 velocity,
                                    protocol::Vector3 angular_velocity = {});
  protocol::Reply set_wall_servo(std::string wall, double target_stress, double gain = 0.0, double max_speed = 0.0);
  // Runs `cycles` cycles and waits for the end (timeout: as long as it takes).
  protocol::Reply cycle(std::int64_t cycles, std::chrono::milliseconds timeout = std::chrono::hours(24));
  std::uint64_t start_cycle(std::int64_t cycles);  // returns at once; await(id) for the end
  protocol::Reply run_until(const protocol::RunUntilArgs& args,
                            std::chrono::milliseconds timeout = std::chrono::hours(24));
  std::uint64_t start_run_until(const protocol::RunUntilArgs& args);
  // Runs the loaded case's stages (all, or from `first_stage`, counted from
  // 1, for `stage_count` stages; 0 = to the last) and waits for the end -
  // or, with `steps`, for the next sample point or stage end, from where a
  // run with steps.resume carries on (docs/SERVICE.md, "Programmes").
  protocol::Reply run_programme(std::uint32_t first_stage = 0, std::uint32_t stage_count = 0,
                                std::chrono::milliseconds timeout = std::chrono::hours(24),
                                const protocol::ProgrammeStepsArgs& steps = {});
  std::uint64_t start_run_programme(std::uint32_t first_stage = 0, std::uint32_t stage_count = 0,
                                    const protocol::ProgrammeStepsArgs& steps = {});
  // `force`: also when another client's run is going on (docs/SERVICE.md).
  protocol::Reply stop(bool force = false);
  protocol::Reply get_state();
  protocol::Reply shutdown(bool force = false);
  protocol::Reply query_contacts(const protocol::ContactQueryArgs& args = {});
  // On the server: a file in its output directory. transfer: the bytes come back in the reply's data.
  protocol::Reply save_snapshot(std::string server_path, bool transfer = false);
  protocol::Reply load_snapshot_on_server(std::string server_path);
  protocol::Reply load_snapshot_bytes(std::string bytes);
  protocol::Reply set_parameter(std::string name, double value, std::string material = {});
  protocol::Reply set_gravity(protocol::Vector3 gravity);

 private:
  static protocol::Command command(protocol::CommandKind kind);
  void receive_loop();
  void take_replies();
  void take_status();
  void connect();
  std::string others_seen() const;  // the servers discovery found, for a NoSuchServer
  // The server's endpoints not of this client's form; throws InterfaceMismatch
  // for those its commands or replies cannot cross when `fatal`.
  std::vector<protocol::PeerVerdict> judge_server(bool fatal);

  ConnectOptions options_;
  dds::Participant participant_;
  protocol::InterfaceWatch interface_watch_;
  std::vector<std::string> interface_notes_;
  dds::Topic<protocol::Command> command_topic_;
  dds::Topic<protocol::Reply> reply_topic_;
  // Replies are keyed by client: the reader keeps this client's alone.
  dds::OwnInstanceFilter own_replies_;
  dds::Topic<protocol::Status> status_topic_;
  dds::Writer<protocol::Command> command_writer_;
  dds::Reader<protocol::Reply> reply_reader_;
  dds::Reader<protocol::Status> status_reader_;
  dds::ReadCondition reply_data_;
  dds::ReadCondition status_data_;
  dds::GuardCondition wake_;
  dds::WaitSet waitset_;

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::map<std::uint64_t, protocol::Reply> partial_;   // replies whose last chunk has not come
  std::map<std::uint64_t, protocol::Reply> complete_;  // replies nobody has awaited yet
  std::set<std::uint64_t> outstanding_;                // requests sent, their reply not complete
  std::optional<protocol::Status> status_;
  std::uint64_t next_request_ = 1;
  bool stopping_ = false;
  std::thread receiver_;
};

struct ServerInfo {
  std::string name;
  std::optional<protocol::Status> status;  // nothing when it did not arrive in time
};

// The names of the servers among these publications: the writers of a
// Status on rt/dem/<name>/status.
std::set<std::string> server_names(const std::vector<dds::Publication>& publications);

// The servers alive on a domain: those whose status topic has a writer,
// found through DDS discovery within `discovery` and read from their
// (durable) status topic.
std::vector<ServerInfo> list_servers(std::uint32_t domain, const std::string& dds_config = {},
                                     std::chrono::milliseconds discovery = 1500ms);

}  // namespace dem::client
