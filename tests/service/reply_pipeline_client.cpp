// A client in a process of its own, for Limits.SeveralFloodingClientsLoseNoReply:
// sends REQUESTS contact queries on the wall "bottom" through one pipeline
// (the client library lets 64 be unanswered; send waits beyond), then
// awaits each. Prints what came back; exits 0 when every request got its
// reply, 1 when some did not, 2 on an error. The test stops this process
// (SIGSTOP) while its requests are in flight and other clients flood the
// server, so its replies can reach it only from the server's history.
//   reply_pipeline_client SERVER DOMAIN REQUESTS
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dem/client/client.h"

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: reply_pipeline_client SERVER DOMAIN REQUESTS [RECEIVE_BUFFER]\n");
    return 2;
  }
  try {
    dem::client::ConnectOptions options;
    options.server = argv[1];
    options.domain = static_cast<std::uint32_t>(std::stoul(argv[2]));
    const int requests = std::stoi(argv[3]);
    if (argc == 5) {
      const char* uri = std::getenv("CYCLONEDDS_URI");  // the loopback configuration, which the cap amends
      if (uri == nullptr) throw std::runtime_error("RECEIVE_BUFFER amends $CYCLONEDDS_URI, which is not set");
      options.dds_config = std::string(uri) +
                           ",<CycloneDDS><Domain><Internal><SocketReceiveBufferSize min=\"default\" max=\"" + argv[4] +
                           "\"/></Internal></Domain></CycloneDDS>";
    }
    dem::client::Client client(options);
    std::printf("connected\n");
    std::fflush(stdout);
    std::vector<std::uint64_t> sent;
    sent.reserve(static_cast<std::size_t>(requests));
    for (int i = 0; i < requests; ++i) {
      dem::protocol::Command command;
      command.kind = static_cast<std::uint8_t>(dem::protocol::CommandKind::kQueryContacts);
      command.query.wall_set = true;
      command.query.wall = "bottom";
      sent.push_back(client.send(command));
    }
    int answered = 0, missing = 0;
    std::string first_missing;
    // Every reply within 30 s of the last request sent.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    for (const std::uint64_t id : sent) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      const std::optional<dem::protocol::Reply> reply = client.await(id, std::max(left, std::chrono::milliseconds(0)));
      if (reply && reply->ok()) {
        ++answered;
      } else if (!reply) {
        if (missing++ == 0) first_missing = std::to_string(id);
      }
    }
    std::printf("%d requests: %d answered ok, %d without a reply%s%s\n", requests, answered, missing,
                missing > 0 ? ", the first: request " : "", first_missing.c_str());
    return missing == 0 && answered == requests ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "reply_pipeline_client: %s\n", error.what());
    return 2;
  }
}
