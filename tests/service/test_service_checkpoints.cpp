// Crash recovery of dem_server (docs/RELIABILITY.md): a server killed with
// SIGKILL and started again with --resume continues from its newest
// checkpoint - a one-shot run ends with the same final state, the same
// tables and ParaView files, byte for byte, as one never interrupted; an interactive server
// takes up the world of the checkpoint, and the same commands then end in
// the same state; twenty kills at random moments of one run change nothing
// either. An earlier run's output is continued with --resume, or replaced
// with --overwrite, never cut unasked.
#include <gtest/gtest.h>
#include <signal.h>

#include <cstdio>
#include <random>

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

// Every regular file of a one-shot run's case directory (tables, analyses,
// final.snapshot) and of its vtk/ equal in `a` and `b`; how many compared.
int expect_same_files(const fs::path& a, const fs::path& b) {
  int compared = 0;
  for (const fs::path& directory : {fs::path(), fs::path("vtk")}) {
    if (!fs::exists(a / directory)) continue;
    for (const auto& entry : fs::directory_iterator(a / directory)) {
      if (!entry.is_regular_file()) continue;
      const fs::path name = directory / entry.path().filename();
      if (!fs::exists(b / name)) {
        ADD_FAILURE() << name << " is missing";
        continue;
      }
      EXPECT_EQ(read_text(a / name), read_text(b / name)) << name << " differs";
      ++compared;
    }
  }
  return compared;
}

// Twenty SIGKILLs of a one-shot run, each at a random moment after the run
// passed one more checkpoint, each followed by a start with --resume (under
// another name: the killed one's stays on the domain until its lease runs
// out): the run ends with the uninterrupted run's final state and tables,
// byte for byte. The verification assembly runs 338,765 cycles in all.
TEST(Checkpoints, TwentyRandomKillsOfAOneShotRunEndAsOneNeverInterrupted) {
  const fs::path case_path = case_file("verification_assembly");
  const std::uint32_t domain = kCheckpointsRandomKills;
  const fs::path whole = output_directory("random_kills_whole");
  const fs::path killed = output_directory("random_kills_killed");
  const std::vector<std::string> one_shot = {"--run-and-exit", "--vtk-interval", "50000", "--checkpoint-cycles",
                                             "2500"};
  ServerProcess first(server_arguments("whole", domain, whole, case_path, one_shot));
  ASSERT_EQ(first.wait(180s), 0);

  std::mt19937 random(37);  // the same moments every run
  std::uniform_int_distribution<int> delay_ms(0, 100);
  const fs::path directory = killed / "verification_assembly";
  int kills = 0;
  std::uint64_t newest = 0;
  for (int life = 0; life < 20; ++life) {
    std::vector<std::string> arguments = one_shot;
    if (life > 0) arguments.push_back("--resume");
    ServerProcess server(server_arguments("life" + std::to_string(life), domain, killed, case_path, arguments));
    const std::uint64_t before = newest;
    ASSERT_TRUE(eventually([&] { return newest_checkpoint(directory) > before; }, 60s)) << "life " << life;
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(random)));
    server.signal(SIGKILL);
    server.wait(10s);
    newest = newest_checkpoint(directory);
    ASSERT_FALSE(fs::exists(directory / "final.snapshot")) << "the run ended before kill " << life + 1;
    ++kills;
    std::printf("kill %d: newest checkpoint at cycle %llu\n", kills, static_cast<unsigned long long>(newest));
  }
  std::vector<std::string> arguments = one_shot;
  arguments.push_back("--resume");
  ServerProcess last(server_arguments("resumed", domain, killed, case_path, arguments));
  ASSERT_EQ(last.wait(180s), 0);
  EXPECT_EQ(kills, 20);
  EXPECT_GE(expect_same_files(whole / "verification_assembly", directory), 6);  // final.snapshot: the state hash too
}

// A one-shot run started again without --resume into the directory of an
// earlier one cut its tables (assembly.csv from 3,317 lines to 32): it is
// refused, naming --resume and --overwrite, and leaves them as they were;
// with --overwrite it starts afresh and ends as the first did.
TEST(Checkpoints, AnEarlierRunsOutputIsContinuedOrReplacedNeverCut) {
  const fs::path case_path = case_file("nine_disc_damped");
  const std::uint32_t domain = kCheckpointsOutputInUse;
  const fs::path out = output_directory("output_in_use");
  ServerProcess first(server_arguments("first", domain, out, case_path, {"--run-and-exit"}));
  ASSERT_EQ(first.wait(60s), 0);
  const fs::path directory = out / "nine_disc_damped";
  const std::string walls = read_text(directory / "walls.csv");
  const std::string final_state = read_text(directory / "final.snapshot");

  ServerProcess again(server_arguments("again", domain, out, case_path, {"--run-and-exit"}));
  EXPECT_EQ(again.wait(60s), 3);  // the initial case cannot be loaded
  EXPECT_EQ(read_text(directory / "walls.csv"), walls);
  EXPECT_EQ(read_text(directory / "final.snapshot"), final_state);

  ServerProcess replaced(server_arguments("replaced", domain, out, case_path, {"--run-and-exit", "--overwrite"}));
  EXPECT_EQ(replaced.wait(60s), 0);
  EXPECT_EQ(read_text(directory / "walls.csv"), walls);
  EXPECT_EQ(read_text(directory / "final.snapshot"), final_state);
}

}  // namespace
}  // namespace dem::test
