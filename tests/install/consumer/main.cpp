// Runs a case with the installed libraries and compares the state reached
// with a snapshot the installed dem_run wrote of the same case: the same
// engine gives the same state, bit for bit.
//   dem_consumer CASE SNAPSHOT
#include <cstdio>

#include "dem/client/mcap_writer.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/snapshot_file.h"
#include "dem/programme.h"
#include "dem/protocol/messages.h"
#include "dem/version.h"
#include "dem/world.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: dem_consumer CASE SNAPSHOT\n");
    return 2;
  }
  dem::io::CaseDefinition definition = dem::io::convert_case(dem::io::load_case_file(argv[1]).message);
  definition.world.threads = 1;
  dem::World world(definition.world);
  for (const dem::StageDef& stage : definition.stages) dem::run_stage(world, stage);
  const dem::World reference(dem::io::read_snapshot_file<2>(argv[2]).snapshot);
  std::printf("dem %s: cycle %llu, state hash %016llx; dem_run's snapshot: cycle %llu, %016llx\n", DEM_VERSION,
              static_cast<unsigned long long>(world.cycle_count()), static_cast<unsigned long long>(world.state_hash()),
              static_cast<unsigned long long>(reference.cycle_count()),
              static_cast<unsigned long long>(reference.state_hash()));
  // dem::client links too: its CRC-32 of "123456789" is the standard check value.
  if (dem::client::crc32("123456789") != 0xCBF43926u) return 1;
  // The messages' header generated from the IDL is installed with the rest.
  if (dem::protocol::to_string(dem::protocol::ServerState::kRunning) != "running") return 1;
  return world.state_hash() == reference.state_hash() ? 0 : 1;
}
