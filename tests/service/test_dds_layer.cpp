// dem::dds and dem::protocol: the project's layer over Cyclone DDS's C API
// and the service's messages on the wire.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <thread>

#include "dem/dds/discovery.h"
#include "dem/dds/error.h"
#include "dem/dds/instance_filter.h"
#include "dem/dds/keyless_descriptor.h"
#include "dem/dds/topic.h"
#include "dem/dds/waitset.h"
#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"
#include "dem/protocol/type_support.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::TopicKind;

// Every field set to something other than its default, so a field the
// conversion forgets shows up as a difference.
protocol::Status full_status() {
  protocol::Status s;
  s.server = "a";
  s.state = protocol::ServerState::kRunning;
  s.case_name = "nine";
  s.dimension = 2;
  s.particles = 9;
  s.walls = 4;
  s.cycle = 123456789012ULL;
  s.time = 1.25;
  s.time_step = 1e-3;
  s.command = "cycle";
  s.command_client = "client-1";
  s.command_request_id = 77;
  s.command_cycles_done = 5;
  s.command_cycles_total = 10;
  s.progress = 0.5;
  s.message = "running";
  s.commands_served = 3;
  s.telemetry_dropped = 2;
  s.stamp = {1700000000, 123};
  return s;
}

protocol::WallForce full_wall(int id) {
  protocol::WallForce w;
  w.name = "wall" + std::to_string(id);
  w.id = id;
  w.force = {1.0 + id, 2.0, 3.0};
  w.moment = {0.0, 0.0, -4.0};
  w.normal_force = 5.0;
  w.area = 6.0;
  w.normal_stress = 5.0 / 6.0;
  w.position = {7.0, 8.0, 9.0};
  w.displacement = {-1.0, -2.0, 0.5};
  w.settlement = 0.25;
  w.contacts = 11;
  return w;
}

protocol::ContactStats full_stats() {
  protocol::ContactStats s;
  s.server = "a";
  s.cycle = 10;
  s.time = 0.1;
  s.stamp = {1, 2};
  s.particles = 9;
  s.contacts = 13;
  s.wall_contacts = 4;
  s.sliding_contacts = 1;
  s.sliding_fraction = 1.0 / 13.0;
  s.coordination_number = 2.11;
  s.mean_normal_force = 3e9;
  s.max_normal_force = 4e9;
  s.histogram_bin_width = 0.25;
  s.histogram = {1, 2, 3, 0, 7};
  s.kinetic_energy = 1e3;
  s.out_of_balance = 0.01;
  return s;
}

protocol::Command full_command() {
  protocol::Command c;
  c.server = "a";
  c.client_id = "client-1";
  c.request_id = 42;
  c.kind = static_cast<std::uint8_t>(protocol::CommandKind::kRunUntil);
  c.load_case = {"p.case", "name: \"x\"", std::string("\0\1\2bin", 6), "file.txtpb"};
  c.wall_velocity = {"top", 3, {{1.0, -2.0, 0.0}, {0.0, 0.0, 0.5}}};
  c.wall_servo = {"top", -1, 1e6, 1e-9, 0.1};
  c.cycle.cycles = -5;
  c.run_until = {"top", -1, 2e6, std::nullopt, 0.5, 1000, 10};
  c.query = {true, "left", 2, true, {0.0, 1.0, 0.0}, {2.0, 3.0, 0.0}, 1e3, 17};
  c.snapshot = {"s.snap", true, std::string(1000, 'x')};
  c.parameter = {"friction", "disc", 0.3, {0.0, -9.81, 0.0}};
  c.stamp = {5, 6};
  return c;
}

protocol::Reply full_reply() {
  protocol::Reply r;
  r.server = "a";
  r.client_id = "client-1";
  r.request_id = 42;
  r.kind = static_cast<std::uint8_t>(protocol::CommandKind::kGetState);
  r.status = protocol::ReplyStatus::kNotFound;
  r.message = "no wall \"x\"";
  r.duration = 0.002;
  r.chunk = 3;
  r.last = false;
  r.state = full_status();
  r.cycles_run = 8;
  r.condition_met = true;
  r.plates = {"a", 10, 0.1, {3, 4}, {full_wall(0), full_wall(1)}};
  r.stats = full_stats();
  r.state_hash = 0xfeedface12345678ULL;
  r.total_contacts = 2;
  protocol::ContactEntry e{1,   2,    -1, {0.5, 0.6, 0.0},  {1.0, 0.0, 0.0}, 1e-3, 5.0, -1.0, {0.0, 1.0, 0.0}, 0.1,
                           0.2, true, 17, {-5.1, -0.9, 0.0}};
  r.contacts = {e, e};
  r.contacts[1].second_particle = -1;
  r.contacts[1].second_wall = 3;
  r.total_bytes = 4;
  r.data = std::string("\0\xff\x01z", 4);
  r.path = "/tmp/x";
  r.stamp = {7, 8};
  return r;
}

template <typename T>
T round_trip(dds::Participant& participant, const std::string& topic_name, const T& value) {
  dds::Topic<T> topic(participant, topic_name);
  dds::Reader<T> reader(participant, topic, dds::Qos().reliable(1s).keep_all());
  dds::Writer<T> writer(participant, topic, dds::Qos().reliable(1s).keep_all());
  EXPECT_TRUE(eventually([&] { return writer.matched_readers() > 0; }, 10s));
  EXPECT_TRUE(writer.write(value));
  std::vector<T> received;
  EXPECT_TRUE(eventually(
      [&] {
        for (T& sample : reader.take()) received.push_back(std::move(sample));
        return !received.empty();
      },
      10s));
  return received.empty() ? T{} : received.front();
}

TEST(DdsLayer, QosSetsThePoliciesAsked) {
  const dds::Qos qos = dds::Qos().reliable(250ms).keep_last(7).transient_local();
  dds_reliability_kind_t reliability;
  dds_duration_t blocking = 0;
  ASSERT_TRUE(dds_qget_reliability(qos.get(), &reliability, &blocking));
  EXPECT_EQ(reliability, DDS_RELIABILITY_RELIABLE);
  EXPECT_EQ(blocking, DDS_MSECS(250));
  dds_history_kind_t history;
  int32_t depth = 0;
  ASSERT_TRUE(dds_qget_history(qos.get(), &history, &depth));
  EXPECT_EQ(history, DDS_HISTORY_KEEP_LAST);
  EXPECT_EQ(depth, 7);
  dds_durability_kind_t durability;
  ASSERT_TRUE(dds_qget_durability(qos.get(), &durability));
  EXPECT_EQ(durability, DDS_DURABILITY_TRANSIENT_LOCAL);
  // A copy owns its own policies.
  dds::Qos copy = qos;
  copy.keep_all();
  ASSERT_TRUE(dds_qget_history(qos.get(), &history, &depth));
  EXPECT_EQ(history, DDS_HISTORY_KEEP_LAST);
  EXPECT_EQ(dds::to_duration(std::chrono::nanoseconds::max()), DDS_INFINITY);
}

TEST(DdsLayer, TelemetryWritersNeverWaitAndStatusIsDurable) {
  dds_reliability_kind_t reliability;
  dds_duration_t blocking = -1;
  ASSERT_TRUE(dds_qget_reliability(protocol::telemetry_writer_qos().get(), &reliability, &blocking));
  EXPECT_EQ(reliability, DDS_RELIABILITY_RELIABLE);
  EXPECT_EQ(blocking, 0);
  dds_history_kind_t history;
  int32_t depth = 0;
  ASSERT_TRUE(dds_qget_history(protocol::telemetry_writer_qos().get(), &history, &depth));
  EXPECT_EQ(history, DDS_HISTORY_KEEP_LAST);  // KEEP_ALL would hold the engine behind a stalled reader
  EXPECT_EQ(depth, 256);                      // the history a late joiner is given
  dds_durability_kind_t durability;
  ASSERT_TRUE(dds_qget_durability(protocol::telemetry_writer_qos().get(), &durability));
  EXPECT_EQ(durability, DDS_DURABILITY_TRANSIENT_LOCAL);
  ASSERT_TRUE(dds_qget_durability(protocol::telemetry_reader_qos().get(), &durability));
  EXPECT_EQ(durability, DDS_DURABILITY_TRANSIENT_LOCAL);
  ASSERT_TRUE(dds_qget_durability(protocol::status_qos().get(), &durability));
  EXPECT_EQ(durability, DDS_DURABILITY_TRANSIENT_LOCAL);
  ASSERT_TRUE(dds_qget_history(protocol::command_qos().get(), &history, &depth));
  EXPECT_EQ(history, DDS_HISTORY_KEEP_ALL);
}

TEST(DdsLayer, ConfigurationFallsBackToTheLoopbackFile) {
  EXPECT_EQ(dds::resolve_config("<CycloneDDS/>"), "<CycloneDDS/>");
  EXPECT_EQ(dds::resolve_config("file:///etc/x.xml"), "file:///etc/x.xml");
  EXPECT_EQ(dds::resolve_config("/etc/x.xml"), "file:///etc/x.xml");
  EXPECT_EQ(dds::default_config().rfind("file://", 0), 0u);
  EXPECT_NE(dds::default_config().find("config/cyclonedds-loopback.xml"), std::string::npos);
  const char* saved = std::getenv("CYCLONEDDS_URI");
  const std::string previous = saved ? saved : "";
  setenv("CYCLONEDDS_URI", "file:///from/environment.xml", 1);
  EXPECT_EQ(dds::resolve_config(""), "file:///from/environment.xml");
  unsetenv("CYCLONEDDS_URI");
  EXPECT_EQ(dds::resolve_config(""), dds::default_config());
  if (saved) setenv("CYCLONEDDS_URI", previous.c_str(), 1);
}

TEST(DdsLayer, ReturnCodesBecomeExceptionsNamingTheAction) {
  EXPECT_EQ(dds::check(5, "anything"), 5);
  try {
    dds::check(DDS_RETCODE_BAD_PARAMETER, "creating a widget");
    FAIL();
  } catch (const dds::DdsError& error) {
    EXPECT_EQ(error.code(), DDS_RETCODE_BAD_PARAMETER);
    EXPECT_EQ(std::string(error.what()),
              std::string("creating a widget: ") + dds_strretcode(DDS_RETCODE_BAD_PARAMETER));
  }
}

TEST(DdsLayer, EveryMessageTypeCrossesTheWireUnchanged) {
  dds::Participant participant(kDdsTypedRoundTrip);
  EXPECT_EQ(round_trip(participant, "rt/test/status", full_status()), full_status());
  EXPECT_EQ(round_trip(participant, "rt/test/stats", full_stats()), full_stats());
  const protocol::PlateForces plates{"a", 10, 0.1, {3, 4}, {full_wall(0), full_wall(1), full_wall(2)}};
  EXPECT_EQ(round_trip(participant, "rt/test/plates", plates), plates);
  EXPECT_EQ(round_trip(participant, "rt/test/command", full_command()), full_command());
  EXPECT_EQ(round_trip(participant, "rt/test/reply", full_reply()), full_reply());
}

TEST(DdsLayer, LargeSamplesCrossTheWire) {
  dds::Participant participant(kDdsLargeSamples);
  protocol::Reply big = full_reply();
  big.data = std::string(8u << 20, 'q');  // 8 MiB
  big.contacts.assign(50'000, big.contacts.front());
  const protocol::Reply received = round_trip(participant, "rt/test/big", big);
  EXPECT_EQ(received.data.size(), big.data.size());
  EXPECT_EQ(received, big);
}

// Replies are keyed by client (idl/dem/command.idl). Once a reader learnt
// its own instance from a writer, that writer's replies to others are
// turned away; a writer it learnt nothing from yet (a restarted server)
// gets through, so the reader can learn again.
TEST(DdsLayer, AnInstanceFilterKeepsTheReadersOwnReplies) {
  dds::Participant participant(kDdsInstanceFilter);
  dds::Topic<protocol::Reply> writer_topic(participant, "rt/test/replies");
  dds::Topic<protocol::Reply> reader_topic(participant, "rt/test/replies");
  dds::OwnInstanceFilter filter(reader_topic.handle());
  dds::Reader<protocol::Reply> reader(participant, reader_topic, protocol::reply_reader_qos());
  const auto reply_to = [](const std::string& client, std::uint64_t request) {
    protocol::Reply reply;
    reply.client_id = client;
    reply.request_id = request;
    reply.last = true;
    return reply;
  };
  // What the reader has after the writes (and 200 ms for any stragglers).
  const auto received = [&](std::size_t expected) {
    std::vector<std::string> got;
    const auto take = [&] {
      for (const auto& [reply, writer, instance] : reader.take_with_writers()) {
        got.push_back(reply.client_id + "/" + std::to_string(reply.request_id));
        if (reply.client_id == "me") filter.learn(writer, instance);
      }
      return got.size() >= expected;
    };
    eventually(take, 10s);
    std::this_thread::sleep_for(200ms);
    take();
    return got;
  };
  dds::Writer<protocol::Reply> server(participant, writer_topic, protocol::reply_qos());
  ASSERT_TRUE(eventually([&] { return server.matched_readers() > 0; }, 10s));
  server.write(reply_to("other", 1));
  server.write(reply_to("me", 1));
  EXPECT_EQ(received(2), (std::vector<std::string>{"other/1", "me/1"}));  // nothing learnt yet
  server.write(reply_to("other", 2));
  server.write(reply_to("me", 2));
  server.write(reply_to("other", 3));
  EXPECT_EQ(received(1), std::vector<std::string>{"me/2"});
  dds::Writer<protocol::Reply> restarted(participant, writer_topic, protocol::reply_qos());
  ASSERT_TRUE(eventually([&] { return restarted.matched_readers() > 0; }, 10s));
  restarted.write(reply_to("other", 4));
  restarted.write(reply_to("me", 3));
  EXPECT_EQ(received(2), (std::vector<std::string>{"other/4", "me/3"}));
  restarted.write(reply_to("other", 5));
  restarted.write(reply_to("me", 4));
  server.write(reply_to("other", 6));
  EXPECT_EQ(received(1), std::vector<std::string>{"me/4"});
}

// The reply without its key is what idlc makes of the IDL without @key:
// the same program but for the key member's flags, and no key list.
TEST(DdsLayer, AKeylessDescriptorIsTheTypeWithoutItsKey) {
  const dds_topic_descriptor_t& keyed = *dds::TypeSupport<protocol::Reply>::descriptor();
  ASSERT_EQ(keyed.m_nkeys, 1u);
  const dds::KeylessDescriptor keyless(keyed);
  const dds_topic_descriptor_t& plain = keyless.get();
  EXPECT_EQ(plain.m_nkeys, 0u);
  EXPECT_EQ(plain.m_keys, nullptr);
  EXPECT_STREQ(plain.m_typename, keyed.m_typename);
  EXPECT_EQ(plain.m_size, keyed.m_size);
  // The program before the key list (where the key descriptor points);
  // word 2 is client_id's op (words 0 and 1: server's op and offset).
  std::size_t differing = 0;
  for (std::size_t word = 0; word < keyed.m_keys[0].m_offset; ++word) {
    if (plain.m_ops[word] == keyed.m_ops[word]) continue;
    ++differing;
    EXPECT_EQ(word, 2u);
    EXPECT_EQ(plain.m_ops[word], keyed.m_ops[word] & ~(DDS_OP_FLAG_KEY | DDS_OP_FLAG_MU));
  }
  EXPECT_EQ(differing, 1u);
}

// Cyclone keeps keyed and keyless endpoints of one topic and type name
// apart: the server's keyless reply writer reaches keyless readers (a ROS 2
// node's) and no keyed one, and its samples arrive whole.
TEST(DdsLayer, AKeylessTopicOfAKeyedTypeMatchesKeylessEndpointsAlone) {
  dds::Participant participant(kDdsKeylessReplies);
  dds::Topic<protocol::Reply> keyed_topic(participant, "rt/test/keyless");
  dds::Topic<protocol::Reply> keyless_topic(participant, "rt/test/keyless", dds::Keys::kNone);
  dds::Writer<protocol::Reply> keyed_writer(participant, keyed_topic, protocol::reply_qos());
  dds::Writer<protocol::Reply> keyless_writer(participant, keyless_topic, protocol::reply_qos());
  dds::Reader<protocol::Reply> keyed_reader(participant, keyed_topic, protocol::reply_reader_qos());
  dds::Reader<protocol::Reply> keyless_reader(participant, keyless_topic, protocol::reply_reader_qos());
  ASSERT_TRUE(
      eventually([&] { return keyed_writer.matched_readers() > 0 && keyless_writer.matched_readers() > 0; }, 10s));
  std::this_thread::sleep_for(200ms);  // any other match would be made by now
  EXPECT_EQ(keyed_writer.matched_readers(), 1u);
  EXPECT_EQ(keyless_writer.matched_readers(), 1u);
  EXPECT_EQ(dds::matched_writers(keyless_reader.handle()), 1u);

  protocol::Reply keyless_reply = full_reply();
  keyless_reply.request_id = 2;
  ASSERT_TRUE(keyed_writer.write(full_reply()));
  ASSERT_TRUE(keyless_writer.write(keyless_reply));
  std::vector<protocol::Reply> keyed_got;
  std::vector<protocol::Reply> keyless_got;
  EXPECT_TRUE(eventually(
      [&] {
        for (protocol::Reply& reply : keyed_reader.take()) keyed_got.push_back(std::move(reply));
        for (protocol::Reply& reply : keyless_reader.take()) keyless_got.push_back(std::move(reply));
        return !keyed_got.empty() && !keyless_got.empty();
      },
      10s));
  std::this_thread::sleep_for(200ms);
  for (protocol::Reply& reply : keyed_reader.take()) keyed_got.push_back(std::move(reply));
  for (protocol::Reply& reply : keyless_reader.take()) keyless_got.push_back(std::move(reply));
  EXPECT_EQ(keyed_got, std::vector<protocol::Reply>{full_reply()});
  EXPECT_EQ(keyless_got, std::vector<protocol::Reply>{keyless_reply});
}

TEST(DdsLayer, WaitSetWakesForDataAndGuardConditions) {
  dds::Participant participant(kDdsWaitSet);
  dds::Topic<protocol::Status> topic(participant, "rt/test/waitset");
  dds::Reader<protocol::Status> reader(participant, topic, protocol::status_qos());
  dds::Writer<protocol::Status> writer(participant, topic, protocol::status_qos());
  dds::ReadCondition data(reader.handle());
  dds::GuardCondition guard(participant);
  dds::WaitSet waitset(participant);
  waitset.attach(data, 1);
  waitset.attach(guard, 2);
  EXPECT_TRUE(waitset.wait(50ms).empty());  // nothing happened: a timeout
  guard.trigger();
  EXPECT_TRUE(guard.triggered());
  EXPECT_EQ(waitset.wait(1s), std::vector<std::intptr_t>{2});
  guard.reset();
  EXPECT_FALSE(guard.triggered());
  ASSERT_TRUE(eventually([&] { return writer.matched_readers() > 0; }, 10s));
  std::thread later([&] {
    std::this_thread::sleep_for(50ms);
    writer.write(full_status());
  });
  EXPECT_EQ(waitset.wait(10s), std::vector<std::intptr_t>{1});
  later.join();
  EXPECT_EQ(reader.take().size(), 1u);
}

TEST(DdsLayer, ParticipantsOfADomainShareItsConfiguration) {
  dds::Participant first(kDdsDomainConfiguration);
  dds::Participant second(kDdsDomainConfiguration);  // the same configuration: shared
  EXPECT_EQ(first.config(), second.config());
  try {
    dds::Participant other(kDdsDomainConfiguration,
                           "<CycloneDDS><Domain><General><AllowMulticast>true"
                           "</AllowMulticast></General></Domain></CycloneDDS>");
    FAIL() << "a second configuration for a running domain was accepted";
  } catch (const dds::DdsError& error) {
    EXPECT_NE(std::string(error.what()).find("already runs with"), std::string::npos) << error.what();
  }
}

TEST(DdsLayer, DiscoveryListsTheWritersOfTheDomainWithTheirParticipants) {
  dds::Participant participant(kDdsDiscovery);
  dds::Topic<protocol::Status> topic(participant, protocol::topic_name("someone", TopicKind::kStatus));
  dds::Writer<protocol::Status> writer(participant, topic, protocol::status_qos());
  dds::PublicationMonitor monitor(participant);
  EXPECT_TRUE(eventually(
      [&] {
        for (const auto& p : monitor.alive()) {
          if (p.topic_name == "rt/dem/someone/status" && p.type_name == protocol::kStatusTypeName &&
              p.participant == dds::guid_of(participant)) {
            return true;
          }
        }
        return false;
      },
      10s));
}

TEST(DdsLayer, EntitiesAreDeletedWithTheirOwner) {
  dds::Participant participant(kDdsEntityLifetime);
  dds::Topic<protocol::Status> topic(participant, "rt/test/lifetime");
  dds_entity_t handle = 0;
  {
    dds::Writer<protocol::Status> writer(participant, topic, protocol::status_qos());
    handle = writer.handle();
    EXPECT_EQ(dds_get_parent(handle) > 0, true);
  }
  EXPECT_LT(dds_get_parent(handle), 0);  // gone with its owner
  dds::Entity moved_from(dds_create_guardcondition(participant.handle()));
  const dds_entity_t guard = moved_from.handle();
  dds::Entity moved_to = std::move(moved_from);
  EXPECT_EQ(moved_to.handle(), guard);
  EXPECT_FALSE(moved_from);
  moved_to.reset();
  EXPECT_LT(dds_get_parent(guard), 0);
}

TEST(Protocol, TopicNamesFollowRos2Conventions) {
  EXPECT_EQ(protocol::topic_name("a", TopicKind::kPlateForces), "rt/dem/a/plate_forces");
  EXPECT_EQ(protocol::topic_name("press_2", TopicKind::kContactStats), "rt/dem/press_2/contact_stats");
  EXPECT_EQ(protocol::topic_name("a", TopicKind::kStatus), "rt/dem/a/status");
  EXPECT_EQ(protocol::topic_name("a", TopicKind::kCommand), "rt/dem/a/command");
  EXPECT_EQ(protocol::topic_name("a", TopicKind::kReply), "rt/dem/a/reply");
  EXPECT_EQ(protocol::topic_name("a", TopicKind::kRegionMeasures), "rt/dem/a/region_measures");
  EXPECT_EQ(protocol::topic_name("a", TopicKind::kNameClaim), "rt/dem/a/_name_claim");  // hidden in ROS 2
  EXPECT_EQ(protocol::server_of_status_topic("rt/dem/press_2/status"), "press_2");
  EXPECT_EQ(protocol::server_of_status_topic("rt/dem/press_2/reply"), std::nullopt);
  EXPECT_EQ(protocol::server_of_status_topic("rt/other/x/status"), std::nullopt);
  EXPECT_EQ(protocol::server_of_status_topic("rt/dem/a/b/status"), std::nullopt);
  for (const char* good : {"a", "dem", "Press_2", "x1"}) EXPECT_TRUE(protocol::valid_server_name(good)) << good;
  for (const char* bad : {"", "2a", "_a", "a-b", "a/b", "a b", "ä"})
    EXPECT_FALSE(protocol::valid_server_name(bad)) << bad;
  EXPECT_FALSE(protocol::valid_server_name(std::string(65, 'a')));
}

TEST(Protocol, KindsAndStatusesHaveNames) {
  EXPECT_EQ(protocol::command_kind(4), protocol::CommandKind::kCycle);
  EXPECT_EQ(protocol::command_kind(0), std::nullopt);
  EXPECT_EQ(protocol::command_kind(13), protocol::CommandKind::kRunProgramme);
  EXPECT_EQ(protocol::command_kind(14), std::nullopt);
  EXPECT_EQ(protocol::to_string(protocol::CommandKind::kQueryContacts), "query_contacts");
  EXPECT_EQ(protocol::to_string(protocol::CommandKind::kRunProgramme), "run_programme");
  EXPECT_EQ(protocol::to_string(protocol::ReplyStatus::kInvalidSnapshot), "invalid_snapshot");
  EXPECT_EQ(protocol::to_string(protocol::ServerState::kLoaded), "loaded");
}

}  // namespace
}  // namespace dem::test
