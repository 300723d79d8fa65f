// dds_discovery_probe: drives what killed dem_server inside Cyclone DDS's
// discovery thread (issue 37, docs/RELIABILITY.md "Discovery") against a
// running server, round after round:
//   - a peer process (probe_participant.h) with readers and writers on the
//     server's topics whose type names the server's own are, described
//     otherwise (other members, extensibility, keys, no type information),
//     asking the server for its types (type-lookup requests), then leaving
//     or dying;
//   - from this process, hand-made discovery messages (rtps_packets.h): a
//     participant that exists only in them announces endpoints on the
//     server's topics with the server's type information, another's, or
//     either damaged, and damaged announcements of itself.
// It checks after every round that the server process is alive, and exits
// 0 when it survived them all, 1 when it died (naming the round), 2 on bad
// arguments.
//
//   dds_discovery_probe --domain D --server NAME --server-pid PID [--rounds N] [--seed S] [--parallel K]
//                       [--no-peers] [--no-raw]
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "dem/command.h"
#include "dem/telemetry.h"
#include "probe_participant.h"
#include "probe_variants.h"
#include "rtps_packets.h"

namespace {

using dem::probe::Bytes;
using dem::probe::GuidPrefix;
using dem::probe::RtpsMessage;

struct Options {
  std::uint32_t domain = 0;
  std::string server;
  pid_t server_pid = 0;
  int rounds = 100;
  std::uint64_t seed = 1;
  int parallel = 2;
  bool peers = true;  // the peer processes (--no-peers: none)
  bool raw = true;    // the hand-made messages (--no-raw: none)
};

// Cyclone's default port mapping (DDSI-RTPS 9.6.1.1): a participant of
// index i on domain d takes the discovery unicast port 7400 + 250 d + 10 + 2 i;
// the loopback configuration numbers them from 0 to 60.
constexpr int kMaxParticipantIndex = 60;

bool alive(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const std::size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

// The type descriptions the hand-made endpoints announce: the server's
// own and the probe's others (no Cyclone call: the descriptors' bytes).
std::vector<Bytes> type_informations() {
  std::vector<Bytes> out;
  for (const dds_topic_descriptor_t* d :
       {&dem_interfaces_msg_dds__Command__desc, &dem_interfaces_msg_dds__Reply__desc,
        &dem_interfaces_msg_dds__Status__desc, &dem_interfaces_msg_dds__PlateForces__desc,
        &probe_final_PlateForces_desc, &probe_appendable_Status_desc, &probe_mutable_Command_desc,
        &probe_mutable_PlateForces_desc, &probe_mutable_Reply_desc}) {
    out.emplace_back(d->type_information.data, d->type_information.data + d->type_information.sz);
  }
  return out;
}

class RawPeer {
 public:
  explicit RawPeer(const Options& options) : options_(options), infos_(type_informations()) {
    socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK, 0);
    sockaddr_in local{};
    local.sin_family = AF_INET;
    local.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(socket_, reinterpret_cast<const sockaddr*>(&local), sizeof local);
    socklen_t length = sizeof local;
    ::getsockname(socket_, reinterpret_cast<sockaddr*>(&local), &length);
    port_ = ntohs(local.sin_port);
  }
  ~RawPeer() { ::close(socket_); }

  // One made-up participant's announcements, valid and damaged.
  void play_round(std::mt19937_64& random) {
    GuidPrefix prefix;
    for (auto& b : prefix) b = static_cast<std::uint8_t>(random());
    const Bytes spdp = dem::probe::participant_announcement(prefix, port_, 2 + static_cast<int>(random() % 4));
    send(RtpsMessage(prefix).info_timestamp().data(dem::probe::kSpdpReader, dem::probe::kSpdpWriter, 1, spdp));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    static constexpr const char* kTopics[][2] = {{"command", "Command_"},
                                                 {"reply", "Reply_"},
                                                 {"status", "Status_"},
                                                 {"plate_forces", "PlateForces_"},
                                                 {"contact_stats", "ContactStats_"}};
    std::int64_t publications = 0;
    std::int64_t subscriptions = 0;
    for (int e = 0; e < 10; ++e) {
      const auto& topic = kTopics[random() % std::size(kTopics)];
      const std::string name = "rt/dem/" + options_.server + "/" + topic[0];
      const std::string type = std::string("dem_interfaces::msg::dds_::") + topic[1];
      const std::size_t pick = random() % (infos_.size() + 1);
      const Bytes info = pick < infos_.size() ? infos_[pick] : Bytes{};
      const bool writer = random() % 2 == 0;
      // User entity ids: a key counted up, kind 0x03 writer or 0x04 reader without key.
      const std::uint32_t entity = (static_cast<std::uint32_t>(e + 1) << 8) | (writer ? 0x03u : 0x04u);
      Bytes payload = dem::probe::endpoint_announcement(prefix, entity, name, type, info);
      if (random() % 2 == 0) payload = dem::probe::damaged(payload, random);
      const std::uint32_t sedp_writer = writer ? dem::probe::kPublicationsWriter : dem::probe::kSubscriptionsWriter;
      const std::uint32_t sedp_reader = writer ? dem::probe::kPublicationsReader : dem::probe::kSubscriptionsReader;
      const std::int64_t sequence = writer ? ++publications : ++subscriptions;
      send(RtpsMessage(prefix)
               .info_timestamp()
               .data(sedp_reader, sedp_writer, sequence, payload)
               .heartbeat(0, sedp_writer, 1, sequence, static_cast<std::uint32_t>(sequence)));
    }
    if (random() % 4 == 0) {  // the participant's own announcement, damaged
      send(RtpsMessage(prefix).info_timestamp().data(dem::probe::kSpdpReader, dem::probe::kSpdpWriter, 2,
                                                     dem::probe::damaged(spdp, random)));
    }
    drain();
  }

  long long messages_sent() const { return sent_; }

 private:
  void send(const RtpsMessage& message) {
    const Bytes& bytes = message.bytes();
    for (int index = 0; index <= kMaxParticipantIndex; ++index) {
      sockaddr_in to{};
      to.sin_family = AF_INET;
      to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      to.sin_port = htons(static_cast<std::uint16_t>(7400 + 250 * options_.domain + 10 + 2 * index));
      ::sendto(socket_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to);
    }
    ++sent_;
  }
  // What the peers send back (their announcements, acknowledgements, type
  // requests to the made-up participant) is read and dropped.
  void drain() {
    char buffer[65536];
    while (::recv(socket_, buffer, sizeof buffer, 0) > 0) {
    }
  }

  const Options& options_;
  std::vector<Bytes> infos_;
  int socket_ = -1;
  std::uint16_t port_ = 0;
  long long sent_ = 0;
};

bool parse(int argc, char** argv, Options& options) {
  std::vector<std::string> arguments;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--no-peers") {
      options.peers = false;
    } else if (argument == "--no-raw") {
      options.raw = false;
    } else {
      arguments.push_back(argument);
    }
  }
  for (std::size_t i = 0; i + 1 < arguments.size(); i += 2) {
    const std::string& key = arguments[i];
    const char* value = arguments[i + 1].c_str();
    if (key == "--domain") {
      options.domain = static_cast<std::uint32_t>(std::strtoul(value, nullptr, 10));
    } else if (key == "--server") {
      options.server = value;
    } else if (key == "--server-pid") {
      options.server_pid = static_cast<pid_t>(std::strtol(value, nullptr, 10));
    } else if (key == "--rounds") {
      options.rounds = std::atoi(value);
    } else if (key == "--seed") {
      options.seed = std::strtoull(value, nullptr, 10);
    } else if (key == "--parallel") {
      options.parallel = std::max(1, std::atoi(value));
    } else {
      return false;
    }
  }
  return arguments.size() % 2 == 0 && !options.server.empty() && options.server_pid > 0 && options.rounds > 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!parse(argc, argv, options)) {
    std::fprintf(stderr,
                 "usage: dds_discovery_probe --domain D --server NAME --server-pid PID [--rounds N] [--seed S] "
                 "[--parallel K] [--no-peers] [--no-raw]\n");
    return 2;
  }
  std::signal(SIGPIPE, SIG_IGN);
  // This process never starts Cyclone: each peer round forks from a
  // process without its threads, and gets a type library of its own.
  RawPeer raw(options);
  std::mt19937_64 random(options.seed);
  std::vector<pid_t> peers;
  int peer_failures = 0;
  const auto reap = [&](bool all) {
    for (auto it = peers.begin(); it != peers.end();) {
      int status = 0;
      const pid_t done = ::waitpid(*it, &status, all ? 0 : WNOHANG);
      if (done == *it) {
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) ++peer_failures;
        it = peers.erase(it);
      } else {
        ++it;
      }
    }
  };
  const auto started = std::chrono::steady_clock::now();
  for (int round = 1; round <= options.rounds; ++round) {
    const std::uint64_t seed = random();
    while (static_cast<int>(peers.size()) >= options.parallel) {
      reap(false);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (options.peers) {
      const pid_t peer = ::fork();
      if (peer == 0) {
        ::alarm(30);  // a peer that hangs is killed rather than holding the probe
        _exit(dem::probe::run_participant_round({options.domain, options.server, seed, 200}));
      }
      if (peer > 0) peers.push_back(peer);
    }
    if (options.raw) {
      raw.play_round(random);
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    reap(false);
    if (!alive(options.server_pid)) {
      reap(true);
      std::printf("dds_discovery_probe: the server (pid %d) died in round %d of %d\n", options.server_pid, round,
                  options.rounds);
      return 1;
    }
    if (round % 100 == 0) {
      std::printf("dds_discovery_probe: %d rounds, %.0f s, server alive\n", round,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
      std::fflush(stdout);
    }
  }
  reap(true);
  // The peers that died leave proxies behind until their lease ends; the
  // server handles their expiry too.
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const bool survived = alive(options.server_pid);
  std::printf(
      "dds_discovery_probe: %d rounds (%d peer processes failed), %lld hand-made messages in %.0f s; the "
      "server %s\n",
      options.rounds, peer_failures, raw.messages_sent(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
      survived ? "is alive" : "died");
  return survived ? 0 : 1;
}
