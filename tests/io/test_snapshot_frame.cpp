// The snapshot frame's checksum: every corruption of a snapshot's bytes -
// any byte changed anywhere, header or payload, a truncation, bytes
// appended - is refused with a message naming the source, never loaded.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "dem/io/snapshot_file.h"
#include "dem/io/snapshot_frame.h"
#include "snapshot_worlds.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string small_snapshot() {
  World world(testing::settling_box());
  world.cycle(20);
  return serialize_snapshot(world.snapshot(), SnapshotInfo{"box", ""});
}

std::string error_of(std::string_view bytes) {
  try {
    parse_snapshot(bytes, "s");
  } catch (const SnapshotError& error) {
    return error.what();
  }
  return "";
}

TEST(SnapshotFrame, TheHeaderCarriesTheLengthAndChecksum) {
  const std::string framed = frame_snapshot("payload");
  ASSERT_EQ(framed.size(), kSnapshotHeaderSize + 7);
  EXPECT_EQ(framed.substr(0, 8), "DEMSNAP1");
  EXPECT_EQ(static_cast<unsigned char>(framed[8]), 7);
  EXPECT_EQ(framed.substr(16, 32), sha256("payload"));
  EXPECT_EQ(unframe_snapshot(framed, "x"), "payload");
  // The SHA-256 of "abc" (FIPS 180-2, appendix B.1).
  const std::string abc = sha256("abc");
  EXPECT_EQ(static_cast<unsigned char>(abc[0]), 0xba);
  EXPECT_EQ(static_cast<unsigned char>(abc[31]), 0xad);
}

TEST(SnapshotFrame, EveryChangedByteIsRefused) {
  const std::string good = small_snapshot();
  ASSERT_EQ(error_of(good), "");
  std::mt19937 random(12);
  for (std::size_t at = 0; at < good.size(); ++at) {
    std::string bad = good;
    // Any other value: flip a random non-empty set of its bits.
    bad[at] = static_cast<char>(bad[at] ^ static_cast<char>(1 + random() % 255));
    const std::string error = error_of(bad);
    ASSERT_THAT(error, StartsWith("s: ")) << "byte " << at << " of " << good.size() << " changed and loaded";
  }
}

TEST(SnapshotFrame, TruncatedOrExtendedBytesAreRefused) {
  const std::string good = small_snapshot();
  EXPECT_THAT(error_of(good.substr(0, good.size() - 1)), HasSubstr("s: truncated: its header promises"));
  EXPECT_THAT(error_of(good.substr(0, 30)), HasSubstr("s: not a dem snapshot (it does not start with"));
  EXPECT_THAT(error_of(good + "x"), HasSubstr("s: 1 bytes follow the snapshot its header describes"));
}

TEST(SnapshotFrame, AChangedPayloadWithItsLengthKeptFailsTheChecksum) {
  std::string bad = small_snapshot();
  bad[kSnapshotHeaderSize + 10] = static_cast<char>(bad[kSnapshotHeaderSize + 10] ^ 1);
  EXPECT_EQ(error_of(bad), "s: corrupt: its SHA-256 checksum does not match its contents");
}

}  // namespace
}  // namespace dem::io
