// A whole experiment through the product as users run it: dem_server in its
// own process on loopback, driven through the client library. The nine-disc
// test (Cundall & Strack 1979, Figs. 5-6) stage by stage; every plate-force
// sample the server publishes equals what the engine computes directly.
#include <gtest/gtest.h>
#include <signal.h>

#include <map>
#include <mutex>

#include "dem/client/telemetry.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::ServerState;

TEST(Experiment, NineDiscTestThroughDemServerMatchesTheEngine) {
  const std::string domain = std::to_string(kExperimentNineDisc);
  ServerProcess process({"--name", "nine", "--domain", domain, "--telemetry-cycles", "10", "--threads", "1", "--out",
                         output_directory("experiment").string(), "--log-level", "warn"});
  client::Client client(connect_options("nine", kExperimentNineDisc));
  std::mutex mutex;
  std::map<std::uint64_t, protocol::PlateForces> published;
  client::TelemetrySubscription telemetry(client, {.plate_forces =
                                                       [&](const protocol::PlateForces& p) {
                                                         std::lock_guard lock(mutex);
                                                         published[p.cycle] = p;
                                                       },
                                                   .contact_stats = {},
                                                   .status = {}});
  ASSERT_TRUE(eventually([&] { return telemetry.matched_publishers() > 0; }, 10s));

  // The same case in an engine of our own, one thread as the server's.
  io::CaseDefinition definition = io::convert_case(io::load_case_file(case_file("nine_disc_damped")).message);
  definition.world.threads = 1;
  World engine(definition.world);
  client.load_case_file(case_file("nine_disc_damped"));
  std::map<std::uint64_t, std::vector<WallMeasure>> expected;
  for (const StageDef& stage : definition.stages) {
    for (const auto& [wall, motion] : stage.wall_motions) {
      engine.set_wall_motion(wall, motion);
      client.set_wall_velocity(engine.wall(wall).name, {motion.velocity.x(), motion.velocity.y(), 0.0},
                               {0.0, 0.0, motion.angular_velocity});
    }
    client.cycle(static_cast<std::int64_t>(stage.cycles));
    for (std::uint64_t done = 0; done < stage.cycles; done += 10) {
      engine.cycle(10);
      expected[engine.cycle_count()] = engine.wall_measures();
    }
  }
  ASSERT_EQ(engine.cycle_count(), 3000u);
  ASSERT_TRUE(eventually(
      [&] {
        std::lock_guard lock(mutex);
        return published.count(3000) > 0;
      },
      10s));

  std::lock_guard lock(mutex);
  std::size_t compared = 0;
  for (const auto& [cycle, measures] : expected) {
    ASSERT_EQ(published.count(cycle), 1u) << "no telemetry at cycle " << cycle;
    const protocol::PlateForces& sample = published.at(cycle);
    ASSERT_EQ(sample.walls.size(), measures.size());
    EXPECT_EQ(sample.cycle, cycle);
    for (std::size_t w = 0; w < measures.size(); ++w) {
      const protocol::WallForce& got = sample.walls[w];
      const WallMeasure& want = measures[w];
      const WallDef& wall = engine.wall(WallId::from_index(w));
      EXPECT_EQ(got.name, wall.name);
      EXPECT_EQ(got.normal_force, want.normal_force) << wall.name << " at " << cycle;
      EXPECT_EQ(got.force.x, want.force.x());
      EXPECT_EQ(got.force.y, want.force.y());
      EXPECT_EQ(got.moment.z, want.moment);
      EXPECT_EQ(got.contacts, want.contacts);
      EXPECT_EQ(got.position.x, want.point.x());
      EXPECT_EQ(got.position.y, want.point.y());
      // Normal stress: the force over the wall's length times a unit depth.
      EXPECT_EQ(got.normal_stress, want.normal_force / ((wall.h2 - wall.h1) * 1.0));
      // Settlement: the displacement along the wall's normal, towards the discs.
      EXPECT_EQ(got.settlement, want.displacement.dot(counter_clockwise_perpendicular(wall.direction)) + 0.0);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 4u * 300u);
  // The compression loaded every wall, and the hold kept the walls where they were.
  EXPECT_GT(published.at(3000).walls[2].normal_stress, 1e6);
  EXPECT_NEAR(published.at(3000).walls[2].settlement, 12.0 * 0.4, 1e-9);

  // A clean stop: the shutdown command, exit code 0.
  client.shutdown();
  EXPECT_EQ(process.wait(20s), 0);
}

TEST(Experiment, SignalsStopTheServerGracefully) {
  const std::string domain = std::to_string(kExperimentSignals);
  ServerProcess process({"--name", "sig", "--domain", domain, "--threads", "1", "--case",
                         case_file("nine_disc_damped").string(), "--out", output_directory("signals").string(),
                         "--log-level", "warn"});
  client::Client client(connect_options("sig", kExperimentSignals));
  EXPECT_EQ(client.status().case_name, "nine_disc_damped");  // the case given at start
  const std::uint64_t request = client.start_cycle(1'000'000'000);
  ASSERT_TRUE(client.wait_for_status([&](const auto& s) { return s.command_request_id == request; }, 10s));
  process.signal(SIGINT);
  // The running command is answered, a final status published, and the exit is clean.
  const auto reply = client.await(request, 20s);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->status, protocol::ReplyStatus::kCancelled);
  EXPECT_EQ(reply->message, "the server is shutting down");
  EXPECT_TRUE(client.wait_for_status([](const auto& s) { return s.state == ServerState::kShutdown; }, 20s));
  EXPECT_EQ(process.wait(20s), 0);
}

TEST(Experiment, BadStartsExitWithTheirCodes) {
  // A name that is not a ROS 2 name token: bad arguments.
  ServerProcess bad_name({"--name", "no-dashes", "--domain", std::to_string(kExperimentSignals)});
  EXPECT_EQ(bad_name.wait(20s), 2);
  // An initial case that is not valid.
  const auto broken = output_directory("bad_start") / "broken.case.txtpb";
  std::ofstream(broken) << "material { name: \"x\" }\nwall { name: \"w\" h1: 1 h2: 1 material: \"x\" }\n";
  ServerProcess bad_case({"--name", "bad", "--domain", std::to_string(kExperimentSignals), "--case", broken.string(),
                          "--log-level", "off"});
  EXPECT_EQ(bad_case.wait(20s), 3);
}

}  // namespace
}  // namespace dem::test
