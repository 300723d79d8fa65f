// Particle ids over the wire stay with their particles: a programme's trim
// removes the top row of a stack of discs (ids 0 1 2, the first ones), and a
// client's id still names the same particle afterwards, while a query naming a removed id (or one never
// given) gets not_found with the engine's words, never another particle.
#include <gtest/gtest.h>

#include <cmath>

#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::ReplyStatus;

std::vector<protocol::ContactEntry> contacts_of(client::Client& client, std::int32_t particle) {
  protocol::ContactQueryArgs query;
  query.particle = particle;
  return client.query_contacts(query).contacts;
}

const protocol::ContactEntry* between(const std::vector<protocol::ContactEntry>& contacts, std::int32_t a,
                                      std::int32_t b) {
  for (const protocol::ContactEntry& c : contacts) {
    if ((c.first == a && c.second_particle == b) || (c.first == b && c.second_particle == a)) return &c;
  }
  return nullptr;
}

protocol::Reply error_reply(client::Client& client, std::int32_t particle) {
  try {
    contacts_of(client, particle);
  } catch (const client::ServerError& error) {
    return error.reply();
  }
  ADD_FAILURE() << "the query naming particle " << particle << " succeeded";
  return {};
}

TEST(StableIds, AClientsIdNamesTheSameParticleAfterATrim) {
  const auto lattice = std::filesystem::path(DEM_SERVICE_TEST_DATA) / "trimmed_lattice.case.txtpb";
  InProcessServer server(server_options("ids", kProgrammeStableIds));
  client::Client client(connect_options("ids", kProgrammeStableIds));
  client.load_case_file(lattice);
  client.cycle(50);

  // Disc 4 (middle of the second row from the top) presses on 7 below and
  // carries 1 above.
  const std::vector<protocol::ContactEntry> before = contacts_of(client, 4);
  const protocol::ContactEntry* below = between(before, 4, 7);
  ASSERT_NE(below, nullptr);
  ASSERT_NE(between(before, 1, 4), nullptr);
  const protocol::Vector3 below_point = below->point;

  const protocol::Reply trimmed = client.run_programme();
  ASSERT_TRUE(trimmed.ok()) << trimmed.message;
  EXPECT_EQ(trimmed.state.particles, 9);

  // The same id, the same particle: its contact with 4 is where it was (a
  // neighbour is a diameter, 100 m, away; one cycle moves it far less).
  const std::vector<protocol::ContactEntry> after = contacts_of(client, 4);
  const protocol::ContactEntry* still = between(after, 4, 7);
  ASSERT_NE(still, nullptr);
  std::printf("contact 4-7 at (%.6f, %.6f) before the trim, (%.6f, %.6f) after\n", below_point.x, below_point.y,
              still->point.x, still->point.y);
  EXPECT_NEAR(still->point.x, below_point.x, 1.0);
  EXPECT_NEAR(still->point.y, below_point.y, 1.0);
  for (const protocol::ContactEntry& c : after) EXPECT_TRUE(c.first != 1 && c.second_particle != 1);

  // A removed id and one never given are errors that name them.
  const protocol::Reply removed = error_reply(client, 1);
  EXPECT_EQ(removed.status, ReplyStatus::kNotFound);
  EXPECT_EQ(removed.message, "particle 1 was removed");
  const protocol::Reply unknown = error_reply(client, 12);
  EXPECT_EQ(unknown.status, ReplyStatus::kNotFound);
  EXPECT_EQ(unknown.message, "no particle 12");
}

}  // namespace
}  // namespace dem::test
