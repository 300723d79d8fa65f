// Servers side by side on one domain, late joiners, cancelling, and a
// subscriber that stops reading.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <atomic>
#include <mutex>

#include "dem/client/telemetry.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::ReplyStatus;
using protocol::ServerState;

TEST(Topology, TwoServersOnOneDomainAreAddressedSeparately) {
  InProcessServer left(server_options("left", kTopologyTwoServers));
  InProcessServer right(server_options("right", kTopologyTwoServers));
  client::Client to_left(connect_options("left", kTopologyTwoServers));
  client::Client to_right(connect_options("right", kTopologyTwoServers));
  to_left.load_case_file(case_file("nine_disc_damped"));
  to_right.load_case_file(case_file("nine_disc_undamped"));
  to_left.cycle(30);
  to_right.cycle(70);
  const protocol::Reply l = to_left.get_state();
  const protocol::Reply r = to_right.get_state();
  EXPECT_EQ(l.server, "left");
  EXPECT_EQ(r.server, "right");
  EXPECT_EQ(l.state.case_name, "nine_disc_damped");
  EXPECT_EQ(r.state.case_name, "nine_disc_undamped");
  EXPECT_EQ(l.state.cycle, 30u);
  EXPECT_EQ(r.state.cycle, 70u);
  // The status topic is its own stream: each client's catches up.
  ASSERT_TRUE(to_left.wait_for_status([](const protocol::Status& s) { return s.cycle == 30; }, 10s));
  ASSERT_TRUE(to_right.wait_for_status([](const protocol::Status& s) { return s.cycle == 70; }, 10s));
  EXPECT_EQ(to_left.status().server, "left");
  EXPECT_EQ(to_right.status().server, "right");
}

TEST(Topology, ALateJoiningMonitorSeesTheCurrentStatus) {
  InProcessServer server(server_options("durable", kTopologyLateJoiner));
  {
    client::Client client(connect_options("durable", kTopologyLateJoiner));
    client.load_case_file(case_file("nine_disc_damped"));
    client.cycle(50);
  }
  // The server now publishes nothing until told something: what a late
  // subscriber gets is the durable status.
  dds::Participant late(kTopologyLateJoiner);
  std::mutex mutex;
  std::optional<protocol::Status> seen;
  client::TelemetrySubscription monitor(
      late, "durable", {.plate_forces = {}, .contact_stats = {}, .status = [&](const protocol::Status& s) {
                          std::lock_guard lock(mutex);
                          seen = s;
                        }});
  ASSERT_TRUE(eventually(
      [&] {
        std::lock_guard lock(mutex);
        return seen.has_value();
      },
      10s));
  std::lock_guard lock(mutex);
  EXPECT_EQ(seen->state, ServerState::kLoaded);
  EXPECT_EQ(seen->case_name, "nine_disc_damped");
  EXPECT_EQ(seen->cycle, 50u);
  EXPECT_EQ(seen->message, "ran 50 cycles to cycle 50");
}

// A monitor, recording or dashboard started beside a run is given the
// run's recent telemetry: the writer's last 256 samples, in order
// (transient-local, as a ROS 2 latched topic with a depth; DDS.md).
TEST(Topology, ALateJoiningMonitorIsGivenTheRecentTelemetry) {
  service::ServerOptions options = server_options("history", kTelemetryHistory);
  options.telemetry_cycles = 10;
  InProcessServer server(options);
  {
    client::Client client(connect_options("history", kTelemetryHistory));
    client.load_case_file(case_file("nine_disc_damped"));
    ASSERT_EQ(client.cycle(3000).cycles_run, 3000u);  // 300 samples of each, every 10 cycles
  }
  dds::Participant late(kTelemetryHistory);
  std::mutex mutex;
  std::vector<std::uint64_t> plates;
  std::vector<std::uint64_t> stats;
  client::TelemetrySubscription monitor(late, "history",
                                        {.plate_forces =
                                             [&](const protocol::PlateForces& p) {
                                               std::lock_guard lock(mutex);
                                               plates.push_back(p.cycle);
                                             },
                                         .contact_stats =
                                             [&](const protocol::ContactStats& c) {
                                               std::lock_guard lock(mutex);
                                               stats.push_back(c.cycle);
                                             }});
  ASSERT_TRUE(eventually(
      [&] {
        std::lock_guard lock(mutex);
        return plates.size() >= 256 && stats.size() >= 256;
      },
      10s))
      << plates.size() << " plate and " << stats.size() << " contact samples";
  std::this_thread::sleep_for(200ms);  // nothing more is coming
  std::lock_guard lock(mutex);
  std::printf("a monitor joining at cycle 3000 was given %zu plate and %zu contact samples, cycles %llu to %llu\n",
              plates.size(), stats.size(), static_cast<unsigned long long>(plates.front()),
              static_cast<unsigned long long>(plates.back()));
  std::vector<std::uint64_t> expected;
  for (std::uint64_t cycle = 3000 - 255 * 10; cycle <= 3000; cycle += 10) expected.push_back(cycle);
  EXPECT_EQ(plates, expected);
  EXPECT_EQ(stats, expected);
}

TEST(Topology, StopCancelsALongCycle) {
  InProcessServer server(server_options("long", kTopologyStopCancels));
  client::Client client(connect_options("long", kTopologyStopCancels));
  client.load_case_file(case_file("nine_disc_damped"));
  const std::uint64_t request = client.start_cycle(1'000'000'000);
  ASSERT_TRUE(client.wait_for_status(
      [&](const auto& s) { return s.command_request_id == request && s.command_cycles_done > 1000; }, 10s));
  const auto asked = std::chrono::steady_clock::now();
  const protocol::Reply stopped = client.stop();
  const auto cancelled = client.await(request, 10s);
  const double latency = std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
  ASSERT_TRUE(cancelled);
  EXPECT_EQ(cancelled->status, ReplyStatus::kCancelled);
  EXPECT_EQ(cancelled->message, "stopped by request");
  EXPECT_GT(cancelled->cycles_run, 1000u);
  EXPECT_LT(cancelled->cycles_run, 1'000'000'000u);
  EXPECT_EQ(stopped.message, "stopped cycle at cycle " + std::to_string(cancelled->state.cycle) + " after " +
                                 std::to_string(cancelled->cycles_run) + " cycles");
  EXPECT_LT(latency, 2.0);  // a chunk of cycles takes about 20 ms
  EXPECT_EQ(client.get_state().state.state, ServerState::kLoaded);
  EXPECT_EQ(client.cycle(10).cycles_run, 10u);  // and it runs again
}

TEST(Topology, ASubscriberThatStopsReadingDoesNotStallTheEngine) {
  service::ServerOptions options = server_options("steady", kTopologyStalledSubscriber);
  options.telemetry_cycles = 1;  // a sample on each topic every cycle
  InProcessServer server(options);
  client::Client client(connect_options("steady", kTopologyStalledSubscriber));
  client.load_case_file(case_file("nine_disc_damped"));
  // 20 over the run: at 1 the wall would press through the discs, which the
  // health check stops (overlaps beyond 3/4 of a radius).
  client.set_wall_velocity("top", {0.0, -0.1, 0.0});
  // A live monitor in another process, stopped (SIGSTOP) once it subscribed:
  // it acknowledges nothing from then on.
  const std::uint64_t served = client.status().commands_served;
  const pid_t monitor = spawn(DEM_DEMCTL_PROGRAM,
                              {"monitor", "--server", "steady", "--domain", std::to_string(kTopologyStalledSubscriber)},
                              /*quiet=*/true);
  ASSERT_TRUE(eventually([&] { return client.get_state().state.commands_served >= served + 2; }, 20s));
  std::this_thread::sleep_for(1s);  // its telemetry readers match
  ::kill(monitor, SIGSTOP);
  // A healthy subscriber in this process keeps reading.
  std::atomic<std::uint64_t> last_cycle{0};
  client::TelemetrySubscription healthy(
      client, {.plate_forces = [&](const auto& p) { last_cycle = p.cycle; }, .contact_stats = {}, .status = {}});
  ASSERT_TRUE(eventually([&] { return healthy.matched_publishers() > 0; }, 10s));

  const auto start = std::chrono::steady_clock::now();
  const protocol::Reply reply = client.cycle(20'000, 60s);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ::kill(monitor, SIGKILL);
  waitpid(monitor, nullptr, 0);
  std::printf("20000 cycles with telemetry every cycle and a stopped subscriber: %.2f s\n", seconds);
  EXPECT_EQ(reply.cycles_run, 20'000u);
  // 40,000 telemetry samples; a writer that waited for the stopped reader
  // (100 ms a sample at Cyclone's default) would take more than an hour.
  EXPECT_LT(seconds, 30.0);
  EXPECT_EQ(reply.state.telemetry_dropped, 0u);  // and nothing was dropped for the others
  EXPECT_TRUE(eventually([&] { return last_cycle == 20'000u; }, 10s)) << last_cycle;
}

TEST(Topology, ClientsListTheLiveServers) {
  auto first = std::make_unique<InProcessServer>(server_options("first", kTopologyListServers));
  InProcessServer second(server_options("second", kTopologyListServers));
  const auto names = [] {
    std::vector<std::string> found;
    for (const auto& server : client::list_servers(kTopologyListServers, {}, 1s)) {
      found.push_back(server.name);
      EXPECT_TRUE(server.status.has_value()) << server.name;
    }
    return found;
  };
  EXPECT_TRUE(eventually([&] { return names() == std::vector<std::string>{"first", "second"}; }, 20s));
  first.reset();  // shuts down gracefully
  EXPECT_TRUE(eventually([&] { return names() == std::vector<std::string>{"second"}; }, 20s));
}

TEST(Topology, ConnectingToNoServerTimesOut) {
  auto options = connect_options("nobody", kTopologyNoServer);
  options.timeout = 500ms;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(client::Client{options}, client::NoSuchServer);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
  options.server = "not a name";
  EXPECT_THROW(client::Client{options}, std::invalid_argument);
}

}  // namespace
}  // namespace dem::test
