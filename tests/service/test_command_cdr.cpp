// The command decoder (dem/protocol/command_cdr.h): what a client encodes
// decodes to the same command, and bytes that are not one are dropped.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "dem/protocol/command_cdr.h"

namespace dem::protocol {
namespace {

Command sample() {
  Command c;
  c.server = "press";
  c.client_id = "host-1-1";
  c.request_id = 42;
  c.kind = static_cast<std::uint8_t>(CommandKind::kRunUntil);
  c.run_until.wall = "top";
  c.run_until.stress = 1e6;
  c.run_until.max_cycles = 5000;
  c.load_case.binary = std::string("\0\1\2", 3);
  c.query.box_set = true;
  c.query.box_max = {1, 2, 3};
  c.snapshot.data = "bytes";
  c.stamp = {12, 34};
  return c;
}

TEST(CommandCdr, WhatIsEncodedDecodesToTheSameCommand) {
  const std::string bytes = encode_command(sample());
  EXPECT_EQ(bytes.substr(0, 4), std::string("\0\1\0\0", 4));  // CDR_LE
  const std::optional<Command> decoded = decode_command(bytes);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(*decoded, sample());
}

TEST(CommandCdr, BytesThatAreNoCommandAreDropped) {
  const std::string bytes = encode_command(sample());
  EXPECT_FALSE(decode_command(""));
  EXPECT_FALSE(decode_command(bytes.substr(0, bytes.size() / 2)));  // truncated
  std::string unknown = bytes;
  unknown[1] = 0x42;  // no such encoding
  EXPECT_FALSE(decode_command(unknown));
  std::string long_string = bytes;
  long_string[4] = '\x7f';  // the first string's length, far beyond the bytes
  EXPECT_FALSE(decode_command(long_string));
}

// The command fuzz target's seeds must be commands of today's IDL: stale
// ones (a field added since) would all be dropped undecoded, and the
// fuzzer would start from nothing (tests/fuzz/make_fuzz_seeds.cpp rewrites them).
TEST(CommandCdr, TheFuzzSeedsAreCommands) {
  int seeds = 0;
  for (const auto& entry : std::filesystem::directory_iterator(DEM_FUZZ_COMMAND_SEEDS)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(decode_command(bytes)) << entry.path() << ": run build/tests/fuzz/make_fuzz_seeds";
    ++seeds;
  }
  EXPECT_GE(seeds, 13);
}

}  // namespace
}  // namespace dem::protocol
