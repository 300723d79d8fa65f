// The one-shot mode, dem_server --case FILE --run-and-exit, as a batch job
// runs it: the case's loading programme to its end with the same result as
// the engine's own run_stage, its tables and final snapshot, telemetry and
// commands while it runs, a stop or SIGTERM (exit 4), a failed run (exit 1
// with the last good state), bad starts, and configuration by environment.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cmath>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>

#include "dem/client/telemetry.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/snapshot_file.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::ServerState;

std::vector<std::vector<std::string>> csv_rows(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream parts(line);
    for (std::string field; std::getline(parts, field, ',');) fields.push_back(field);
    rows.push_back(std::move(fields));
  }
  return rows;
}

// The nine-disc case with some of its text replaced (from, to).
std::filesystem::path variant(const std::filesystem::path& directory,
                              const std::vector<std::pair<std::string, std::string>>& changes) {
  std::string text = read_text(case_file("nine_disc_damped"));
  for (const auto& [from, to] : changes) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const auto path = directory / "variant.case.txtpb";
  std::ofstream(path) << text;
  return path;
}

// Its "hold" stage made endless, for runs that are stopped. Nine discs cycle
// at millions of cycles a second: the case's tables every 10 cycles would
// write some 25 MB a second (686 MB once, where a stop took long), so they
// are written every 100,000 cycles here; telemetry keeps its own interval.
std::filesystem::path long_variant(const std::filesystem::path& directory) {
  return variant(directory, {{"cycles: 2960", "cycles: 2000000000"}, {"interval: 10\n", "interval: 100000\n"}});
}

std::vector<std::string> one_shot(const std::string& name, Domain domain, const std::filesystem::path& out,
                                  const std::filesystem::path& case_path, const std::string& telemetry_cycles) {
  return {"--name",
          name,
          "--domain",
          std::to_string(domain),
          "--case",
          case_path.string(),
          "--run-and-exit",
          "--threads",
          "1",
          "--out",
          out.string(),
          "--telemetry-cycles",
          telemetry_cycles,
          "--log-level",
          "warn"};
}

TEST(OneShot, RunsTheProgrammeToItsEndAsTheEngineDoesAndExitsZero) {
  const auto out = output_directory("one_shot_complete");
  ServerProcess process(one_shot("batch", kOneShotComplete, out, case_file("nine_disc_damped"), "100"));
  ASSERT_EQ(process.wait(120s), 0);

  // The engine's own run of the same stages, one thread as the server's.
  io::CaseDefinition definition = io::convert_case(io::load_case_file(case_file("nine_disc_damped")).message);
  definition.world.threads = 1;
  World engine(definition.world);
  for (const StageDef& stage : definition.stages) run_stage(engine, stage);

  const auto results = out / "nine_disc_damped";
  const io::LoadedSnapshot final_state = io::read_snapshot_file<2>(results / "final.snapshot");
  EXPECT_EQ(final_state.info.case_name, "nine_disc_damped");
  EXPECT_EQ(final_state.snapshot.cycle, 3000u);
  EXPECT_EQ(World(final_state.snapshot).state_hash(), engine.state_hash());

  // A row per stage: compress (40 cycles), hold (2960).
  const auto stages = csv_rows(results / "stages.csv");
  ASSERT_EQ(stages.size(), 3u);
  EXPECT_EQ(stages[0], (std::vector<std::string>{"stage", "name", "cycles_run", "condition_met", "cycle", "time"}));
  EXPECT_EQ(stages[1][1], "compress");
  EXPECT_EQ(stages[1][2], "40");
  EXPECT_EQ(stages[2][1], "hold");
  EXPECT_EQ(stages[2][4], "3000");

  // The time series at the case's interval (10 cycles), not the telemetry's
  // (100): cycles 0, 10, ..., 3000, each once, four walls each.
  const auto walls = csv_rows(results / "walls.csv");
  ASSERT_EQ(walls.size(), 1u + 301u * 4u);
  std::set<std::string> cycles;
  for (std::size_t i = 1; i < walls.size(); ++i) cycles.insert(walls[i][0]);
  EXPECT_EQ(cycles.size(), 301u);
  EXPECT_EQ(csv_rows(results / "assembly.csv").size(), 1u + 301u);
  EXPECT_GT(csv_rows(results / "contacts.csv").size(), 1u);
  EXPECT_EQ(csv_rows(results / "particles.csv").size(), 1u + 9u);
}

TEST(OneShot, PublishesTelemetryAndAnswersCommandsWhileItRunsAndAStopEndsIt) {
  const auto out = output_directory("one_shot_stop");
  const auto long_case = long_variant(out);
  ServerProcess process(one_shot("longrun", kOneShotStop, out, long_case, "1000"));
  client::Client client(connect_options("longrun", kOneShotStop));
  std::mutex mutex;
  std::vector<std::uint64_t> samples;
  client::TelemetrySubscription telemetry(client, {.plate_forces =
                                                       [&](const protocol::PlateForces& p) {
                                                         std::lock_guard lock(mutex);
                                                         samples.push_back(p.cycle);
                                                       },
                                                   .contact_stats = {},
                                                   .status = {}});
  // The programme shows as a running command, with its progress.
  ASSERT_TRUE(client.wait_for_status(
      [](const protocol::Status& s) { return s.state == ServerState::kRunning && s.command_cycles_done > 0; }, 20s));
  EXPECT_EQ(client.status().command, "programme");
  EXPECT_EQ(client.status().command_cycles_total, 2000000040u);
  ASSERT_TRUE(eventually(
      [&] {
        std::lock_guard lock(mutex);
        return samples.size() >= 3;
      },
      30s));
  {
    std::lock_guard lock(mutex);
    for (std::size_t i = 1; i < samples.size(); ++i) EXPECT_GT(samples[i], samples[i - 1]);
    // Every 1000 cycles, and where the compress stage ended (cycle 40).
    for (const std::uint64_t cycle : samples) EXPECT_TRUE(cycle % 1000 == 0 || cycle == 40) << cycle;
  }
  // Commands are answered between cycles; a second run is refused.
  EXPECT_EQ(client.get_state().plates.walls.size(), 4u);
  EXPECT_THROW(client.cycle(10, 20s), client::ServerError);

  const protocol::Reply stopped = client.stop();
  EXPECT_NE(stopped.message.find("stopping the programme at cycle"), std::string::npos) << stopped.message;
  EXPECT_TRUE(client.wait_for_status(
      [](const protocol::Status& s) {
        return s.state == ServerState::kShutdown && s.message.find("programme stopped") != std::string::npos;
      },
      20s));
  EXPECT_EQ(process.wait(30s), 4);
  const auto results = out / "nine_disc_damped";
  const io::LoadedSnapshot final_state = io::read_snapshot_file<2>(results / "final.snapshot");
  EXPECT_GT(final_state.snapshot.cycle, 40u);
  const auto stages = csv_rows(results / "stages.csv");
  ASSERT_EQ(stages.size(), 3u);  // the hold stage, cut short
  EXPECT_EQ(stages[2][4], std::to_string(final_state.snapshot.cycle));
}

TEST(OneShot, SigtermStopsItWithAFinalSnapshot) {
  const auto out = output_directory("one_shot_sigterm");
  const auto long_case = long_variant(out);
  ServerProcess process(one_shot("term", kOneShotSigterm, out, long_case, "1000"));
  client::Client client(connect_options("term", kOneShotSigterm));
  ASSERT_TRUE(client.wait_for_status(
      [](const protocol::Status& s) { return s.state == ServerState::kRunning && s.command_cycles_done > 0; }, 20s));
  process.signal(SIGTERM);
  EXPECT_EQ(process.wait(30s), 4);
  const io::LoadedSnapshot final_state = io::read_snapshot_file<2>(out / "nine_disc_damped" / "final.snapshot");
  EXPECT_GT(final_state.snapshot.cycle, 0u);
  EXPECT_TRUE(std::filesystem::exists(out / "nine_disc_damped" / "particles.csv"));
}

TEST(OneShot, AFailedRunExitsOneWithTheErrorLoggedAndTheLastGoodState) {
  const auto out = output_directory("one_shot_failure");
  const auto log = out / "dem_server.log";
  // The server's log goes to a file, to look for the error in it.
  const std::string command =
      std::string(DEM_SERVER_PROGRAM) + " --name boom --domain " + std::to_string(kOneShotFailure) +
      " --case " DEM_SERVICE_TEST_DATA "/blows_up.case.txtpb --run-and-exit --threads 1 --out " + out.string() + " 2>" +
      log.string();
  const pid_t pid = spawn("/bin/sh", {"-c", command});
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);

  // The case rests for 100 cycles, then blows up in its second stage: the
  // engine's health status names it before the numbers overflow.
  const std::string text = read_text(log);
  EXPECT_NE(text.find("[error] programme failed: the run is unhealthy in stage 2/2 compress at cycle 1"),
            std::string::npos)
      << text;
  // Energy from nowhere (with the energy budget), a particle flung out, or
  // the overlaps it causes (assessments are paced by wall time).
  EXPECT_TRUE(text.find("J of energy appeared without work done") != std::string::npos ||
              text.find("of its radius in a step") != std::string::npos ||
              text.find("the particles pass through each other") != std::string::npos)
      << text;
  // The last good state is written, and it is good: from the end of the
  // first stage on, before the failure, finite.
  const auto results = out / "blows_up";
  ASSERT_TRUE(std::filesystem::exists(results / "last_good.snapshot")) << text;
  EXPECT_FALSE(std::filesystem::exists(results / "final.snapshot"));
  const io::LoadedSnapshot state = io::read_snapshot_file<2>(results / "last_good.snapshot");
  EXPECT_GE(state.snapshot.cycle, 100u);
  EXPECT_LT(state.snapshot.cycle, 200u);
  EXPECT_TRUE(std::isfinite(World(state.snapshot).assembly_measures().kinetic_energy));
  EXPECT_NE(text.find("the world is back at the last good state, cycle " + std::to_string(state.snapshot.cycle) +
                      ", which is in " + (results / "last_good.snapshot").string()),
            std::string::npos)
      << text;
  // The stage that ended before the failure is in stages.csv.
  const auto stages = csv_rows(results / "stages.csv");
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_EQ(stages[1][1], "rest");
}

TEST(OneShot, BadStartsExitWithTheirCodes) {
  const auto out = output_directory("one_shot_bad");
  const std::string domain = std::to_string(kOneShotBadStarts);
  // Nothing to run: no case.
  ServerProcess no_case({"--name", "bad", "--domain", domain, "--run-and-exit", "--log-level", "off"});
  EXPECT_EQ(no_case.wait(20s), 2);
  // A case without stages.
  const auto stageless = out / "stageless.case.txtpb";
  std::string text = read_text(case_file("nine_disc_damped"));
  text.erase(text.find("stage {"));
  std::ofstream(stageless) << text;
  ServerProcess no_stages({"--name", "bad", "--domain", domain, "--case", stageless.string(), "--run-and-exit", "--out",
                           out.string(), "--log-level", "off"});
  EXPECT_EQ(no_stages.wait(20s), 3);
}

// As a container or a batch script configures it: every setting from the
// environment, no arguments.
TEST(OneShot, TakesItsSettingsFromTheEnvironment) {
  const auto out = output_directory("one_shot_environment");
  ASSERT_EQ(setenv("DEM_SERVER", "fromenv", 1), 0);
  ASSERT_EQ(setenv("DEM_DOMAIN", std::to_string(kOneShotEnvironment).c_str(), 1), 0);
  ASSERT_EQ(setenv("DEM_CASE", case_file("nine_disc_damped").c_str(), 1), 0);
  ASSERT_EQ(setenv("DEM_OUT", out.c_str(), 1), 0);
  ASSERT_EQ(setenv("DEM_RUN_AND_EXIT", "1", 1), 0);
  ASSERT_EQ(setenv("DEM_THREADS", "1", 1), 0);
  ASSERT_EQ(setenv("DEM_LOG_LEVEL", "warn", 1), 0);
  ServerProcess process({});
  for (const char* name :
       {"DEM_SERVER", "DEM_DOMAIN", "DEM_CASE", "DEM_OUT", "DEM_RUN_AND_EXIT", "DEM_THREADS", "DEM_LOG_LEVEL"}) {
    unsetenv(name);
  }
  EXPECT_EQ(process.wait(120s), 0);
  EXPECT_EQ(io::read_snapshot_file<2>(out / "nine_disc_damped" / "final.snapshot").snapshot.cycle, 3000u);
}

}  // namespace
}  // namespace dem::test
