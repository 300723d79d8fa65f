#include "dem/client/client.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>

#include "dem/client/local_file.h"
#include "dem/dds/discovery.h"
#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"

namespace dem::client {

using protocol::CommandKind;
using protocol::TopicKind;

namespace {

constexpr std::intptr_t kReplies = 1;
constexpr std::intptr_t kStatus = 2;
constexpr std::intptr_t kWake = 3;

std::string seconds(std::chrono::milliseconds duration) {
  std::ostringstream out;
  out << std::chrono::duration<double>(duration).count() << " s";
  return out.str();
}

// "<host>-<pid>-<n>": unique among the clients of a domain.
std::string make_client_id() {
  static std::atomic<int> counter{0};
  char host[64] = {};
  gethostname(host, sizeof host - 1);
  std::string id;
  for (const char* c = host; *c != '\0'; ++c) id += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
  return id + "-" + std::to_string(getpid()) + "-" + std::to_string(++counter);
}

// The reply reader reads in the default partition, where the server's
// shared writer sends a client's first replies, and in the client's own,
// where its writer of this client's replies alone sends the rest (docs/DDS.md,
// "Replies"). DDS Security permissions without a <partitions> rule grant
// the default partition alone: then the reader reads there only, and gets
// its replies from the shared writer among everyone's.
dds::Reader<protocol::Reply> make_reply_reader(const dds::Participant& participant,
                                               const dds::Topic<protocol::Reply>& topic, const std::string& client_id) {
  try {
    return dds::Reader<protocol::Reply>(
        participant, topic,
        dds::Qos(protocol::reply_reader_qos()).partitions({"", protocol::reply_partition(client_id)}));
  } catch (const dds::DdsError& error) {
    if (error.code() != DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) throw;
    return dds::Reader<protocol::Reply>(participant, topic, protocol::reply_reader_qos());
  }
}

ConnectOptions checked(ConnectOptions options) {
  if (!protocol::valid_server_name(options.server)) {
    throw std::invalid_argument("\"" + options.server +
                                "\" is not a server name (a letter, then letters, digits or underscores)");
  }
  if (options.client_id.empty()) options.client_id = make_client_id();
  return options;
}

}  // namespace

Client::Client(ConnectOptions options)
    : options_(checked(std::move(options))),
      participant_(options_.domain, options_.dds_config),
      interface_watch_(participant_, protocol::topics_of(options_.server), "this client"),
      command_topic_(participant_, protocol::topic_name(options_.server, TopicKind::kCommand)),
      reply_topic_(participant_, protocol::topic_name(options_.server, TopicKind::kReply)),
      own_replies_(reply_topic_.handle()),
      status_topic_(participant_, protocol::topic_name(options_.server, TopicKind::kStatus)),
      command_writer_(participant_, command_topic_, protocol::command_qos()),
      reply_reader_(make_reply_reader(participant_, reply_topic_, options_.client_id)),
      status_reader_(participant_, status_topic_, protocol::status_qos()),
      reply_data_(reply_reader_.handle()),
      status_data_(status_reader_.handle()),
      wake_(participant_),
      waitset_(participant_) {
  waitset_.attach(reply_data_, kReplies);
  waitset_.attach(status_data_, kStatus);
  waitset_.attach(wake_, kWake);
  receiver_ = std::thread([this] { receive_loop(); });
  try {
    connect();
  } catch (...) {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.trigger();
    receiver_.join();
    throw;
  }
}

Client::~Client() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.trigger();
  if (receiver_.joinable()) receiver_.join();
}

void Client::connect() {
  const auto deadline = std::chrono::steady_clock::now() + options_.timeout;
  const auto remaining = [&] {
    return std::max(0ms,
                    std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()));
  };
  const std::string where = "server \"" + options_.server + "\" on DDS domain " + std::to_string(options_.domain);
  // The server's durable status says it is there.
  const auto status = wait_for_status([](const protocol::Status&) { return true; }, remaining());
  if (!status) {
    judge_server(true);  // a server there whose status this client cannot read
    throw NoSuchServer("no " + where + " within " + seconds(options_.timeout) + "; " + others_seen());
  }
  if (status->state == protocol::ServerState::kShutdown) throw NoSuchServer(where + " is shutting down");
  // One round trip: the server has then matched this client both ways, so
  // no later command or reply is lost to discovery. A ping sent before the
  // server's reader matched this writer is lost; send another, with more
  // patience each time, and take the first answer.
  std::set<std::uint64_t> pings;
  for (auto patience = 100ms; remaining() > 0ms; patience = std::min(patience * 2, 2000ms)) {
    if (command_writer_.matched_readers() > 0) pings.insert(send(command(CommandKind::kGetState)));
    std::unique_lock lock(mutex_);
    const bool answered = changed_.wait_for(lock, std::min(patience, remaining()), [&] {
      return std::any_of(pings.begin(), pings.end(), [&](std::uint64_t id) { return complete_.count(id) > 0; });
    });
    if (answered) {
      // The pings sent before the server's reader matched were lost: they
      // wait for no reply.
      for (const std::uint64_t id : pings) {
        complete_.erase(id);
        outstanding_.erase(id);
      }
      lock.unlock();
      for (const protocol::PeerVerdict& verdict : judge_server(false)) {
        interface_notes_.push_back(verdict.text);
        if (options_.on_interface_note) options_.on_interface_note(verdict.text);
      }
      return;
    }
  }
  judge_server(true);  // its commands or replies of a form this client's cannot read
  throw NoSuchServer(where + " was found but did not answer within " + seconds(options_.timeout));
}

std::vector<protocol::PeerVerdict> Client::judge_server(bool fatal) {
  using Kind = protocol::PeerVerdict::Kind;
  const std::string command_topic = protocol::topic_name(options_.server, TopicKind::kCommand);
  std::vector<protocol::PeerVerdict> verdicts;
  std::string fatal_text;
  for (protocol::PeerVerdict& verdict : interface_watch_.check()) {
    // The server's endpoints: the command topic's reader, every other topic's
    // writers (other clients read those and write commands).
    const bool servers = verdict.peer.writer != (verdict.peer.topic_name == command_topic);
    if (!servers) continue;
    const bool crossing = verdict.peer.topic_name == command_topic ||
                          verdict.peer.topic_name == protocol::topic_name(options_.server, TopicKind::kReply) ||
                          verdict.peer.topic_name == protocol::topic_name(options_.server, TopicKind::kStatus);
    if (fatal && crossing && verdict.kind != Kind::kOlderCompatible) {
      fatal_text += (fatal_text.empty() ? "" : "; ") + verdict.text;
    }
    verdicts.push_back(std::move(verdict));
  }
  if (!fatal_text.empty()) {
    throw InterfaceMismatch("server \"" + options_.server + "\" cannot meet this client: " + fatal_text);
  }
  return verdicts;
}

// What this participant has discovered meanwhile, for a name given wrong
// or not at all: the servers it can see on the domain, by name.
std::string Client::others_seen() const {
  const std::set<std::string> names = server_names(dds::PublicationMonitor(participant_).alive());
  const std::string domain = "DDS domain " + std::to_string(options_.domain);
  if (names.empty()) return "no server is on " + domain + " (another --domain, or not started yet?)";
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return "servers on " + domain + ": " + list + " (name one with --server NAME or $DEM_SERVER)";
}

// --- receiving -----------------------------------------------------------

void Client::receive_loop() {
  for (;;) {
    {
      std::lock_guard lock(mutex_);
      if (stopping_) return;
    }
    try {
      waitset_.wait(std::chrono::seconds(1));
      take_replies();
      take_status();
    } catch (const std::exception&) {
      // A DDS error while receiving surfaces to callers as a reply timeout;
      // keep receiving rather than end the client's thread.
      std::this_thread::sleep_for(50ms);
    }
  }
}

void Client::take_replies() {
  std::vector<dds::Received<protocol::Reply>> replies = reply_reader_.take_with_writers();
  if (replies.empty()) return;
  {
    std::lock_guard lock(mutex_);
    for (auto& [chunk, writer, instance] : replies) {
      // Another client's reply, let through before this client's first
      // reply from this writer taught the filter its instance.
      if (chunk.client_id != options_.client_id) continue;
      own_replies_.learn(writer, instance);
      const std::uint64_t id = chunk.request_id;
      if (chunk.chunk == 0) {
        partial_[id] = std::move(chunk);
      } else if (auto found = partial_.find(id); found != partial_.end() && !found->second.last) {
        protocol::Reply& reply = found->second;
        reply.contacts.insert(reply.contacts.end(), std::make_move_iterator(chunk.contacts.begin()),
                              std::make_move_iterator(chunk.contacts.end()));
        reply.data += chunk.data;
        reply.chunk = chunk.chunk;
        reply.last = chunk.last;
        reply.duration = chunk.duration;
        reply.state = std::move(chunk.state);
      }
      if (auto found = partial_.find(id); found != partial_.end() && found->second.last) {
        complete_[id] = std::move(found->second);
        partial_.erase(found);
        outstanding_.erase(id);
      }
    }
  }
  changed_.notify_all();
}

void Client::take_status() {
  std::vector<protocol::Status> statuses = status_reader_.take();
  if (statuses.empty()) return;
  {
    std::lock_guard lock(mutex_);
    status_ = std::move(statuses.back());
  }
  changed_.notify_all();
}

// --- requests ------------------------------------------------------------

protocol::Command Client::command(CommandKind kind) {
  protocol::Command command;
  command.kind = static_cast<std::uint8_t>(kind);
  return command;
}

std::uint64_t Client::send(protocol::Command command) {
  {
    std::unique_lock lock(mutex_);
    // A bounded pipeline: the server's replies to this client never outrun
    // what its reply history keeps for it (ConnectOptions::max_outstanding).
    const auto kind = protocol::command_kind(command.kind);
    const bool control = kind == CommandKind::kStop || kind == CommandKind::kShutdown;
    if (!control && !changed_.wait_for(lock, options_.reply_timeout, [&] {
          return outstanding_.size() < std::max<std::size_t>(options_.max_outstanding, 1);
        })) {
      throw ReplyTimeout(std::to_string(outstanding_.size()) + " requests to server \"" + options_.server +
                         "\" still unanswered after " + seconds(options_.reply_timeout) + " (at most " +
                         std::to_string(options_.max_outstanding) + " may be outstanding)");
    }
    command.request_id = next_request_++;
    outstanding_.insert(command.request_id);
  }
  command.server = options_.server;
  command.client_id = options_.client_id;
  command.stamp = protocol::now_stamp();
  try {
    command_writer_.write(command);
  } catch (...) {
    std::lock_guard lock(mutex_);
    outstanding_.erase(command.request_id);
    changed_.notify_all();
    throw;
  }
  return command.request_id;
}

std::optional<protocol::Reply> Client::await(std::uint64_t request_id, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  if (!changed_.wait_for(lock, timeout, [&] { return complete_.count(request_id) > 0; })) {
    outstanding_.erase(request_id);  // given up on: it no longer holds a place
    changed_.notify_all();
    return std::nullopt;
  }
  protocol::Reply reply = std::move(complete_.at(request_id));
  complete_.erase(request_id);
  return reply;
}

protocol::Reply Client::call(protocol::Command command, std::optional<std::chrono::milliseconds> timeout,
                             bool cancelled_is_ok) {
  const auto kind = protocol::command_kind(command.kind);
  const std::string what = kind ? std::string(protocol::to_string(*kind)) : "command";
  const std::chrono::milliseconds wait = timeout.value_or(options_.reply_timeout);
  const std::uint64_t id = send(std::move(command));
  std::optional<protocol::Reply> reply = await(id, wait);
  if (!reply) {
    throw ReplyTimeout("no reply from server \"" + options_.server + "\" to " + what + " within " + seconds(wait) +
                       (server_alive() ? "" : " (the server is gone)"));
  }
  if (!reply->ok() && !(cancelled_is_ok && reply->status == protocol::ReplyStatus::kCancelled)) {
    throw ServerError(std::move(*reply));
  }
  return std::move(*reply);
}

std::size_t Client::outstanding() const {
  std::lock_guard lock(mutex_);
  return outstanding_.size();
}

protocol::Status Client::status() const {
  std::lock_guard lock(mutex_);
  return status_.value_or(protocol::Status{});
}

std::optional<protocol::Status> Client::wait_for_status(const std::function<bool(const protocol::Status&)>& condition,
                                                        std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  if (!changed_.wait_for(lock, timeout, [&] { return status_ && condition(*status_); })) return std::nullopt;
  return status_;
}

bool Client::server_alive() const { return status_reader_.matched_writers() > 0; }

// --- one call per command --------------------------------------------------

protocol::Reply Client::load_case_file(const std::filesystem::path& local_file) {
  return load_case_text(read_local_file(local_file), local_file.string());
}

protocol::Reply Client::load_case_text(std::string text, std::string source_name) {
  protocol::Command c = command(CommandKind::kLoadCase);
  c.load_case.text = std::move(text);
  c.load_case.source_name = std::move(source_name);
  return call(std::move(c));
}

protocol::Reply Client::load_case_binary(std::string bytes, std::string source_name) {
  protocol::Command c = command(CommandKind::kLoadCase);
  c.load_case.binary = std::move(bytes);
  c.load_case.source_name = std::move(source_name);
  return call(std::move(c));
}

protocol::Reply Client::load_case_on_server(std::string path) {
  protocol::Command c = command(CommandKind::kLoadCase);
  c.load_case.path = std::move(path);
  return call(std::move(c));
}

protocol::Reply Client::set_wall_velocity(std::string wall, protocol::Vector3 velocity,
                                          protocol::Vector3 angular_velocity) {
  protocol::Command c = command(CommandKind::kSetWallVelocity);
  c.wall_velocity.wall = std::move(wall);
  c.wall_velocity.twist.linear = velocity;
  c.wall_velocity.twist.angular = angular_velocity;
  return call(std::move(c));
}

protocol::Reply Client::set_wall_servo(std::string wall, double target_stress, double gain, double max_speed) {
  protocol::Command c = command(CommandKind::kSetWallServo);
  c.wall_servo.wall = std::move(wall);
  c.wall_servo.target_stress = target_stress;
  c.wall_servo.gain = gain;
  c.wall_servo.max_speed = max_speed;
  return call(std::move(c));
}

std::uint64_t Client::start_cycle(std::int64_t cycles) {
  protocol::Command c = command(CommandKind::kCycle);
  c.cycle.cycles = cycles;
  return send(std::move(c));
}

protocol::Reply Client::cycle(std::int64_t cycles, std::chrono::milliseconds timeout) {
  protocol::Command c = command(CommandKind::kCycle);
  c.cycle.cycles = cycles;
  return call(std::move(c), timeout);
}

std::uint64_t Client::start_run_until(const protocol::RunUntilArgs& args) {
  protocol::Command c = command(CommandKind::kRunUntil);
  c.run_until = args;
  return send(std::move(c));
}

protocol::Reply Client::run_until(const protocol::RunUntilArgs& args, std::chrono::milliseconds timeout) {
  protocol::Command c = command(CommandKind::kRunUntil);
  c.run_until = args;
  return call(std::move(c), timeout);
}

std::uint64_t Client::start_run_programme(std::uint32_t first_stage, std::uint32_t stage_count,
                                          const protocol::ProgrammeStepsArgs& steps) {
  protocol::Command c = command(CommandKind::kRunProgramme);
  c.programme = {first_stage, stage_count};
  c.programme_steps = steps;
  return send(std::move(c));
}

protocol::Reply Client::run_programme(std::uint32_t first_stage, std::uint32_t stage_count,
                                      std::chrono::milliseconds timeout, const protocol::ProgrammeStepsArgs& steps) {
  protocol::Command c = command(CommandKind::kRunProgramme);
  c.programme = {first_stage, stage_count};
  c.programme_steps = steps;
  return call(std::move(c), timeout);
}

protocol::Reply Client::stop(bool force) {
  protocol::Command c = command(CommandKind::kStop);
  c.force = force;
  return call(std::move(c));
}
protocol::Reply Client::get_state() { return call(command(CommandKind::kGetState)); }
protocol::Reply Client::shutdown(bool force) {
  protocol::Command c = command(CommandKind::kShutdown);
  c.force = force;
  return call(std::move(c));
}

protocol::Reply Client::query_contacts(const protocol::ContactQueryArgs& args) {
  protocol::Command c = command(CommandKind::kQueryContacts);
  c.query = args;
  return call(std::move(c));
}

protocol::Reply Client::save_snapshot(std::string server_path, bool transfer) {
  protocol::Command c = command(CommandKind::kSaveSnapshot);
  c.snapshot.path = std::move(server_path);
  c.snapshot.transfer = transfer;
  return call(std::move(c));
}

protocol::Reply Client::load_snapshot_on_server(std::string server_path) {
  protocol::Command c = command(CommandKind::kLoadSnapshot);
  c.snapshot.path = std::move(server_path);
  return call(std::move(c));
}

protocol::Reply Client::load_snapshot_bytes(std::string bytes) {
  protocol::Command c = command(CommandKind::kLoadSnapshot);
  c.snapshot.transfer = true;
  c.snapshot.data = std::move(bytes);
  return call(std::move(c));
}

protocol::Reply Client::set_parameter(std::string name, double value, std::string material) {
  protocol::Command c = command(CommandKind::kSetParameter);
  c.parameter.name = std::move(name);
  c.parameter.value = value;
  c.parameter.material = std::move(material);
  return call(std::move(c));
}

protocol::Reply Client::set_gravity(protocol::Vector3 gravity) {
  protocol::Command c = command(CommandKind::kSetParameter);
  c.parameter.name = "gravity";
  c.parameter.vector = gravity;
  return call(std::move(c));
}

// --- discovery -------------------------------------------------------------

std::set<std::string> server_names(const std::vector<dds::Publication>& publications) {
  std::set<std::string> names;
  for (const dds::Publication& publication : publications) {
    if (publication.type_name != protocol::kStatusTypeName) continue;
    if (auto name = protocol::server_of_status_topic(publication.topic_name)) names.insert(*name);
  }
  return names;
}

std::vector<ServerInfo> list_servers(std::uint32_t domain, const std::string& dds_config,
                                     std::chrono::milliseconds discovery) {
  dds::Participant participant(domain, dds_config);
  dds::PublicationMonitor publications(participant);
  std::this_thread::sleep_for(discovery);
  std::vector<ServerInfo> servers;
  for (const std::string& name : server_names(publications.alive())) {
    dds::Topic<protocol::Status> topic(participant, protocol::topic_name(name, TopicKind::kStatus));
    dds::Reader<protocol::Status> reader(participant, topic, protocol::status_qos());
    ServerInfo info{name, std::nullopt};
    // The status is durable: it arrives as soon as the reader matches.
    for (auto waited = 0ms; waited < 1000ms && !info.status; waited += 20ms) {
      std::vector<protocol::Status> statuses = reader.take();
      if (!statuses.empty())
        info.status = std::move(statuses.back());
      else
        std::this_thread::sleep_for(20ms);
    }
    if (!info.status || info.status->state != protocol::ServerState::kShutdown) servers.push_back(std::move(info));
  }
  return servers;
}

}  // namespace dem::client
