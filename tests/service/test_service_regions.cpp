// The measures of a case's regions through the service (issue 13): a case
// with measurement regions and a box control, loaded into a server in this
// process; its region telemetry reaches a C++ subscriber and its tables
// (regions.csv, box.csv) are written beside walls.csv; a server killed in
// the shear stage of an element test and resumed ends with the same tables
// and state as one never interrupted. DDS domains 220 and 222 (issue 13's
// tests use 220-239).
#include <gtest/gtest.h>
#include <signal.h>

#include <fstream>
#include <mutex>

#include "dem/client/telemetry.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

constexpr std::uint32_t kRegionTelemetry = 220;
constexpr std::uint32_t kRegionCheckpoints = 222;

namespace fs = std::filesystem;

TEST(Regions, TheirMeasuresArePublishedAndWritten) {
  const service::ServerOptions options = server_options("biaxial", kRegionTelemetry);
  InProcessServer server(options);
  client::Client client(connect_options("biaxial", kRegionTelemetry));
  const auto biaxial = std::filesystem::path(DEM_CASES_DIR) / ".." / "tests" / "io" / "data" / "biaxial.case.txtpb";
  client.load_case_file(biaxial);

  std::mutex mutex;
  std::vector<protocol::RegionTelemetry> samples;
  client::TelemetrySubscription telemetry(client, {.plate_forces = {},
                                                   .contact_stats = {},
                                                   .status = {},
                                                   .region_measures = [&](const protocol::RegionTelemetry& t) {
                                                     std::lock_guard lock(mutex);
                                                     samples.push_back(t);
                                                   }});
  ASSERT_TRUE(eventually([&] { return telemetry.matched_publishers() > 0; }, 10s));
  client.cycle(3000);
  ASSERT_TRUE(eventually(
      [&] {
        std::lock_guard lock(mutex);
        return !samples.empty() && samples.back().cycle == 3000;
      },
      10s));
  std::lock_guard lock(mutex);
  const protocol::RegionTelemetry& last = samples.back();
  EXPECT_EQ(last.server, "biaxial");
  EXPECT_EQ(last.dimension, 2);
  ASSERT_EQ(last.regions.size(), 3u);
  EXPECT_EQ(last.regions[0].name, "all");
  EXPECT_EQ(last.regions[2].name, "circle");
  const protocol::RegionMeasures& all = last.regions[0];
  std::printf("region \"all\" at cycle 3000: %d particles, porosity %.4f, mean stress %.1f Pa, coordination %.3f\n",
              all.particles, all.porosity, all.mean_stress, all.coordination);
  EXPECT_EQ(all.particles, 120);
  ASSERT_EQ(all.stress.size(), 4u);  // 2 x 2, row by row
  EXPECT_EQ(all.principal_stress.size(), 2u);
  EXPECT_EQ(all.fabric.size(), 4u);
  EXPECT_GT(all.porosity, 0.0);
  EXPECT_LT(all.porosity, 1.0);
  EXPECT_NEAR(all.mean_stress, 0.5 * (all.stress[0] + all.stress[3]), 1e-9 * std::abs(all.mean_stress) + 1e-12);

  // Beside walls.csv: regions.csv and, the case having a box control, box.csv.
  const auto directory = options.output_directory / "biaxial";
  for (const char* file : {"regions.csv", "box.csv"}) {
    std::ifstream in(directory / file);
    std::string header;
    ASSERT_TRUE(std::getline(in, header)) << file;
    EXPECT_EQ(header.substr(0, 11), "cycle,time,") << file;
  }
}

// Randall's reduced graded assembly (cases/randall): compression to 256,000
// cycles, then constant-volume shear under the box control to 297,000.
// Killed after a checkpoint in the shear stage, the resumed server neither
// sets the stage's box control again (its strain reference stays) nor
// starts regions.csv and box.csv afresh.
TEST(Regions, AnElementTestKilledInItsShearAndResumedEndsAsOneNeverInterrupted) {
  const fs::path case_path = fs::path(DEM_CASES_DIR) / "randall" / "graded_reduced.case.txtpb";
  const auto arguments = [&](const std::string& name, const fs::path& out, std::vector<std::string> more) {
    std::vector<std::string> all = {"--name",        name,
                                    "--domain",      std::to_string(kRegionCheckpoints),
                                    "--case",        case_path.string(),
                                    "--out",         out.string(),
                                    "--threads",     "1",
                                    "--log-level",   "warn",
                                    "--run-and-exit"};
    all.insert(all.end(), more.begin(), more.end());
    return all;
  };
  const fs::path whole = output_directory("regions_checkpoints_whole");
  const fs::path killed = output_directory("regions_checkpoints_killed");
  // The uninterrupted run and the one to be killed side by side (a run
  // takes some 4 s in Release, over a minute under ThreadSanitizer on a
  // loaded machine: hence the generous bounds).
  ServerProcess first(arguments("whole", whole, {}));
  ServerProcess second(arguments("killed", killed, {"--checkpoint-cycles", "5000"}));
  const fs::path directory = killed / "randall_graded_reduced";
  ASSERT_TRUE(eventually([&] { return newest_checkpoint(directory) >= 270000; }, 600s));
  second.signal(SIGKILL);
  second.wait(10s);
  ASSERT_FALSE(fs::exists(directory / "final.snapshot")) << "the run ended before it was killed";

  ServerProcess third(arguments("resumed", killed, {"--resume", "--checkpoint-cycles", "5000"}));
  ASSERT_EQ(first.wait(600s), 0);
  ASSERT_EQ(third.wait(600s), 0);
  std::printf("killed after the checkpoint at cycle %llu (shear from 256,000)\n",
              static_cast<unsigned long long>(newest_checkpoint(directory)));
  for (const char* name : {"regions.csv", "box.csv", "walls.csv", "assembly.csv", "stages.csv", "final.snapshot"}) {
    EXPECT_EQ(read_text(whole / "randall_graded_reduced" / name), read_text(directory / name)) << name << " differs";
  }
}

}  // namespace
}  // namespace dem::test
