// The engine's health status as a server command acts on it: a cycle that
// blows up ends failed with the reason, the last good state is written
// beside the tables and the world goes back to it, and the server - in
// error - still answers, reads and saves it.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/io/snapshot_file.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::ReplyStatus;
using protocol::ServerState;

TEST(Health, ACycleThatBlowsUpFailsAndKeepsTheLastGoodState) {
  service::ServerOptions options = server_options("health", kHealthCycleBlowUp);
  InProcessServer server(options);
  client::Client client(connect_options("health", kHealthCycleBlowUp));
  // Stable while nothing presses; unstable once the walls press the discs
  // (tests/service/data/blows_up.case.txtpb).
  client.load_case_file(std::filesystem::path(DEM_SERVICE_TEST_DATA) / "blows_up.case.txtpb");
  ASSERT_TRUE(client.cycle(100).ok());
  client.set_wall_velocity("top", {0, -12, 0});
  client.set_wall_velocity("bottom", {0, 12, 0});
  const std::optional<protocol::Reply> reply = client.await(client.start_cycle(1000), 60s);
  ASSERT_TRUE(reply);
  const protocol::Reply& failed = *reply;
  EXPECT_EQ(failed.status, ReplyStatus::kFailed);
  EXPECT_NE(failed.message.find("the run is unhealthy at cycle "), std::string::npos) << failed.message;
  // Energy from nowhere (with the energy budget), a particle flung out or
  // the overlaps it causes: which an assessment sees first depends on when
  // it comes (they are paced by wall time).
  EXPECT_TRUE(failed.message.find("J of energy appeared without work done") != std::string::npos ||
              failed.message.find("of its radius in a step") != std::string::npos ||
              failed.message.find("the particles pass through each other") != std::string::npos)
      << failed.message;
  EXPECT_LT(failed.cycles_run, 1000u);
  EXPECT_EQ(failed.state.state, ServerState::kError);

  // The last good state is on disk, and the world is back at it.
  const auto path = options.output_directory / "blows_up" / "last_good.snapshot";
  ASSERT_TRUE(std::filesystem::exists(path)) << failed.message;
  const io::LoadedSnapshot good = io::read_snapshot_file(path);
  EXPECT_GE(good.snapshot.cycle, 100u);
  EXPECT_NE(failed.message.find("the world is back at the last good state, cycle " +
                                std::to_string(good.snapshot.cycle) + ", which is in " + path.string()),
            std::string::npos)
      << failed.message;
  const protocol::Reply state = client.get_state();
  EXPECT_EQ(state.state.state, ServerState::kError);
  EXPECT_EQ(state.state.cycle, good.snapshot.cycle);
  EXPECT_EQ(state.state_hash, World(good.snapshot).state_hash());
  EXPECT_TRUE(std::isfinite(state.stats.kinetic_energy));

  // In error it saves that state, and refuses to cycle until a load.
  EXPECT_TRUE(client.save_snapshot("saved_after_failure.snapshot").ok());
  const std::optional<protocol::Reply> refused = client.await(client.start_cycle(10), 10s);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, ReplyStatus::kRefused);
  EXPECT_EQ(client.load_snapshot_on_server("saved_after_failure.snapshot").state.state, ServerState::kLoaded);
}

}  // namespace
}  // namespace dem::test
