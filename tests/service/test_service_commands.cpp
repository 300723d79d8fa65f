// Every command's normal path, through the client library to a server in
// this process (over the loopback DDS configuration).
#include <gtest/gtest.h>

#include <cmath>
#include <mutex>
#include <numbers>
#include <sstream>

#include "dem/case.pb.h"
#include "dem/client/telemetry.h"
#include "dem/io/case_loader.h"
#include "dem/io/snapshot_file.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::ReplyStatus;
using protocol::ServerState;

const std::string kNineDisc = "nine_disc_damped";

// A server with the nine-disc case loaded and a client connected to it.
struct Loaded {
  Loaded(const std::string& name, std::uint32_t domain, std::function<void(service::ServerOptions&)> adjust = {})
      : server([&] {
          service::ServerOptions options = server_options(name, domain);
          if (adjust) adjust(options);
          return options;
        }()),
        client(connect_options(name, domain)) {
    client.load_case_file(case_file(kNineDisc));
  }
  // The nine-disc compression: every wall moves inwards at 12.
  void compress() {
    client.set_wall_velocity("bottom", {0, 12, 0});
    client.set_wall_velocity("right", {-12, 0, 0});
    client.set_wall_velocity("top", {0, -12, 0});
    client.set_wall_velocity("left", {12, 0, 0});
  }
  InProcessServer server;
  client::Client client;
};

TEST(Commands, LoadCaseFromTextFileOrBinary) {
  InProcessServer server(server_options("load", kCommandsLoadCase));
  client::Client client(connect_options("load", kCommandsLoadCase));
  EXPECT_EQ(client.status().state, ServerState::kIdle);

  const protocol::Reply text = client.load_case_file(case_file(kNineDisc));
  EXPECT_TRUE(text.ok());
  EXPECT_NE(text.message.find("loaded case nine_disc_damped"), std::string::npos) << text.message;
  EXPECT_EQ(text.state.state, ServerState::kLoaded);
  EXPECT_EQ(text.state.particles, 9);
  EXPECT_EQ(text.state.walls, 4);
  EXPECT_EQ(text.state.dimension, 2);
  EXPECT_EQ(text.state.time_step, 0.01);

  const protocol::Reply path = client.load_case_on_server(case_file("verification_assembly").string());
  EXPECT_EQ(path.state.case_name, "verification_assembly");
  EXPECT_EQ(path.state.particles, 197);
  EXPECT_EQ(path.path, case_file("verification_assembly").string());

  const std::string bytes = io::load_case_file(case_file(kNineDisc)).message.SerializeAsString();
  const protocol::Reply binary = client.load_case_binary(bytes, "nine.bin");
  EXPECT_EQ(binary.state.case_name, "nine_disc_damped");
  EXPECT_EQ(binary.state.cycle, 0u);
  const auto status = client.wait_for_status([](const auto& s) { return s.case_name == "nine_disc_damped"; }, 10s);
  ASSERT_TRUE(status);
  EXPECT_EQ(status->state, ServerState::kLoaded);
}

TEST(Commands, WallVelocityAndServoSteerTheWalls) {
  Loaded s("walls", kCommandsWallMotion);
  const protocol::Reply moved = s.client.set_wall_velocity("top", {0.0, -12.0, 0.0}, {0.0, 0.0, 0.01});
  EXPECT_NE(moved.message.find("wall top moves at (0, -12) m/s, 0.01 rad/s"), std::string::npos) << moved.message;
  s.client.cycle(10);
  const auto top = s.client.get_state().plates.walls.at(2);
  EXPECT_NEAR(top.displacement.y, -12.0 * 0.1, 1e-9);
  // By id, when no name is given.
  protocol::Command by_id;
  by_id.kind = static_cast<std::uint8_t>(protocol::CommandKind::kSetWallVelocity);
  by_id.wall_velocity.wall_id = 0;
  by_id.wall_velocity.twist.linear = {0.0, 1.0, 0.0};
  EXPECT_NE(s.client.call(by_id).message.find("wall bottom moves"), std::string::npos);

  const protocol::Reply servo = s.client.set_wall_servo("top", 5e7, 1e-12, 10.0);
  EXPECT_NE(servo.message.find("servo-controlled to 5e+07 Pa (gain 1e-12 m/(Pa s), at most 10 m/s)"), std::string::npos)
      << servo.message;
  const protocol::Reply chosen = s.client.set_wall_servo("right", 1e7);
  EXPECT_NE(chosen.message.find("servo-controlled to 1e+07 Pa"), std::string::npos) << chosen.message;
}

TEST(Commands, CycleIsAcceptedAtOnceReportsProgressAndReplies) {
  Loaded s("cycler", kCommandsCycle, [](auto& o) { o.progress_interval = 10ms; });
  // Slowly: 200,000 cycles of the full compression would press the walls
  // through the discs, which the health check stops (overlaps beyond 3/4 of a radius).
  s.client.set_wall_velocity("top", {0, -0.01, 0});
  const auto start = std::chrono::steady_clock::now();
  const std::uint64_t request = s.client.start_cycle(200000);
  // Accepted: the status shows the command running with its progress.
  const auto running = s.client.wait_for_status(
      [&](const auto& st) {
        return st.state == ServerState::kRunning && st.command_request_id == request && st.command_cycles_done > 0;
      },
      10s);
  ASSERT_TRUE(running);
  EXPECT_EQ(running->command, "cycle");
  EXPECT_EQ(running->command_client, s.client.client_id());
  EXPECT_EQ(running->command_cycles_total, 200000u);
  EXPECT_GT(running->progress, 0.0);
  // Other commands are answered between chunks while it runs.
  EXPECT_EQ(s.client.get_state().state.state, ServerState::kRunning);
  const auto reply = s.client.await(request, 60s);
  ASSERT_TRUE(reply);
  EXPECT_TRUE(reply->ok());
  EXPECT_EQ(reply->cycles_run, 200000u);
  EXPECT_EQ(reply->state.cycle, 200000u);
  EXPECT_EQ(reply->state.state, ServerState::kLoaded);
  EXPECT_GT(reply->duration, 0.0);
  EXPECT_LT(reply->duration, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  EXPECT_EQ(reply->message, "ran 200000 cycles to cycle 200000");
}

TEST(Commands, RunUntilStopsAtStressSettlementOrEnergy) {
  Loaded s("until", kCommandsRunUntil);
  s.compress();
  protocol::RunUntilArgs stress;
  stress.wall = "top";
  stress.stress = 1e7;
  stress.max_cycles = 10000;
  const protocol::Reply by_stress = s.client.run_until(stress);
  EXPECT_TRUE(by_stress.condition_met);
  EXPECT_LT(by_stress.cycles_run, 10000u);
  const double reached = s.client.get_state().plates.walls.at(2).normal_stress;
  EXPECT_GE(reached, 1e7);
  EXPECT_NE(by_stress.message.find("the stress on top reached"), std::string::npos) << by_stress.message;

  protocol::RunUntilArgs settlement;
  settlement.wall = "top";
  settlement.settlement = 6.0;  // it is at about 0.12 * cycles so far
  settlement.max_cycles = 10000;
  const protocol::Reply by_settlement = s.client.run_until(settlement);
  EXPECT_TRUE(by_settlement.condition_met);
  EXPECT_GE(s.client.get_state().plates.walls.at(2).settlement, 6.0);

  for (const char* wall : {"bottom", "right", "top", "left"}) s.client.set_wall_velocity(wall, {});
  protocol::RunUntilArgs calm;
  calm.kinetic_energy = 1.0;  // the damped assembly comes to rest
  calm.max_cycles = 100000;
  calm.check_interval = 10;
  const protocol::Reply by_energy = s.client.run_until(calm);
  EXPECT_TRUE(by_energy.condition_met);
  EXPECT_EQ(by_energy.cycles_run % 10, 0u);
  EXPECT_LT(s.client.get_state().stats.kinetic_energy, 1.0);

  protocol::RunUntilArgs capped = stress;
  capped.stress = 1e29;  // never reached (1e30 is the largest threshold a command may give)
  capped.max_cycles = 50;
  const protocol::Reply cap = s.client.run_until(capped);
  EXPECT_FALSE(cap.condition_met);
  EXPECT_EQ(cap.cycles_run, 50u);
}

TEST(Commands, GetStateCarriesPlatesAndContactStatistics) {
  Loaded s("state", kCommandsGetState);
  s.compress();
  s.client.cycle(40);
  const protocol::Reply state = s.client.get_state();
  EXPECT_EQ(state.state.cycle, 40u);
  EXPECT_EQ(state.plates.cycle, 40u);
  ASSERT_EQ(state.plates.walls.size(), 4u);
  EXPECT_EQ(state.plates.walls[2].name, "top");
  EXPECT_EQ(state.plates.walls[2].area, 400.0);
  EXPECT_EQ(state.plates.walls[2].normal_stress, state.plates.walls[2].normal_force / 400.0);
  EXPECT_EQ(state.stats.contacts, 24);
  EXPECT_EQ(state.stats.particles, 9);
  EXPECT_NE(state.state_hash, 0u);
}

TEST(Commands, QueryContactsFiltersAndSendsLargeResultsInChunks) {
  Loaded s("contacts", kCommandsQueryContacts, [](auto& o) { o.contact_chunk = 5; });
  s.compress();
  s.client.cycle(40);
  const protocol::Reply all = s.client.query_contacts();
  EXPECT_EQ(all.total_contacts, 24u);
  EXPECT_EQ(all.contacts.size(), 24u);  // joined from five chunks of at most 5
  EXPECT_EQ(all.chunk, 4u);
  EXPECT_TRUE(all.last);
  protocol::ContactQueryArgs on_top;
  on_top.wall_set = true;
  on_top.wall = "top";
  on_top.chunk_size = 1;
  const protocol::Reply top = s.client.query_contacts(on_top);
  EXPECT_EQ(top.contacts.size(), 3u);
  EXPECT_EQ(top.chunk, 2u);
  for (const auto& c : top.contacts) EXPECT_EQ(c.second_wall, 2);
  protocol::ContactQueryArgs box;
  box.box_set = true;
  box.box_min = {0, 0, 0};
  box.box_max = {300, 100, 0};  // the bottom row and its walls
  for (const auto& c : s.client.query_contacts(box).contacts) EXPECT_LE(c.point.y, 100.0);
  protocol::ContactQueryArgs strong;
  strong.min_normal_force = 0.5 * all.contacts.front().normal_force;
  for (const auto& c : s.client.query_contacts(strong).contacts) EXPECT_GT(c.normal_force, *strong.min_normal_force);
}

TEST(Commands, SetParameterChangesTheSimulation) {
  Loaded s("params", kCommandsSetParameter);
  // The dashpots shorten the critical step (time_step.cpp): the discs'
  // rotation on one contact, omega^2 = k_s R^2 / I = 2 k_s / m, with
  // zeta = beta omega / 2; the case's fixed step stays.
  const double omega = std::sqrt(2.0 * 1.35e9 / (1000.0 * std::numbers::pi * 50.0 * 50.0));
  const double zeta = 0.02 * omega / 2.0;
  const double critical = 2.0 / omega * (std::sqrt(1.0 + zeta * zeta) - zeta);
  std::ostringstream shown;  // as replies show numbers: 6 significant digits
  shown << critical;
  const std::string steps = "; time step 0.01 s, critical step " + shown.str() + " s";
  EXPECT_EQ(s.client.set_parameter("contact_damping", 0.02).message, "contact_damping set to 0.02 s" + steps);
  // Global damping, taken at the middle of the step, leaves it where it was.
  EXPECT_EQ(s.client.set_parameter("global_damping", 4).message, "global_damping set to 4 1/s" + steps);
  // A damping under which the fixed step would be unstable is refused, and changes nothing.
  try {
    s.client.set_parameter("contact_damping", 50.0);
    ADD_FAILURE() << "a damping that leaves the step unstable was taken";
  } catch (const client::ServerError& error) {
    EXPECT_EQ(error.reply().status, protocol::ReplyStatus::kBadRequest) << error.what();
    EXPECT_NE(error.reply().message.find("below the time step 0.01 s"), std::string::npos) << error.what();
  }
  EXPECT_EQ(s.client.set_parameter("global_damping", 4).message, "global_damping set to 4 1/s" + steps);
  EXPECT_EQ(s.client.set_parameter("friction", 0.25, "disc").message, "friction of disc set to 0.25");
  EXPECT_EQ(s.client.set_gravity({0.0, -9.81, 0.0}).message, "gravity set to (0, -9.81) m/s^2");
  // A fraction is of the undamped step, 0.1075 s; 0.9 of it is above the damped one.
  try {
    s.client.set_parameter("time_step_fraction", 0.9);
    ADD_FAILURE() << "a fraction above the damped critical step was taken";
  } catch (const client::ServerError& error) {
    EXPECT_NE(error.reply().message.find("above the critical step " + shown.str() + " s"), std::string::npos)
        << error.what();
  }
  const protocol::Reply step = s.client.set_parameter("time_step_fraction", 0.05);
  EXPECT_NE(step.message.find("0.05 of the undamped critical step"), std::string::npos) << step.message;
  EXPECT_NEAR(step.state.time_step, 0.05 * 0.01 / 0.093, 2e-4);  // the case's fixed 0.01 was 0.093 of the undamped step
  // Gravity acts: the discs fall.
  s.client.cycle(100);
  EXPECT_GT(s.client.get_state().stats.kinetic_energy, 0.0);
}

TEST(Commands, SnapshotsSaveAndLoadByPathOrTransfer) {
  Loaded s("snapshots", kCommandsSnapshotPathAndTransfer);
  s.compress();
  s.client.cycle(60);
  const protocol::Reply saved = s.client.save_snapshot("runs/at60.snapshot");
  EXPECT_TRUE(std::filesystem::exists(saved.path)) << saved.path;
  EXPECT_NE(saved.path.find("runs/at60.snapshot"), std::string::npos);
  EXPECT_EQ(saved.total_bytes, std::filesystem::file_size(saved.path));
  const protocol::Reply sent = s.client.save_snapshot({}, true);
  EXPECT_EQ(sent.data, read_text(saved.path));  // the same state, the same bytes
  EXPECT_EQ(sent.total_bytes, sent.data.size());
  const std::uint64_t at60 = s.client.get_state().state_hash;
  s.client.cycle(30);
  EXPECT_NE(s.client.get_state().state_hash, at60);
  EXPECT_EQ(s.client.load_snapshot_on_server("runs/at60.snapshot").state.cycle, 60u);
  EXPECT_EQ(s.client.get_state().state_hash, at60);
  s.client.cycle(30);
  EXPECT_EQ(s.client.load_snapshot_bytes(sent.data).state.cycle, 60u);
  EXPECT_EQ(s.client.get_state().state_hash, at60);
  EXPECT_EQ(s.client.status().case_name, "nine_disc_damped");
}

TEST(Commands, ShutdownRepliesThenPublishesAFinalStatus) {
  auto server = std::make_unique<InProcessServer>(server_options("stopper", kCommandsShutdown));
  client::Client client(connect_options("stopper", kCommandsShutdown));
  client.load_case_file(case_file(kNineDisc));
  std::mutex mutex;
  std::vector<protocol::Status> seen;
  client::TelemetrySubscription watcher(client,
                                        {.plate_forces = {}, .contact_stats = {}, .status = [&](const auto& st) {
                                           std::lock_guard lock(mutex);
                                           seen.push_back(st);
                                         }});
  ASSERT_TRUE(eventually([&] { return watcher.matched_publishers() > 0; }, 10s));
  EXPECT_EQ(client.stop().message, "nothing was running");
  EXPECT_EQ(client.shutdown().message, "shutting down");
  server->server().wait();
  EXPECT_TRUE(eventually(
      [&] {
        std::lock_guard lock(mutex);
        return !seen.empty() && seen.back().state == ServerState::kShutdown;
      },
      10s));
  std::lock_guard lock(mutex);
  EXPECT_EQ(seen.back().message, "shut down at cycle 0");
  // The case's tables were written to the output directory.
  const auto directory = server->server().options().output_directory / "nine_disc_damped";
  for (const char* file : {"walls.csv", "assembly.csv", "contacts.csv", "particles.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(directory / file)) << file;
  }
}

TEST(Commands, TelemetryFollowsSimulatedTime) {
  Loaded s("timed", kCommandsTelemetryBySimulatedTime, [](auto& o) {
    o.telemetry_cycles = 0;
    o.telemetry_seconds = 0.25;  // 25 cycles of 0.01 s
  });
  std::mutex mutex;
  std::vector<std::uint64_t> cycles;
  client::TelemetrySubscription telemetry(s.client, {.plate_forces =
                                                         [&](const auto& p) {
                                                           std::lock_guard lock(mutex);
                                                           cycles.push_back(p.cycle);
                                                         },
                                                     .contact_stats = {},
                                                     .status = {}});
  ASSERT_TRUE(eventually([&] { return telemetry.matched_publishers() > 0; }, 10s));
  s.client.cycle(110);
  ASSERT_TRUE(eventually(
      [&] {
        std::lock_guard lock(mutex);
        return !cycles.empty() && cycles.back() == 110;
      },
      10s));
  std::lock_guard lock(mutex);
  // The sample of the load (cycle 0) comes first: the recent history a
  // subscription is given when it joins (transient-local, DDS.md).
  EXPECT_EQ(cycles, (std::vector<std::uint64_t>{0, 25, 50, 75, 100, 110}));
}

}  // namespace
}  // namespace dem::test

namespace dem::test {
namespace {

TEST(Commands, AThreeDimensionalCaseRunsThroughTheSameCommands) {
  InProcessServer server(server_options("spheres", kCommandsThreeDimensional));
  client::Client client(connect_options("spheres", kCommandsThreeDimensional));
  // 2000 spheres falling into a box of five rectangular walls.
  const auto box = std::filesystem::path(DEM_CASES_DIR) / "validation" / "box_settle.case.txtpb";
  const protocol::Reply loaded = client.load_case_on_server(box.string());
  EXPECT_EQ(loaded.state.dimension, 3);
  EXPECT_EQ(loaded.state.particles, 2000);
  EXPECT_EQ(loaded.state.walls, 5);
  client.set_gravity({0.0, 0.0, -20.0});  // a z component is a 3D world's own
  client.cycle(300);
  const protocol::Reply state = client.get_state();
  ASSERT_EQ(state.plates.walls.size(), 5u);
  EXPECT_EQ(state.plates.walls[0].name, "floor");
  EXPECT_DOUBLE_EQ(state.plates.walls[0].area, 0.03 * 0.03);  // a rectangle's area
  EXPECT_DOUBLE_EQ(state.plates.walls[1].area, 0.03 * 0.18);
  EXPECT_NE(client.set_wall_velocity("floor", {0.0, 0.0, 1e-3}, {0.0, 0.0, 0.1}).message.find("(0, 0, 0.001) m/s"),
            std::string::npos);

  // Snapshot and continuation, in 3D.
  const std::string saved = client.save_snapshot({}, true).data;
  client.cycle(200);
  const std::uint64_t uninterrupted = client.get_state().state_hash;
  EXPECT_EQ(client.load_snapshot_bytes(saved).state.dimension, 3);
  client.cycle(200);
  EXPECT_EQ(client.get_state().state_hash, uninterrupted);
  // Queries look at z too.
  protocol::ContactQueryArgs low;
  low.box_set = true;
  low.box_min = {0.0, 0.0, 0.0};
  low.box_max = {0.03, 0.03, 0.01};
  for (const auto& c : client.query_contacts(low).contacts) EXPECT_LE(c.point.z, 0.01);
}

}  // namespace
}  // namespace dem::test
