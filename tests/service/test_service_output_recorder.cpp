// The service's per-case files (OutputRecorder): the ParaView series of a
// programme - steps while a stage runs at the case's vtk_interval, or the
// server's when it was given one, and the final state at the end - and none
// for a world driven by commands alone; an earlier run's output is never
// cut unasked (claim). No DDS: the recorder by itself.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/service/output_recorder.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

// The cycles of the steps a .pvd lists, in order.
std::vector<std::uint64_t> steps(const std::filesystem::path& pvd) {
  std::ifstream in(pvd);
  std::stringstream text;
  text << in.rdbuf();
  std::vector<std::uint64_t> cycles;
  const std::string all = text.str();
  for (auto at = all.find("particles_"); at != std::string::npos; at = all.find("particles_", at + 1)) {
    cycles.push_back(std::stoull(all.substr(at + 10, 10)));
  }
  return cycles;
}

struct NineDisc {
  io::CaseDefinition definition = io::convert_case(io::load_case_file(case_file("nine_disc_damped")).message);
  World world{definition.world};
};

TEST(OutputRecorderVtk, AProgrammeWritesStepsAtTheCasesIntervalAndTheEnd) {
  const auto out = output_directory("output_recorder_vtk_case");
  NineDisc nine;
  service::OutputRecorder recorder(out, true);
  recorder.start("nine", nine.world, std::nullopt, 1000);
  for (int i = 0; i < 25; ++i) {
    nine.world.cycle(100);
    recorder.record(nine.world, std::size_t{0});  // a stage of a programme runs
  }
  recorder.finish(nine.world);
  EXPECT_EQ(steps(out / "nine" / "particles.pvd"), (std::vector<std::uint64_t>{100, 1100, 2100, 2500}));
  EXPECT_TRUE(std::filesystem::exists(out / "nine" / "vtk" / "contacts_0000002500.vtp"));
  EXPECT_TRUE(std::filesystem::exists(out / "nine" / "vtk" / "walls_0000001100.vtp"));
}

TEST(OutputRecorderVtk, TheServersIntervalReplacesTheCasesAndZeroTurnsItOff) {
  const auto out = output_directory("output_recorder_vtk_override");
  NineDisc nine;
  {
    service::OutputRecorder recorder(out / "every500", true, 500);
    recorder.start("nine", nine.world, std::nullopt, 1000);
    for (int i = 0; i < 10; ++i) {
      nine.world.cycle(100);
      recorder.record(nine.world, std::size_t{0});
    }
    recorder.finish(nine.world);
  }
  EXPECT_EQ(steps(out / "every500" / "nine" / "particles.pvd"), (std::vector<std::uint64_t>{100, 600, 1000}));
  {
    service::OutputRecorder recorder(out / "off", true, 0);
    recorder.start("nine", nine.world, std::nullopt, 1000);
    nine.world.cycle(100);
    recorder.record(nine.world, std::size_t{0});
    recorder.finish(nine.world);
  }
  EXPECT_FALSE(std::filesystem::exists(out / "off" / "nine" / "particles.pvd"));
  EXPECT_TRUE(std::filesystem::exists(out / "off" / "nine" / "walls.csv"));
}

TEST(OutputRecorderVtk, CommandsAloneWriteNoSeries) {
  const auto out = output_directory("output_recorder_vtk_commands");
  NineDisc nine;
  service::OutputRecorder recorder(out, true);
  recorder.start("nine", nine.world, std::nullopt, 100);
  nine.world.cycle(300);
  recorder.record(nine.world);  // a cycle command: no stage
  recorder.finish(nine.world);
  EXPECT_FALSE(std::filesystem::exists(out / "nine" / "particles.pvd"));
  EXPECT_TRUE(std::filesystem::exists(out / "nine" / "particles.csv"));
}

// A server restarted into an output directory without --resume cut its
// assembly.csv from 3,317 lines to 32 (issue 37): a new recorder refuses a
// case directory with files in it, naming --resume and --overwrite; with
// overwrite it empties it first, checkpoints and all.
TEST(OutputRecorderClaim, AnEarlierRunsOutputIsRefusedOrReplacedWhenAsked) {
  const auto out = output_directory("output_recorder_claim");
  NineDisc nine;
  {
    service::OutputRecorder earlier(out, true);
    earlier.claim("nine", false);  // nothing there yet
    earlier.start("nine", nine.world);
    nine.world.cycle(100);
    earlier.record(nine.world);
    earlier.claim("nine", false);  // its own: a load of the same case starts again
    earlier.finish(nine.world);
  }
  std::filesystem::create_directories(out / "nine" / "checkpoints");
  std::ofstream(out / "nine" / "checkpoints" / "checkpoint-0000000100.resume") << "a checkpoint";
  const std::string assembly = read_text(out / "nine" / "assembly.csv");

  service::OutputRecorder restarted(out, true);
  try {
    restarted.claim("nine", false);
    ADD_FAILURE() << "an earlier run's output was taken over";
  } catch (const service::OutputRecorder::OutputInUse& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("holds the output of an earlier run (assembly.csv"), std::string::npos) << message;
    EXPECT_NE(message.find("--resume"), std::string::npos) << message;
    EXPECT_NE(message.find("--overwrite"), std::string::npos) << message;
  }
  EXPECT_EQ(read_text(out / "nine" / "assembly.csv"), assembly);  // untouched
  restarted.claim("other", false);                                // another case's directory is free

  restarted.claim("nine", true);
  EXPECT_TRUE(std::filesystem::is_empty(out / "nine"));
}

}  // namespace
}  // namespace dem::test
