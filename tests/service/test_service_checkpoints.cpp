// Crash recovery of dem_server (docs/RELIABILITY.md): a server killed with
// SIGKILL and started again with --resume continues from its newest
// checkpoint - a one-shot run ends with the same final state, the same
// tables and ParaView files, byte for byte, as one never interrupted; an interactive server
// takes up the world of the checkpoint, and the same commands then end in
// the same state.
#include <gtest/gtest.h>
#include <signal.h>

#include "service_test_support.h"

namespace dem::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> server_arguments(const std::string& name, std::uint32_t domain, const fs::path& out,
                                          const fs::path& case_path, std::vector<std::string> more) {
  std::vector<std::string> arguments = {
      "--name",     name,        "--domain", std::to_string(domain), "--case", case_path.string(), "--out",
      out.string(), "--threads", "1",        "--log-level",          "warn"};
  arguments.insert(arguments.end(), more.begin(), more.end());
  return arguments;
}

TEST(Checkpoints, AOneShotRunKilledAndResumedEndsAsOneNeverInterrupted) {
  const fs::path case_path = fs::path(DEM_CASES_DIR) / "miyata" / "cs_reduced.case.txtpb";
  const fs::path whole = output_directory("checkpoints_whole");
  const fs::path killed = output_directory("checkpoints_killed");
  const std::uint32_t domain = kCheckpointsOneShot;
  ServerProcess first(
      server_arguments("whole", domain, whole, case_path, {"--run-and-exit", "--vtk-interval", "5000"}));
  ASSERT_EQ(first.wait(120s), 0);

  // Killed in the loading stage (from cycle 25,100), the analyses under way.
  ServerProcess second(server_arguments("killed", domain, killed, case_path,
                                        {"--run-and-exit", "--vtk-interval", "5000", "--checkpoint-cycles", "5000"}));
  const fs::path directory = killed / "miyata_cs_reduced";
  ASSERT_TRUE(eventually([&] { return newest_checkpoint(directory) >= 40000; }, 120s));
  second.signal(SIGKILL);
  second.wait(10s);
  EXPECT_FALSE(fs::exists(directory / "final.snapshot"));

  // Another name: the killed server's stays on the domain until its lease runs out.
  ServerProcess third(
      server_arguments("resumed", domain, killed, case_path,
                       {"--run-and-exit", "--vtk-interval", "5000", "--resume", "--checkpoint-cycles", "5000"}));
  ASSERT_EQ(third.wait(120s), 0);
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(whole / "miyata_cs_reduced")) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(read_text(entry.path()), read_text(directory / name)) << name << " differs";
    ++compared;
  }
  EXPECT_GE(compared, 16);  // every table, the analyses, final.snapshot, the ParaView series
  // The ParaView steps: those before the checkpoint kept, none the killed server wrote after it left over.
  int steps = 0;
  for (const auto& entry : fs::directory_iterator(whole / "miyata_cs_reduced" / "vtk")) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(read_text(entry.path()), read_text(directory / "vtk" / name)) << name << " differs";
    ++steps;
  }
  EXPECT_GE(steps, 3 * 8);
  int resumed_steps = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(directory / "vtk")) ++resumed_steps;
  EXPECT_EQ(resumed_steps, steps);
}

TEST(Checkpoints, AnInteractiveServerKilledAndResumedTakesUpItsWorld) {
  const fs::path case_path = case_file("nine_disc_damped");
  const std::uint32_t domain = kCheckpointsInteractive;
  std::uint64_t whole_hash = 0;
  const fs::path whole = output_directory("interactive_whole");
  {
    ServerProcess server(server_arguments("whole", domain, whole, case_path, {}));
    client::Client client(connect_options("whole", domain));
    client.set_wall_velocity("top", {0, -1, 0});
    client.cycle(3000);
    whole_hash = client.get_state().state_hash;
    client.shutdown();
    EXPECT_EQ(server.wait(20s), 0);
  }
  const fs::path out = output_directory("interactive_killed");
  const std::vector<std::string> checkpointing = {"--checkpoint-cycles", "500"};
  std::uint64_t resumed_at = 0;
  {
    ServerProcess server(server_arguments("killed", domain, out, case_path, checkpointing));
    client::Client client(connect_options("killed", domain));
    client.set_wall_velocity("top", {0, -1, 0});
    client.start_cycle(3000);
    ASSERT_TRUE(eventually([&] { return newest_checkpoint(out / "nine_disc_damped") >= 1500; }, 60s));
    server.signal(SIGKILL);
    server.wait(10s);
    resumed_at = newest_checkpoint(out / "nine_disc_damped");
  }
  std::vector<std::string> resuming = checkpointing;
  resuming.push_back("--resume");
  // Another name: the killed server's stays on the domain until its lease runs out.
  ServerProcess server(server_arguments("resumed", domain, out, case_path, resuming));
  client::Client client(connect_options("resumed", domain));
  const protocol::Reply state = client.get_state();
  EXPECT_EQ(state.state.cycle, resumed_at);
  ASSERT_LT(resumed_at, 3000u);
  client.cycle(static_cast<std::int64_t>(3000 - resumed_at));  // the wall's motion is in the state
  EXPECT_EQ(client.get_state().state_hash, whole_hash);
  client.shutdown();
  EXPECT_EQ(server.wait(20s), 0);
  EXPECT_EQ(read_text(out / "nine_disc_damped" / "walls.csv"), read_text(whole / "nine_disc_damped" / "walls.csv"));
}

}  // namespace
}  // namespace dem::test
