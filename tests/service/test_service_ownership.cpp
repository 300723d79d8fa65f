// Names and ownership (docs/SERVICE.md, "Who may stop a run"): a server
// refuses to start under a name already on the domain, and of two started
// at the same instant only one takes it; a run belongs to
// the client that started it - another may watch it, but stops it (or
// shuts the server down under it) only with force, or once the owner has
// left the domain.
#include <gtest/gtest.h>

#include <array>
#include <latch>
#include <memory>
#include <thread>

#include "dem/service/name_claim.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::ReplyStatus;

TEST(Ownership, ASecondServerOfTheSameNameRefusesToStart) {
  InProcessServer first(server_options("twin", kOwnershipNames));
  try {
    service::Server second(server_options("twin", kOwnershipNames));
    FAIL() << "a second server named twin started";
  } catch (const service::NameInUse& error) {
    EXPECT_EQ(std::string(error.what()), "a server named \"twin\" is already on DDS domain " +
                                             std::to_string(kOwnershipNames) +
                                             ": choose another --name, or another --domain");
  }
  // The first serves on, alone.
  client::Client client(connect_options("twin", kOwnershipNames));
  EXPECT_EQ(client.get_state().state.state, protocol::ServerState::kIdle);
  // The program says so with its own exit code.
  ServerProcess process(
      {"--name", "twin", "--domain", std::to_string(kOwnershipNames), "--name-wait", "1", "--log-level", "off"});
  EXPECT_EQ(process.wait(30s), 5);
}

// Neither sees the other's status writer when it looks: the claims decide
// (service/name_claim.h).
TEST(Ownership, OfTwoServersStartedAtTheSameInstantOneTakesTheName) {
  // The process's first participant of a domain sets the domain up, which
  // takes a while and would let one server start well before the other.
  const dds::Participant domain_set_up(kOwnershipSimultaneousServers);
  std::array<std::unique_ptr<service::Server>, 2> servers;
  std::array<std::string, 2> refusals;
  std::latch start(2);
  std::array<std::thread, 2> threads;
  for (std::size_t i = 0; i < 2; ++i) {
    threads[i] = std::thread([&, i] {
      start.arrive_and_wait();
      try {
        servers[i] = std::make_unique<service::Server>(server_options("twins", kOwnershipSimultaneousServers));
      } catch (const service::NameInUse& error) {
        refusals[i] = error.what();
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  ASSERT_EQ((servers[0] != nullptr) + (servers[1] != nullptr), 1) << refusals[0] << " / " << refusals[1];
  // The one refused saw the other claiming (most often), or, looking a
  // moment later, serving already.
  const std::string& refusal = servers[0] ? refusals[1] : refusals[0];
  const std::string domain = std::to_string(kOwnershipSimultaneousServers);
  EXPECT_TRUE(refusal == "another server named \"twins\" started on DDS domain " + domain +
                             " at the same time and takes the name (of servers started together, the one whose DDS "
                             "participant has the lowest GUID does): choose another --name, or another --domain" ||
              refusal == "a server named \"twins\" is already on DDS domain " + domain +
                             ": choose another --name, or another --domain")
      << refusal;
  service::Server& winner = servers[0] ? *servers[0] : *servers[1];
  winner.start();
  client::Client client(connect_options("twins", kOwnershipSimultaneousServers));
  EXPECT_EQ(client.get_state().state.state, protocol::ServerState::kIdle);
  winner.request_shutdown();
  winner.wait();
}

// The programs, with their own discovery time (0.5 s): one exits with code
// 5, the other serves.
TEST(Ownership, OfTwoProgramsStartedAtTheSameInstantOneExitsWithCode5) {
  const std::vector<std::string> arguments{
      "--name",      "twins", "--domain",    std::to_string(kOwnershipSimultaneousPrograms),
      "--name-wait", "2",     "--log-level", "error"};
  ServerProcess first(arguments);
  ServerProcess second(arguments);
  int refused = -1;
  ServerProcess* winner = nullptr;
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (refused < 0 && std::chrono::steady_clock::now() < deadline) {
    if ((refused = first.wait(10ms)) >= 0) {
      winner = &second;
    } else if ((refused = second.wait(10ms)) >= 0) {
      winner = &first;
    }
  }
  EXPECT_EQ(refused, 5);
  ASSERT_NE(winner, nullptr);
  client::Client client(connect_options("twins", kOwnershipSimultaneousPrograms));
  EXPECT_EQ(client.get_state().state.state, protocol::ServerState::kIdle);
  EXPECT_TRUE(client.shutdown().ok());
  EXPECT_EQ(winner->wait(30s), 0);
}

TEST(Ownership, OnlyTheOwnerStopsARunUnlessForced) {
  InProcessServer server(server_options("owned", kOwnershipRuns));
  client::Client owner(connect_options("owned", kOwnershipRuns));
  client::Client other(connect_options("owned", kOwnershipRuns));
  owner.load_case_file(case_file("nine_disc_damped"));
  const std::uint64_t run = owner.start_cycle(1'000'000'000);
  ASSERT_TRUE(other.wait_for_status([&](const auto& s) { return s.command_request_id == run; }, 10s));

  // Watching is free; stopping and shutting down are not.
  EXPECT_EQ(other.get_state().state.command_client, owner.client_id());
  for (const bool shutdown : {false, true}) {
    try {
      shutdown ? other.shutdown() : other.stop();
      FAIL() << "another client ended the run";
    } catch (const client::ServerError& error) {
      EXPECT_EQ(error.status(), ReplyStatus::kRefused);
      EXPECT_NE(std::string(error.what())
                    .find("refused: the running cycle (request " + std::to_string(run) + ") of client " +
                          owner.client_id() + " belongs to that client"),
                std::string::npos)
          << error.what();
    }
  }
  EXPECT_EQ(other.get_state().state.state, protocol::ServerState::kRunning);
  // With force it may.
  EXPECT_TRUE(other.stop(true).ok());
  const std::optional<protocol::Reply> ended = owner.await(run, 10s);
  ASSERT_TRUE(ended);
  EXPECT_EQ(ended->status, ReplyStatus::kCancelled);
  // The owner stops its own without force.
  const std::uint64_t again = owner.start_cycle(1'000'000'000);
  ASSERT_TRUE(owner.wait_for_status([&](const auto& s) { return s.command_request_id == again; }, 10s));
  EXPECT_TRUE(owner.stop().ok());
}

TEST(Ownership, TheRunOfAClientThatLeftGoesOnAndAnyoneMayStopIt) {
  InProcessServer server(server_options("orphan", kOwnershipVanished));
  client::Client other(connect_options("orphan", kOwnershipVanished));
  std::uint64_t run = 0;
  {
    client::Client owner(connect_options("orphan", kOwnershipVanished));
    owner.load_case_file(case_file("nine_disc_damped"));
    run = owner.start_cycle(1'000'000'000);
    ASSERT_TRUE(owner.wait_for_status([&](const auto& s) { return s.command_request_id == run; }, 10s));
  }  // the owner's participant leaves the domain
  ASSERT_TRUE(eventually([&] { return other.status().message.find("its client has left") != std::string::npos; }, 10s))
      << other.status().message;
  EXPECT_EQ(other.status().state, protocol::ServerState::kRunning);  // it went on
  EXPECT_TRUE(other.stop().ok());                                    // and anyone may stop it
  EXPECT_TRUE(eventually([&] { return other.status().state == protocol::ServerState::kLoaded; }, 10s));
}

}  // namespace
}  // namespace dem::test
