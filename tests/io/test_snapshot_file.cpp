// Snapshots as bytes and files: what parses is a snapshot, what does not
// is refused with a message naming the source.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "dem/case.pb.h"
#include "dem/io/snapshot_file.h"
#include "dem/io/snapshot_frame.h"
#include "io_test_support.h"
#include "snapshot_worlds.h"

namespace dem::io {
namespace {

std::string error_of(std::string_view bytes, std::string_view source) {
  try {
    parse_snapshot(bytes, source);
  } catch (const SnapshotError& error) {
    return error.what();
  }
  return "";
}

TEST(SnapshotFile, BytesRoundTripExactly) {
  World world(testing::settling_box());
  world.cycle(800);
  const std::string bytes = serialize_snapshot(world.snapshot(), SnapshotInfo{"box", "d"});
  const LoadedSnapshot loaded = parse_snapshot(bytes, "mem");
  EXPECT_EQ(loaded.info.case_name, "box");
  World restored(loaded.snapshot);
  EXPECT_EQ(restored.state_hash(), world.state_hash());
}

TEST(SnapshotFile, GarbageIsRefusedNamingTheSource) {
  EXPECT_EQ(error_of("definitely not a snapshot", "upload"),
            "upload: not a dem snapshot (it does not start with the \"DEMSNAP1\" header; snapshots written before "
            "the header was added must be saved again)");
  // A sound frame around bytes that are no message.
  EXPECT_EQ(error_of(frame_snapshot("definitely not a snapshot"), "upload"),
            "upload: not a dem snapshot (the bytes are not a serialized dem.proto.Snapshot)");
  // Random bytes: whether or not protobuf can parse them, they are no snapshot.
  std::mt19937 random(2024);
  for (int trial = 0; trial < 200; ++trial) {
    std::string bytes(static_cast<std::size_t>(random() % 300), '\0');
    for (char& c : bytes) c = static_cast<char>(random());
    const std::string error = error_of(bytes, "random");
    EXPECT_EQ(error.rfind("random: not a dem snapshot", 0), 0u) << error;
  }
  // Another message that parses as protobuf: a case.
  proto::Case a_case;
  a_case.set_name("not a snapshot");
  EXPECT_EQ(error_of(frame_snapshot(a_case.SerializeAsString()), "case.bin"),
            "case.bin: not a dem snapshot (no \"dem.snapshot\" format tag)");
  EXPECT_EQ(error_of(frame_snapshot(""), "empty"), "empty: not a dem snapshot (no \"dem.snapshot\" format tag)");
  EXPECT_EQ(error_of("", "empty").rfind("empty: not a dem snapshot (it does not start with", 0), 0u);
}

TEST(SnapshotFile, TruncatedBytesAreRefused) {
  World world(testing::settling_box());
  world.cycle(100);
  const std::string bytes = serialize_snapshot(world.snapshot(), SnapshotInfo{});
  for (const std::size_t keep : {bytes.size() / 3, bytes.size() / 2, bytes.size() - 1}) {
    EXPECT_THROW(parse_snapshot(std::string_view(bytes).substr(0, keep), "cut"), SnapshotError) << keep;
  }
}

TEST(SnapshotFile, FilesRoundTripAndLeaveNoPartialFile) {
  const auto directory = test::fresh_directory("snapshot_file");
  World world(testing::settling_box());
  world.cycle(300);
  const auto path = directory / "nested" / "box.snapshot";
  write_snapshot_file(path, world.snapshot(), SnapshotInfo{"box", ""});
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
  World restored(read_snapshot_file(path).snapshot);
  EXPECT_EQ(restored.state_hash(), world.state_hash());
  std::filesystem::remove_all(directory);
}

TEST(SnapshotFile, MissingOrUnwritableFilesNameThePath) {
  try {
    read_snapshot_file("/nonexistent/dir/x.snapshot");
    FAIL();
  } catch (const SnapshotError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("/nonexistent/dir/x.snapshot: cannot read the snapshot", 0), 0u)
        << error.what();
  }
  World world(testing::settling_box());
  EXPECT_THROW(write_snapshot_file("/proc/x.snapshot", world.snapshot(), SnapshotInfo{}), SnapshotError);
}

TEST(SnapshotFile, ThreeDimensionalSnapshotsKeepTheirDimension) {
  World3 world(testing::sphere_stack(ContactLaw::kLinear));
  world.cycle(200);
  const std::string bytes = serialize_snapshot(world.snapshot(), SnapshotInfo{});
  EXPECT_EQ(parse_snapshot_message(bytes).dimension(), 3u);
  EXPECT_NE(error_of(bytes, "s3").find("s3: dimension: the snapshot is 3D, expected 2D"), std::string::npos)
      << error_of(bytes, "s3");
  World3 restored(parse_snapshot<3>(bytes).snapshot);
  EXPECT_EQ(restored.state_hash(), world.state_hash());
}

}  // namespace
}  // namespace dem::io
