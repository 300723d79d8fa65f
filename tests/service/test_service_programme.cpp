// The run_programme command: a loaded case's stages run on a server that
// takes commands, with the same result as the engine's own run_stage; a
// range of stages; its status and reply; a stop; Miyata's staged plate
// loading (trim, place the plate, lower it to a stress) through the
// command loop, with dem_run's plate loading analyses; and the requests it
// refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <mutex>
#include <tuple>
#include <vector>

#include "dem/client/telemetry.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::ReplyStatus;
using protocol::ServerState;

std::uint64_t engine_hash(const std::filesystem::path& case_path, std::size_t first, std::size_t count) {
  io::CaseDefinition definition = io::convert_case(io::load_case_file(case_path).message);
  definition.world.threads = 1;  // as the test server's
  World engine(definition.world);
  for (std::size_t i = first; i < first + count; ++i) run_stage(engine, definition.stages[i]);
  return engine.state_hash();
}

protocol::Reply error_reply(const std::function<void()>& command) {
  try {
    command();
  } catch (const client::ServerError& error) {
    return error.reply();
  }
  ADD_FAILURE() << "the command succeeded";
  return {};
}

TEST(ProgrammeCommand, RunsTheStagesAsTheEngineDoesThenTakesCommandsAgain) {
  InProcessServer server(server_options("stages", kProgrammeCommand));
  client::Client client(connect_options("stages", kProgrammeCommand));
  client.load_case_file(case_file("nine_disc_damped"));

  // compress (40 cycles), hold (2960).
  const protocol::Reply all = client.run_programme();
  EXPECT_TRUE(all.ok()) << all.message;
  EXPECT_EQ(all.cycles_run, 3000u);
  EXPECT_FALSE(all.condition_met);  // hold is of fixed length: no stop condition ended it
  EXPECT_NE(all.message.find("programme complete at cycle 3000"), std::string::npos) << all.message;
  EXPECT_EQ(all.state.state, ServerState::kLoaded);
  EXPECT_EQ(client.get_state().state_hash, engine_hash(case_file("nine_disc_damped"), 0, 2));

  // Commands work as before, and a range of stages runs on from where the world is.
  EXPECT_EQ(client.cycle(10).cycles_run, 10u);
  const protocol::Reply hold = client.run_programme(2, 1);
  EXPECT_TRUE(hold.ok()) << hold.message;
  EXPECT_EQ(hold.cycles_run, 2960u);
  EXPECT_EQ(client.get_state().state.cycle, 5970u);
}

TEST(ProgrammeCommand, MiyatasPlateLoadingRunsThroughTheCommandLoop) {
  // The reduced CS case: settle, trim and settle, place the plate and lower
  // it until it carries 900 kPa (Miyata et al. 2002, 3.2).
  const auto cs = std::filesystem::path(DEM_CASES_DIR) / "miyata" / "cs_reduced.case.txtpb";
  const service::ServerOptions options = server_options("miyata", kProgrammeCommandStop);
  InProcessServer server(options);
  client::Client client(connect_options("miyata", kProgrammeCommandStop));
  client.load_case_file(cs);

  const protocol::Reply prepared = client.run_programme(1, 2);
  ASSERT_TRUE(prepared.ok()) << prepared.message;
  const std::uint64_t loading = client.start_run_programme(3, 1);
  // This request's run: a status of the previous run_programme (request
  // before it) may still be the latest the client holds.
  const auto running = client.wait_for_status(
      [&](const protocol::Status& s) {
        return s.state == ServerState::kRunning && s.command == "run_programme" && s.command_request_id == loading;
      },
      30s);
  ASSERT_TRUE(running);
  EXPECT_EQ(running->command_client, client.client_id());
  EXPECT_EQ(running->command_request_id, loading);
  const auto reply = client.await(loading, 120s);
  ASSERT_TRUE(reply);
  ASSERT_TRUE(reply->ok()) << reply->message;
  EXPECT_TRUE(reply->condition_met);  // the last stage run ended on its stress, before its cap
  const protocol::Reply state = client.get_state();
  const auto& top = state.plates.walls.at(1);
  ASSERT_EQ(top.name, "top");
  std::printf("reduced CS through run_programme: top plate %.1f kPa at settlement %.4f m, %d contacts, cycle %llu\n",
              top.normal_stress / 1e3, top.settlement, top.contacts,
              static_cast<unsigned long long>(state.plates.cycle));
  EXPECT_GE(top.normal_stress, 900e3);  // the stage's stop condition
  EXPECT_LT(top.normal_stress, 950e3);
  EXPECT_GT(top.settlement, 0.0);  // counted from where the stage placed the plate
  // The same stages in the engine give the same state.
  EXPECT_EQ(state.state_hash, engine_hash(cs, 0, 3));

  // The plate loading analyses dem_run writes, written when the case is
  // replaced: a row per output interval of the loading stage, three states.
  client.load_case_file(cs);
  const auto tables = options.output_directory / "miyata_cs_reduced";
  const auto lines = [&](const char* file) {
    std::ifstream in(tables / file);
    int count = 0;
    for (std::string line; std::getline(in, line);) ++count;
    return count;
  };
  const int loading_rows = lines("compression.csv") - 1;
  std::printf("compression.csv: %d rows; compression_states.csv: %d states\n", loading_rows,
              lines("compression_states.csv") - 1);
  EXPECT_GT(loading_rows, 100);  // the loading stage: about 46,000 cycles at 100 a row
  EXPECT_EQ(lines("compression_states.csv") - 1, 3);
  EXPECT_GT(lines("plate_contacts.csv"), 1);
  EXPECT_GT(lines("force_tail.csv"), 1);
}

// run_programme in steps (programme_steps): the run returns every
// sample_every cycles of a stage and at each stage's end, the world waiting
// there; resumed from each reply it ends bit for bit where one run does.
TEST(ProgrammeCommand, InStepsReturnsAtExactCyclesAndEndsWhereOneRunDoes) {
  InProcessServer server(server_options("steps", kProgrammeSteps));
  client::Client client(connect_options("steps", kProgrammeSteps));
  client.load_case_file(case_file("nine_disc_damped"));  // compress (40 cycles), hold (2960)
  protocol::ProgrammeStepsArgs steps{.sample_every = 30};
  std::vector<std::tuple<std::uint32_t, std::uint64_t, bool, std::uint64_t>> returns;
  std::uint32_t stage = 1;
  for (int step = 0; step < 200; ++step) {
    const protocol::Reply reply = client.run_programme(stage, 0, 60s, steps);
    ASSERT_TRUE(reply.ok()) << reply.message;
    returns.emplace_back(reply.stage, reply.stage_cycles, reply.stage_ended, reply.state.cycle);
    EXPECT_EQ(reply.state.state, ServerState::kLoaded);
    if (reply.stage == 2 && reply.stage_ended) break;
    stage = reply.stage_ended ? reply.stage + 1 : reply.stage;
    steps.resume = true;
    steps.stage_cycles_done = reply.stage_ended ? 0 : reply.stage_cycles;
  }
  using Return = std::tuple<std::uint32_t, std::uint64_t, bool, std::uint64_t>;
  ASSERT_EQ(returns.size(), 2u + 98u + 1u);  // 30, 40 (compress's end), then 30 ... 2940 and 2960 of hold
  EXPECT_EQ(returns[0], Return(1, 30, false, 30));
  EXPECT_EQ(returns[1], Return(1, 40, true, 40));
  EXPECT_EQ(returns[2], Return(2, 30, false, 70));
  EXPECT_EQ(returns[99], Return(2, 2940, false, 2980));
  EXPECT_EQ(returns[100], Return(2, 2960, true, 3000));
  EXPECT_EQ(client.get_state().state_hash, engine_hash(case_file("nine_disc_damped"), 0, 2));

  // Bad steps are refused with nothing run.
  EXPECT_EQ(error_reply([&] { client.run_programme(2, 0, 10s, {.stage_cycles_done = 10}); }).message,
            "stage_cycles_done is for a resumed run: set resume");
  EXPECT_EQ(error_reply([&] { client.run_programme(2, 0, 10s, {.resume = true, .stage_cycles_done = 2960}); }).message,
            "stage 2 (\"hold\") runs at most 2960 cycles: it cannot be resumed after 2960");
  client.load_case_file(std::filesystem::path(DEM_CASES_DIR) / "miyata" / "cs_reduced.case.txtpb");
  const protocol::Reply off_check = error_reply([&] { client.run_programme(1, 0, 10s, {.sample_every = 150}); });
  EXPECT_EQ(off_check.status, ReplyStatus::kBadRequest);
  EXPECT_EQ(off_check.message,
            "sample_every 150 is not a multiple of stage 1 (\"settle\")'s condition check interval, 100 cycles: a "
            "run returns only where it resumes");
  EXPECT_EQ(error_reply([&] { client.run_programme(1, 0, 10s, {.resume = true, .stage_cycles_done = 50}); }).message,
            "stage 1 (\"settle\") resumes only on one of its condition checks, every 100 cycles, not after 50");
  EXPECT_EQ(client.get_state().state.cycle, 0u);
}

TEST(ProgrammeCommand, AStopEndsItCancelledAndBadRangesAreRefused) {
  InProcessServer server(server_options("refusals", kProgrammeCommandErrors));
  client::Client client(connect_options("refusals", kProgrammeCommandErrors));
  EXPECT_EQ(error_reply([&] { client.run_programme(); }).message,
            "run_programme refused: no case is loaded: load a case or a snapshot first");

  client.load_case_file(case_file("nine_disc_damped"));
  const protocol::Reply past = error_reply([&] { client.run_programme(3); });
  EXPECT_EQ(past.status, ReplyStatus::kBadRequest);
  EXPECT_EQ(past.message, "first_stage 3 is past the 2 stages of nine_disc_damped");
  EXPECT_EQ(error_reply([&] { client.run_programme(2, 2); }).message,
            "2 stages from stage 2 go past the 2 of nine_disc_damped");
  EXPECT_EQ(client.get_state().state.cycle, 0u);  // nothing was run

  // A snapshot carries no stages.
  client.save_snapshot("nine_disc.snapshot");
  client.load_snapshot_on_server("nine_disc.snapshot");
  EXPECT_EQ(error_reply([&] { client.run_programme(); }).message,
            "run_programme refused: nine_disc_damped has no stages (a snapshot keeps none; load the case)");

  // A long compression (300,000 cycles), stopped: the reply is cancelled
  // and the server takes commands again.
  client.load_case_file(case_file("verification_assembly"));
  const std::uint64_t request = client.start_run_programme();
  ASSERT_TRUE(client.wait_for_status([](const auto& s) { return s.state == ServerState::kRunning; }, 10s));
  const protocol::Reply twice = error_reply([&] { client.run_programme(); });
  EXPECT_EQ(twice.message, "run_programme refused: a command is already running: wait for it or stop it");
  client.stop();
  const auto stopped = client.await(request, 10s);
  ASSERT_TRUE(stopped);
  EXPECT_EQ(stopped->status, ReplyStatus::kCancelled);
  EXPECT_NE(stopped->message.find("programme stopped"), std::string::npos) << stopped->message;
  EXPECT_LT(stopped->cycles_run, 300000u);
  // The status published after the reply may come a moment after it.
  EXPECT_TRUE(client.wait_for_status([](const auto& s) { return s.state == ServerState::kLoaded; }, 10s));
  EXPECT_TRUE(client.cycle(5).ok());
}

// What a monitor, a dashboard and ParaView see of a programme run by
// command (Miyata's reduced CS: settle, trim and settle, load to 900 kPa):
// telemetry at each stage's end whatever the schedule - the last sample is
// the state the reply reports, the one where the stop condition is met;
// a ParaView series from the programme's first cycle, as dem_run's; and a
// status whose progress is the stages' own (the loading stage's share is
// its plate's stress over the 900 kPa it runs to, not its cycles over a
// cap of millions).
TEST(ProgrammeCommand, PublishesItsEndStartsItsSeriesAtItsStartAndShowsTheStagesProgress) {
  const auto cs = std::filesystem::path(DEM_CASES_DIR) / "miyata" / "cs_reduced.case.txtpb";
  service::ServerOptions options = server_options("ends", kProgrammeEnds);
  options.telemetry_cycles = 7000;  // a schedule the stages' ends do not fall on
  options.vtk_interval = 20000;
  InProcessServer server(options);
  client::Client client(connect_options("ends", kProgrammeEnds));
  std::mutex mutex;
  std::vector<std::uint64_t> sample_cycles;
  std::vector<protocol::Status> statuses;
  client::TelemetrySubscription telemetry(client, {.plate_forces =
                                                       [&](const protocol::PlateForces& p) {
                                                         std::lock_guard lock(mutex);
                                                         sample_cycles.push_back(p.cycle);
                                                       },
                                                   .status =
                                                       [&](const protocol::Status& s) {
                                                         std::lock_guard lock(mutex);
                                                         if (s.state == ServerState::kRunning) statuses.push_back(s);
                                                       }});
  ASSERT_TRUE(eventually([&] { return telemetry.matched_publishers() > 0; }, 10s));
  client.load_case_file(cs);
  const protocol::Reply reply = client.run_programme();
  ASSERT_TRUE(reply.ok()) << reply.message;
  const std::uint64_t end = reply.state.cycle;
  ASSERT_TRUE(eventually(
      [&] {
        std::lock_guard lock(mutex);
        return !sample_cycles.empty() && sample_cycles.back() == end;
      },
      10s));
  std::lock_guard lock(mutex);
  std::printf("programme ended at cycle %llu; %zu plate samples, the last at %llu\n",
              static_cast<unsigned long long>(end), sample_cycles.size(),
              static_cast<unsigned long long>(sample_cycles.back()));
  EXPECT_NE(end % options.telemetry_cycles, 0u) << "the test needs an end off the schedule";

  // The series' first step is the programme's first cycle.
  std::ifstream pvd(options.output_directory / "miyata_cs_reduced" / "particles.pvd");
  const std::string series((std::istreambuf_iterator<char>(pvd)), std::istreambuf_iterator<char>());
  const auto first_step = series.find("particles_");
  ASSERT_NE(first_step, std::string::npos) << series;
  EXPECT_EQ(series.substr(first_step, 20), "particles_0000000000") << series;

  // Progress: each of the three stages a third; the loading stage by its stress.
  // (The status that announces a stage, before its first cycle, says only
  // that it runs.)
  std::vector<const protocol::Status*> loading;
  for (const protocol::Status& s : statuses) {
    EXPECT_GE(s.progress, 0.0);
    EXPECT_LE(s.progress, 1.0);
    if (s.message.ends_with(" running")) continue;
    if (s.message.starts_with("stage 1/3 settle: ")) {
      EXPECT_LE(s.progress, 1.0 / 3.0) << s.message;
      EXPECT_NE(s.message.find("of at most 400000"), std::string::npos) << s.message;  // a kinetic energy: its cap
    }
    if (s.message.starts_with("stage 3/3 load: top stress ")) loading.push_back(&s);
  }
  ASSERT_FALSE(loading.empty()) << "the loading stage showed no status of its progress";
  for (const protocol::Status* s : loading) {
    // "stage 3/3 load: top stress 563.1 kPa of 900 kPa": two stages done and
    // the third as far as its stress (in Pa before the plate bears, "0 Pa",
    // or while a contact's dashpot pulls it, "-53.01 Pa").
    const std::string& text = s->message;
    std::size_t number_end = 0;
    const double value = std::stod(text.substr(text.find("stress ") + 7), &number_end);
    const std::string unit = text.substr(text.find("stress ") + 7 + number_end);
    ASSERT_TRUE(unit.starts_with(" kPa of 900 kPa") || unit.starts_with(" Pa of 900 kPa")) << text;
    const double stress_kpa = unit.starts_with(" kPa") ? value : value / 1e3;
    EXPECT_NEAR(s->progress, (2.0 + std::clamp(stress_kpa / 900.0, 0.0, 1.0)) / 3.0, 1e-3) << text;
  }
  const protocol::Status& last = *loading.back();
  std::printf("the last status of the loading stage: %.3f done, \"%s\"; cycle %llu of at most %llu (%.1f%%)\n",
              last.progress, last.message.c_str(), static_cast<unsigned long long>(last.command_cycles_done),
              static_cast<unsigned long long>(last.command_cycles_total),
              100.0 * static_cast<double>(last.command_cycles_done) / static_cast<double>(last.command_cycles_total));
}

}  // namespace
}  // namespace dem::test
