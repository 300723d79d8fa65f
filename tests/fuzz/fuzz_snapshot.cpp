// libFuzzer target: any bytes as a snapshot (a file or a transfer) - the
// frame and its checksum, parsing, the value checks, conversion, the world
// restored from it, a few cycles. The checksum would stop almost every
// mutation at the frame, so the first byte chooses: 0, the bytes as they
// come (the frame tested); otherwise the rest framed here, so the fuzzer
// reaches the message behind it.
#include <string>
#include <string_view>

#include "dem/error.h"
#include "dem/health.h"
#include "dem/io/snapshot_file.h"
#include "dem/io/snapshot_frame.h"
#include "fuzz_support.h"

namespace {

template <int Dim>
void restore_and_step(const dem::proto::Snapshot& message) {
  const dem::WorldSnapshotT<Dim> snapshot = dem::io::snapshot_from_proto<Dim>(message, nullptr, dem::fuzz::limits());
  dem::BasicWorld<Dim> world(snapshot);
  dem::HealthMonitorT<Dim> health(world);
  world.cycle(3);
  (void)health.assess(world);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view rest(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::string bytes = data[0] == 0 ? std::string(rest) : dem::io::frame_snapshot(rest);
  try {
    const dem::proto::Snapshot message = dem::io::parse_snapshot_message(bytes, "fuzz.snapshot");
    if (message.dimension() == 3) {
      restore_and_step<3>(message);
    } else {
      restore_and_step<2>(message);
    }
  } catch (const dem::io::SnapshotError& error) {
    dem::fuzz::refused(error);
  } catch (const dem::DefinitionError& error) {
    dem::fuzz::refused(error);
  } catch (const std::exception& error) {
    dem::fuzz::unexpected("snapshot", error);
  }
  return 0;
}
