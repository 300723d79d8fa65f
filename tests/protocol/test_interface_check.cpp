// What a peer's declared interface says (dem/protocol/interface_check.h),
// judged against the recorded history (idl/interface_history.json): the
// same form; the forms of dem_interfaces 0.1.0 - whose Command gained
// `force` and ContactQuery's `particle_set`/`particle` in the middle (no
// reading across), and whose ContactQuery alone gained fields at its end
// (an older reader still reads it); a 0.2.0 client of a 0.3.0 server;
// a hash no version had; no hash at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "dem/protocol/interface_check.h"
#include "dem/protocol/interface_version.h"

namespace dem::protocol {
namespace {

using Kind = PeerVerdict::Kind;

constexpr std::string_view kCommand = "dem_interfaces::msg::dds_::Command_";
constexpr std::string_view kContactQuery = "dem_interfaces::msg::dds_::ContactQuery_";
constexpr std::string_view kReply = "dem_interfaces::msg::dds_::Reply_";

dds::Endpoint endpoint(std::string_view type, std::string user_data, bool writer) {
  return {"rt/dem/press/command", std::string(type), {}, std::move(user_data), writer};
}

std::string_view older_hash(std::string_view type, std::string_view versions) {
  const auto found = std::find_if(kOlderForms.begin(), kOlderForms.end(),
                                  [&](const OlderForm& f) { return f.type_name == type && f.versions == versions; });
  EXPECT_NE(found, kOlderForms.end()) << type << " " << versions;
  return found == kOlderForms.end() ? std::string_view() : found->hash;
}

TEST(InterfaceCheck, EveryEndpointDeclaresItsRos2TypeHashAndTheVersion) {
  const std::string data = endpoint_user_data(kCommand);
  EXPECT_EQ(data, "typehash=" + std::string(type_hash_of(kCommand)) +
                      ";dem_interfaces=" + std::string(kInterfaceVersion) + ";");
  EXPECT_TRUE(type_hash_of(kCommand).starts_with("RIHS01_"));
  EXPECT_EQ(type_hash_of(kCommand).size(), 7u + 64u);
  EXPECT_EQ(peer_type_hash(data), type_hash_of(kCommand));
  EXPECT_EQ(peer_type_hash("a=b;typehash=RIHS01_x;"), "RIHS01_x");  // ROS 2's pairs, in any order
  EXPECT_EQ(peer_type_hash(""), "");
  EXPECT_TRUE(endpoint_user_data("geometry_msgs::msg::dds_::Vector3_").empty());  // not a topic of ours
  EXPECT_EQ(kInterfaceVersion, "0.3.0");
}

TEST(InterfaceCheck, TheSameFormMeets) {
  const PeerVerdict verdict = judge_peer(endpoint(kCommand, endpoint_user_data(kCommand), true), "this server");
  EXPECT_EQ(verdict.kind, Kind::kSame) << verdict.text;
}

TEST(InterfaceCheck, A010CommandWriterIsReportedWithWhatItLacks) {
  // The ROS 2 node of the issue: built from the package's first files.
  const std::string_view old = older_hash(kCommand, "0.1.0 as of 0308f76");
  const PeerVerdict verdict = judge_peer(endpoint(kCommand, "typehash=" + std::string(old) + ";", true), "this server");
  std::printf("%s\n", verdict.text.c_str());
  EXPECT_EQ(verdict.kind, Kind::kIncompatible);
  EXPECT_EQ(
      verdict.text,
      "rt/dem/press/command: a writer of Command built from dem_interfaces 0.1.0 as of 0308f76, whose Command "
      "lacks force, programme_steps, query.particle_set, query.particle: its samples cannot be read by this server "
      "(dem_interfaces 0.3.0) and are dropped; rebuild it from dem_interfaces 0.3.0");
}

TEST(InterfaceCheck, AnOlderReaderOfAMessageThatGainedFieldsAtItsEndStillReads) {
  // ContactQuery gained particle_set and particle at its end: a reader of
  // the older form reads the current one's samples, not the other way.
  const std::string_view old = older_hash(kContactQuery, "0.1.0 as of 0308f76 to ac60c8a");
  const std::string data = "typehash=" + std::string(old) + ";dem_interfaces=0.1.0;";
  const PeerVerdict reader = judge_peer(endpoint(kContactQuery, data, false), "this client");
  EXPECT_EQ(reader.kind, Kind::kOlderCompatible) << reader.text;
  EXPECT_NE(reader.text.find("whose ContactQuery lacks particle_set, particle"), std::string::npos) << reader.text;
  EXPECT_NE(reader.text.find("(it says dem_interfaces 0.1.0)"), std::string::npos) << reader.text;
  const PeerVerdict writer = judge_peer(endpoint(kContactQuery, data, true), "this client");
  EXPECT_EQ(writer.kind, Kind::kIncompatible) << writer.text;
}

TEST(InterfaceCheck, A020ClientIsToldItsCommandsLackTheProgrammeSteps) {
  // 0.3.0 appended programme_steps to Command and the stage fields to
  // Reply: a reader cannot read a writer of fewer fields, so a 0.2.0
  // client's commands are not read; it still reads the replies.
  const std::string_view command = older_hash(kCommand, "0.1.0 as of 0ff9d3e to 911c994, 0.2.0");
  const PeerVerdict writer = judge_peer(
      endpoint(kCommand, "typehash=" + std::string(command) + ";dem_interfaces=0.2.0;", true), "this server");
  EXPECT_EQ(writer.kind, Kind::kIncompatible) << writer.text;
  EXPECT_NE(writer.text.find("whose Command lacks programme_steps: its samples cannot be read"), std::string::npos)
      << writer.text;
  const std::string_view reply = older_hash(kReply, "0.2.0");
  const PeerVerdict reader =
      judge_peer(endpoint(kReply, "typehash=" + std::string(reply) + ";dem_interfaces=0.2.0;", false), "this server");
  EXPECT_EQ(reader.kind, Kind::kOlderCompatible) << reader.text;
  EXPECT_NE(reader.text.find("whose Reply lacks stage, stage_cycles, stage_ended"), std::string::npos) << reader.text;
}

TEST(InterfaceCheck, AnUnknownHashAndNoHashAreSaidSo) {
  const std::string unknown = "RIHS01_" + std::string(64, '0');
  const PeerVerdict other = judge_peer(endpoint(kCommand, "typehash=" + unknown + ";", true), "this server");
  EXPECT_EQ(other.kind, Kind::kUnknownForm);
  EXPECT_NE(other.text.find("built from other message files"), std::string::npos) << other.text;
  const PeerVerdict none = judge_peer(endpoint(kCommand, "", true), "this server");
  EXPECT_EQ(none.kind, Kind::kNoTypeHash);
  EXPECT_NE(none.text.find("declares no type hash"), std::string::npos) << none.text;
  EXPECT_EQ(judge_peer(endpoint("std_msgs::msg::dds_::String_", "", true), "this server").kind, Kind::kNotOurs);
}

}  // namespace
}  // namespace dem::protocol
