// Continuing from a snapshot gives bit-identical results to a run that
// never stopped: saved by path or transferred, restored into the same
// server or another one.
#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include "dem/io/snapshot_file.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

// The photoelastic verification assembly (197 discs) under four servo walls
// (Cundall & Strack 1979, Table 1): contact history, sliding and servos in
// the state.
void start_compression(client::Client& client) {
  client.load_case_file(case_file("verification_assembly"));
  // The case's stage 1, as stresses on walls 1200 long: F_V = 6e8, F_H = 0.4 F_V;
  // gain 5e-9 m/(N s) on force is 6e-6 m/(Pa s) on stress.
  client.set_wall_servo("wall1_bottom", 6e8 / 1200, 5e-9 * 1200, 50);
  client.set_wall_servo("wall3_top", 6e8 / 1200, 5e-9 * 1200, 50);
  client.set_wall_servo("wall2_right", 2.4e8 / 1200, 5e-9 * 1200, 50);
  client.set_wall_servo("wall4_left", 2.4e8 / 1200, 5e-9 * 1200, 50);
}

// The fields in which two snapshots differ ("" when they are the same):
// the dynamics, the contact table and the energy budget all continue bit
// for bit.
std::string differences(const std::string& a, const std::string& b) {
  const proto::Snapshot first = io::parse_snapshot_message(a);
  const proto::Snapshot second = io::parse_snapshot_message(b);
  google::protobuf::util::MessageDifferencer differencer;
  std::string report;
  differencer.ReportDifferencesToString(&report);
  return differencer.Compare(first, second) ? std::string() : report.substr(0, 2000);
}

TEST(Snapshots, ContinuationIsBitIdenticalInTheSameOrAnotherServer) {
  InProcessServer origin(server_options("origin", kSnapshotContinuation));
  InProcessServer copy(server_options("copy", kSnapshotContinuation));
  client::Client a(connect_options("origin", kSnapshotContinuation));
  client::Client b(connect_options("copy", kSnapshotContinuation));
  start_compression(a);
  a.cycle(4000);
  a.save_snapshot("at4000.snapshot");
  const std::string saved = a.save_snapshot({}, true).data;
  a.cycle(3000);
  const protocol::Reply uninterrupted = a.get_state();
  const std::string end = a.save_snapshot({}, true).data;
  ASSERT_GT(uninterrupted.stats.contacts, 50);
  ASSERT_GT(uninterrupted.stats.sliding_contacts, 0);

  // Another server, from the transferred bytes.
  EXPECT_EQ(b.load_snapshot_bytes(saved).state.cycle, 4000u);
  b.cycle(3000);
  const protocol::Reply continued = b.get_state();
  EXPECT_EQ(continued.state_hash, uninterrupted.state_hash);
  EXPECT_EQ(continued.state.cycle, 7000u);
  EXPECT_EQ(differences(b.save_snapshot({}, true).data, end), "");  // the whole state, value for value
  for (std::size_t i = 0; i < continued.plates.walls.size(); ++i) {
    EXPECT_EQ(continued.plates.walls[i].normal_stress, uninterrupted.plates.walls[i].normal_stress);
    EXPECT_EQ(continued.plates.walls[i].settlement, uninterrupted.plates.walls[i].settlement);
  }

  // The same server, from its file.
  EXPECT_EQ(a.load_snapshot_on_server("at4000.snapshot").state.cycle, 4000u);
  a.cycle(3000);
  EXPECT_EQ(a.get_state().state_hash, uninterrupted.state_hash);
}

TEST(Snapshots, LargeSnapshotsTravelInChunks) {
  service::ServerOptions options = server_options("chunky", kSnapshotTransfer);
  options.snapshot_chunk = 1024;
  InProcessServer server(options);
  client::Client client(connect_options("chunky", kSnapshotTransfer));
  start_compression(client);
  client.cycle(500);
  const protocol::Reply sent = client.save_snapshot({}, true);
  EXPECT_GT(sent.total_bytes, 10u * 1024u);
  EXPECT_EQ(sent.data.size(), sent.total_bytes);
  EXPECT_EQ(sent.chunk + 1, (sent.total_bytes + 1023) / 1024);
  const std::uint64_t hash = client.get_state().state_hash;
  client.cycle(100);
  client.load_snapshot_bytes(sent.data);
  EXPECT_EQ(client.get_state().state_hash, hash);
}

}  // namespace
}  // namespace dem::test
