// Checkpoints on disk: the newest whole one is found, a damaged one is
// passed over for the one before, only the newest few are kept, where
// the run stood reads back exactly, and a run's next one is due after its
// interval in cycles.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "dem/io/checkpoint_store.h"
#include "dem/io/snapshot_file.h"
#include "io_test_support.h"
#include "snapshot_worlds.h"

namespace dem::io {
namespace {

ResumePoint point_at(std::uint64_t cycle) {
  ResumePoint point;
  point.cycle = cycle;
  point.stage = 2;
  point.stage_cycles = cycle - 100;
  point.case_digest = "abc123";
  point.tables = {{"walls.csv", 1234}, {"assembly.csv", 99}};
  point.analysis = "samples 1\n0 5 0.5 1e-3 2 3 4 5\nsnapshots 0\n";
  point.vtk_steps = {{0, 0.0}, {250, 0.1 / 3.0}, {500, 1.0e-7 * 500}};
  return point;
}

TEST(CheckpointStore, ResumeTextReadsBackExactly) {
  const ResumePoint point = point_at(700);
  const ResumePoint read = parse_resume(resume_text(point));
  EXPECT_EQ(read.cycle, 700u);
  EXPECT_EQ(read.stage, 2u);
  EXPECT_EQ(read.stage_cycles, 600u);
  EXPECT_EQ(read.case_digest, "abc123");
  EXPECT_EQ(read.tables, point.tables);
  EXPECT_EQ(read.analysis, point.analysis);
  EXPECT_EQ(read.vtk_steps, point.vtk_steps);                                 // times to the bit
  EXPECT_THROW(parse_resume("dem.resume 1\ncycle 7\n"), std::runtime_error);  // cut short
}

TEST(CheckpointStore, KeepsTheNewestAndSkipsADamagedOne) {
  const auto directory = test::fresh_directory("checkpoints");
  CheckpointStore store(directory, 2);
  EXPECT_FALSE(store.latest());
  World world(testing::settling_box());
  for (const std::uint64_t cycle : {100, 200, 300}) {
    world.cycle(100);
    store.write(serialize_snapshot(world.snapshot(), SnapshotInfo{}), point_at(cycle));
  }
  int resumes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    resumes += entry.path().extension() == ".resume";
  EXPECT_EQ(resumes, 2);
  ASSERT_TRUE(store.latest());
  EXPECT_EQ(store.latest()->point.cycle, 300u);
  EXPECT_EQ(parse_snapshot(store.latest()->snapshot_bytes).snapshot.cycle, 300u);
  // A torn newest snapshot (a crash of the disk, not of the run): the one before.
  std::ofstream(store.latest()->path, std::ios::binary | std::ios::trunc) << "DEMSNAP1 torn";
  ASSERT_TRUE(store.latest());
  EXPECT_EQ(store.latest()->point.cycle, 200u);
  std::filesystem::remove_all(directory);
}

// dem_run's and dem_server's schedule (PeriodicCheckpoints): none without a
// directory or an interval; due `cycles` after the run began, then after
// the last checkpoint; each stamped with the run's case.
TEST(CheckpointStore, PeriodicCheckpointsAreDueAfterTheirInterval) {
  const auto directory = test::fresh_directory("periodic_checkpoints");
  PeriodicCheckpoints off(CheckpointSettings{});
  off.begin(directory, "abc123", 0);
  EXPECT_FALSE(off.store());
  EXPECT_FALSE(off.due(1'000'000));
  PeriodicCheckpoints elsewhere(CheckpointSettings{.cycles = 100});
  elsewhere.begin({}, "abc123", 0);  // a server whose output directory is not its own
  EXPECT_FALSE(elsewhere.due(1'000'000));

  PeriodicCheckpoints periodic(CheckpointSettings{.cycles = 100, .keep = 2});
  periodic.begin(directory, "def456", 50);
  ASSERT_TRUE(periodic.store());
  EXPECT_FALSE(periodic.due(149));
  EXPECT_TRUE(periodic.due(150));
  World world(testing::settling_box());
  world.cycle(170);
  periodic.write(serialize_snapshot(world.snapshot(), SnapshotInfo{}), ResumePoint{.cycle = 170});
  EXPECT_FALSE(periodic.due(269));
  EXPECT_TRUE(periodic.due(270));
  ASSERT_TRUE(periodic.store()->latest());
  EXPECT_EQ(periodic.store()->latest()->point.cycle, 170u);
  EXPECT_EQ(periodic.store()->latest()->point.case_digest, "def456");
  periodic.begin(directory, "def456", 1000);  // a new world loaded: its interval from its own cycle
  EXPECT_FALSE(periodic.due(1099));
  EXPECT_TRUE(periodic.due(1100));
  std::filesystem::remove_all(directory);
}

// A programme run killed 6 s in had nothing to resume from (issue 37): by
// default the first checkpoint is due 5 s of wall time into a run, the
// next ones every 300 s after the last.
TEST(CheckpointStore, TheFirstCheckpointComesSoonAfterTheStart) {
  const CheckpointSettings defaults = default_programme_checkpoints();
  EXPECT_TRUE(defaults.enabled());
  EXPECT_EQ(defaults.first_seconds, 5.0);
  EXPECT_EQ(defaults.seconds, 300.0);
  EXPECT_EQ(defaults.cycles, 0u);

  const auto directory = test::fresh_directory("first_checkpoint");
  PeriodicCheckpoints periodic(CheckpointSettings{.seconds = 300.0, .first_seconds = 0.05});
  periodic.begin(directory, "abc123", 0);
  EXPECT_FALSE(periodic.due(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  EXPECT_TRUE(periodic.due(20));
  World world(testing::settling_box());
  world.cycle(20);
  periodic.write(serialize_snapshot(world.snapshot(), SnapshotInfo{}), ResumePoint{.cycle = 20});
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  EXPECT_FALSE(periodic.due(30));           // from now on, the interval
  periodic.begin(directory, "abc123", 30);  // a new run begins: its first one soon again
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  EXPECT_TRUE(periodic.due(40));
  std::filesystem::remove_all(directory);
}

// A resumed run's ParaView series keeps the steps of its checkpoint and
// drops the ones the crashed run wrote after it.
TEST(CheckpointStore, AResumedParaViewSeriesKeepsTheCheckpointsSteps) {
  const auto directory = test::fresh_directory("vtk_resume");
  World world(testing::settling_box());
  std::vector<VtkSeries::Step> at_checkpoint;
  {
    VtkSeries series(directory, 10);
    for (int i = 0; i < 5; ++i) {
      series.record(world);
      if (i == 2) at_checkpoint = series.step_list();
      world.cycle(10);
    }
  }
  ASSERT_EQ(at_checkpoint.size(), 3u);
  const VtkSeries resumed(directory, 10, at_checkpoint);
  EXPECT_EQ(resumed.step_list(), at_checkpoint);
  EXPECT_FALSE(resumed.due(at_checkpoint.back().cycle + 9));
  EXPECT_TRUE(resumed.due(at_checkpoint.back().cycle + 10));
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory / "vtk")) {
    files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files.size(), 9u);  // three kinds, three steps
  EXPECT_EQ(files.back(), "walls_0000000020.vtp");
  std::ifstream pvd(directory / "particles.pvd");
  const std::string text((std::istreambuf_iterator<char>(pvd)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("vtk/particles_0000000020.vtp"), std::string::npos);
  EXPECT_EQ(text.find("vtk/particles_0000000030.vtp"), std::string::npos);
  std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace dem::io
