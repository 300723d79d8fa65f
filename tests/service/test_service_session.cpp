// The world session and the helpers beside it (no DDS): the case's
// programme stepped stage by stage as the runner steps it (CaseProgramme),
// where a checkpoint may be taken, and the session's snapshots and
// in-memory checkpoints (world_snapshots.h), in 2D and 3D.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <variant>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/service/case_programme.h"
#include "dem/service/world_session.h"
#include "dem/service/world_snapshots.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

io::CaseDefinition nine_discs() {
  io::CaseDefinition definition = io::convert_case(io::load_case_file(case_file("nine_disc_damped")).message);
  definition.world.threads = 1;
  return definition;
}

// Steps a stage to its end in uneven chunks (never past the next check),
// as the runner's chunks fall; returns what it ran.
StageResult step_through(service::StageStepper& stage, std::uint64_t chunk) {
  for (bool over = stage.cycles_to_next_stop() == 0; !over;) {
    stage.cycle(std::min(chunk, stage.cycles_to_next_stop()));
    over = stage.check();
  }
  return stage.result();
}

// `count` cycles as a cycle command runs them: a one-stage programme, stepped to its end.
void run_cycles(service::WorldSession& session, std::uint64_t count) {
  auto stage = service::CaseProgramme::one_stage(session.dimension(), count, {}).begin_stage(0, session);
  step_through(stage, count);
}

TEST(CaseProgramme, StagesSteppedInChunksEndAsTheEnginesRunStage) {
  const io::CaseDefinition definition = nine_discs();
  World engine(definition.world);
  for (const StageDef& stage : definition.stages) run_stage(engine, stage);

  const service::CaseProgramme programme(definition.stages);
  ASSERT_EQ(programme.stage_count(), 2u);
  EXPECT_EQ(programme.stage_name(0), "compress");
  EXPECT_EQ(programme.stage_cycles(0), 40u);
  EXPECT_EQ(programme.stage_cycles(1), 2960u);
  const auto session = std::make_unique<service::WorldSession>(World(definition.world));
  for (std::size_t i = 0; i < programme.stage_count(); ++i) {
    auto stage = programme.begin_stage(i, *session);
    EXPECT_EQ(step_through(stage, 7).cycles_run, programme.stage_cycles(i));
  }
  std::printf("engine %016llx, stepped in chunks of 7 cycles %016llx, at cycle %llu\n",
              static_cast<unsigned long long>(engine.state_hash()),
              static_cast<unsigned long long>(session->state_hash()),
              static_cast<unsigned long long>(session->cycle_count()));
  EXPECT_EQ(session->cycle_count(), 3000u);
  EXPECT_EQ(session->state_hash(), engine.state_hash());
}

// A checkpoint in a stage, put back and the stage resumed from it (its
// start actions not done again), ends where the stage run whole ends.
TEST(CaseProgramme, AStageResumedFromACheckpointEndsAsOneNeverInterrupted) {
  const io::CaseDefinition definition = nine_discs();
  const service::CaseProgramme programme(definition.stages);
  const auto session = std::make_unique<service::WorldSession>(World(definition.world));
  auto compress = programme.begin_stage(0, *session);
  step_through(compress, 40);
  auto hold = programme.begin_stage(1, *session);
  hold.cycle(1000);
  hold.check();
  const service::StateCheckpoint checkpoint(*session);
  EXPECT_EQ(checkpoint.cycle(), 1040u);
  step_through(hold, 100);
  const std::uint64_t whole = session->state_hash();

  checkpoint.restore(*session);
  EXPECT_EQ(session->cycle_count(), 1040u);
  auto rest = programme.begin_stage(1, *session, 1000);
  EXPECT_EQ(step_through(rest, 100).cycles_run, 1960u);
  EXPECT_EQ(session->cycle_count(), 3000u);
  EXPECT_EQ(session->state_hash(), whole);
}

// Where a checkpoint may be taken: on a condition check, before the end,
// and not where the conditions hold (the stage ends there).
TEST(CaseProgramme, ACheckpointIsResumableOnlyOnAChecksCycleWhereTheStageGoesOn) {
  const io::CaseDefinition definition = nine_discs();
  StageDef never = definition.stages.front();
  never.cycles = 100;
  never.until.kinetic_energy_below = 0.0;  // the energy is never negative
  never.until.check_interval = 10;
  StageDef at_once = never;
  at_once.until.kinetic_energy_below = 1e300;
  const service::CaseProgramme programme(std::vector<StageDef>{never, at_once});
  const auto session = std::make_unique<service::WorldSession>(World(definition.world));
  EXPECT_TRUE(programme.resumable_at(0, 10, *session));
  EXPECT_FALSE(programme.resumable_at(0, 15, *session));   // between two checks
  EXPECT_FALSE(programme.resumable_at(0, 100, *session));  // the stage's end
  EXPECT_FALSE(programme.resumable_at(1, 10, *session));   // its conditions hold: it ends there
  // A stage of the other dimension is not this session's.
  EXPECT_THROW(session->begin_stage(StageDef3{}), std::bad_variant_access);
}

// A session's snapshot read back into another session of the case goes on
// as the first does; an in-memory checkpoint's bytes are that snapshot.
TEST(WorldSnapshots, ASnapshotPutBackGoesOnAsTheWorldItWasTakenFrom) {
  const io::CaseDefinition definition = nine_discs();
  const service::CaseProgramme programme(definition.stages);
  const auto first = std::make_unique<service::WorldSession>(World(definition.world));
  auto compress = programme.begin_stage(0, *first);
  step_through(compress, 40);
  const io::SnapshotInfo info{"nine_disc_damped", ""};
  const std::string bytes = service::snapshot_bytes(*first, info);
  EXPECT_EQ(service::StateCheckpoint(*first).bytes(info), bytes);
  run_cycles(*first, 500);

  const auto second = std::make_unique<service::WorldSession>(World(definition.world));
  service::restore_bytes(*second, bytes, "<test>");
  EXPECT_EQ(second->cycle_count(), 40u);
  run_cycles(*second, 500);
  EXPECT_EQ(second->state_hash(), first->state_hash());
}

TEST(WorldSnapshots, ThreeDimensionalSessionsTooAndNotAcrossDimensions) {
  const auto box = std::filesystem::path(DEM_CASES_DIR) / "validation" / "box_settle.case.txtpb";
  const io::LoadedCase loaded = io::load_case_file(box);
  auto definition = std::get<io::CaseDefinition3>(io::convert_any_case(loaded.message, loaded.source));
  definition.world.threads = 1;
  const auto session = std::make_unique<service::WorldSession>(World3(definition.world));
  EXPECT_EQ(session->dimension(), 3);
  EXPECT_EQ(session->world<3>().particle_count(), session->particle_count());
  EXPECT_THROW(session->world<2>(), std::bad_variant_access);
  run_cycles(*session, 20);
  const service::StateCheckpoint checkpoint(*session);
  const std::string bytes = service::snapshot_bytes(*session, {});
  run_cycles(*session, 30);
  const std::uint64_t uninterrupted = session->state_hash();

  checkpoint.restore(*session);
  run_cycles(*session, 30);
  EXPECT_EQ(session->state_hash(), uninterrupted);
  service::restore_bytes(*session, bytes, "<test>");
  EXPECT_EQ(session->cycle_count(), 20u);
  run_cycles(*session, 30);
  EXPECT_EQ(session->state_hash(), uninterrupted);

  const auto flat = std::make_unique<service::WorldSession>(World(nine_discs().world));
  EXPECT_THROW(checkpoint.restore(*flat), std::bad_variant_access);
}

}  // namespace
}  // namespace dem::test
