// Bad input never crashes the server and never changes its state: each is
// answered by an error reply naming what is wrong, and the server goes on
// serving with the simulation as it was.
#include <gtest/gtest.h>

#include "dem/case.pb.h"
#include "dem/dds/topic.h"
#include "dem/io/case_loader.h"
#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::CommandKind;
using protocol::ReplyStatus;

// A loaded nine-disc server, 40 cycles into its compression.
struct Fixture {
  Fixture(const std::string& name, std::uint32_t domain)
      : server(server_options(name, domain)), client(connect_options(name, domain)) {
    client.load_case_file(case_file("nine_disc_damped"));
    client.set_wall_velocity("top", {0.0, -12.0, 0.0});
    client.cycle(40);
    hash = client.get_state().state_hash;
  }
  // The error reply to a command that must fail.
  protocol::Reply refused(protocol::Command command) {
    try {
      client.call(std::move(command));
    } catch (const client::ServerError& error) {
      return error.reply();
    }
    ADD_FAILURE() << "the command succeeded";
    return {};
  }
  // Still serving, and nothing changed.
  void expect_untouched() {
    const protocol::Reply state = client.get_state();
    EXPECT_EQ(state.state.case_name, "nine_disc_damped");
    EXPECT_EQ(state.state.cycle, 40u);
    EXPECT_EQ(state.state_hash, hash);
  }
  InProcessServer server;
  client::Client client;
  std::uint64_t hash = 0;
};

protocol::Command command(CommandKind kind) {
  protocol::Command c;
  c.kind = static_cast<std::uint8_t>(kind);
  return c;
}

TEST(Errors, UnknownWallIsNotFound) {
  Fixture f("bad_wall", kErrorsUnknownWall);
  protocol::Command velocity = command(CommandKind::kSetWallVelocity);
  velocity.wall_velocity.wall = "roof";
  const protocol::Reply reply = f.refused(velocity);
  EXPECT_EQ(reply.status, ReplyStatus::kNotFound);
  EXPECT_EQ(reply.message, "no wall \"roof\" (walls: bottom, right, top, left)");
  velocity.wall_velocity.wall.clear();
  velocity.wall_velocity.wall_id = 4;
  EXPECT_EQ(f.refused(velocity).message, "no wall with id 4 (there are 4 walls: bottom, right, top, left)");
  protocol::Command servo = command(CommandKind::kSetWallServo);
  servo.wall_servo.wall = "roof";
  servo.wall_servo.target_stress = 1e6;
  EXPECT_EQ(f.refused(servo).status, ReplyStatus::kNotFound);
  protocol::Command query = command(CommandKind::kQueryContacts);
  query.query.wall_set = true;
  query.query.wall = "roof";
  EXPECT_EQ(f.refused(query).status, ReplyStatus::kNotFound);
  protocol::Command until = command(CommandKind::kRunUntil);
  until.run_until = {"roof", -1, 1e6, std::nullopt, std::nullopt, 100, 0};
  EXPECT_EQ(f.refused(until).status, ReplyStatus::kNotFound);
  f.expect_untouched();
}

TEST(Errors, NegativeOrZeroCycleCountsAreBadRequests) {
  Fixture f("bad_cycles", kErrorsNegativeCycles);
  protocol::Command cycle = command(CommandKind::kCycle);
  cycle.cycle.cycles = -5;
  const protocol::Reply reply = f.refused(cycle);
  EXPECT_EQ(reply.status, ReplyStatus::kBadRequest);
  EXPECT_EQ(reply.message, "cycle.cycles: must be > 0, got -5");
  cycle.cycle.cycles = 0;
  EXPECT_EQ(f.refused(cycle).status, ReplyStatus::kBadRequest);
  protocol::Command until = command(CommandKind::kRunUntil);
  until.run_until.kinetic_energy = 1.0;
  until.run_until.max_cycles = -1;
  EXPECT_EQ(f.refused(until).status, ReplyStatus::kBadRequest);
  until.run_until.max_cycles = 10;
  until.run_until.kinetic_energy.reset();
  EXPECT_EQ(f.refused(until).message,
            "run_until needs a condition: a plate's stress or settlement, or the kinetic energy");
  f.expect_untouched();
}

TEST(Errors, MalformedCaseBytesAreAnInvalidCase) {
  Fixture f("bad_bytes", kErrorsMalformedCase);
  protocol::Command load = command(CommandKind::kLoadCase);
  load.load_case.binary = std::string("\xff\xff\xff\xff not a case", 15);
  load.load_case.source_name = "upload.bin";
  const protocol::Reply reply = f.refused(load);
  EXPECT_EQ(reply.status, ReplyStatus::kInvalidCase);
  EXPECT_NE(reply.message.find("upload.bin"), std::string::npos) << reply.message;
  load.load_case.binary.clear();
  load.load_case.text = "material { name: \"x\" density: }";
  load.load_case.source_name = "typo.case.txtpb";
  const protocol::Reply syntax = f.refused(load);
  EXPECT_EQ(syntax.status, ReplyStatus::kInvalidCase);
  EXPECT_EQ(syntax.message.rfind("typo.case.txtpb:1:", 0), 0u) << syntax.message;
  // Two sources at once, or none.
  load.load_case.path = "x";
  EXPECT_EQ(f.refused(load).status, ReplyStatus::kBadRequest);
  EXPECT_EQ(f.refused(command(CommandKind::kLoadCase)).status, ReplyStatus::kBadRequest);
  protocol::Command missing = command(CommandKind::kLoadCase);
  missing.load_case.path = "/no/such/case.txtpb";
  EXPECT_EQ(f.refused(missing).message.rfind("no case file on the server: /no/such/case.txtpb: not a file in the "
                                             "directories this server reads (",
                                             0),
            0u);
  f.expect_untouched();
}

TEST(Errors, ACaseThatFailsValidationNamesItsFields) {
  Fixture f("bad_case", kErrorsInvalidCase);
  std::string text = read_text(case_file("nine_disc_damped"));
  // The bottom wall ends where it starts, and a lattice uses an unknown material.
  text.replace(text.find("h1: -200 h2: 200"), 16, "h1: 200 h2: 200");
  text.replace(text.find("lattice { material: \"disc\""), 26, "lattice { material: \"sand\"");
  protocol::Command load = command(CommandKind::kLoadCase);
  load.load_case.text = text;
  load.load_case.source_name = "broken.case.txtpb";
  const protocol::Reply reply = f.refused(load);
  EXPECT_EQ(reply.status, ReplyStatus::kInvalidCase);
  EXPECT_NE(reply.message.find("broken.case.txtpb:"), std::string::npos) << reply.message;
  EXPECT_NE(reply.message.find("wall[0].h2: must be greater than h1"), std::string::npos) << reply.message;
  EXPECT_NE(reply.message.find("unknown material \"sand\""), std::string::npos) << reply.message;
  f.expect_untouched();
}

TEST(Errors, AGarbageSnapshotIsAnInvalidSnapshot) {
  Fixture f("bad_snapshot", kErrorsGarbageSnapshot);
  protocol::Command load = command(CommandKind::kLoadSnapshot);
  load.snapshot.transfer = true;
  load.snapshot.data = "this is not a snapshot at all";
  const protocol::Reply reply = f.refused(load);
  EXPECT_EQ(reply.status, ReplyStatus::kInvalidSnapshot);
  EXPECT_EQ(reply.message,
            "<transferred snapshot>: not a dem snapshot (it does not start with the \"DEMSNAP1\" "
            "header; snapshots written before the header was added must be saved again)");
  // A real snapshot cut short, or with one byte changed: its frame says so.
  const std::string good = f.client.save_snapshot({}, true).data;
  std::string cut = good.substr(0, good.size() / 2);
  load.snapshot.data = cut;
  EXPECT_EQ(f.refused(load).status, ReplyStatus::kInvalidSnapshot);
  std::string changed = good;
  changed[changed.size() / 2] = static_cast<char>(changed[changed.size() / 2] ^ 4);
  load.snapshot.data = changed;
  EXPECT_EQ(f.refused(load).message,
            "<transferred snapshot>: corrupt: its SHA-256 checksum does not match its contents");
  // A case's bytes are no snapshot either.
  load.snapshot.data = io::load_case_file(case_file("nine_disc_damped")).message.SerializeAsString();
  EXPECT_NE(f.refused(load).message.find("not a dem snapshot"), std::string::npos);
  std::ofstream(f.server.server().options().output_directory / "junk.snapshot") << "junk";
  protocol::Command from_file = command(CommandKind::kLoadSnapshot);
  from_file.snapshot.path = "junk.snapshot";
  EXPECT_EQ(f.refused(from_file).status, ReplyStatus::kInvalidSnapshot);
  from_file.snapshot.path = "absent.snapshot";
  EXPECT_EQ(f.refused(from_file).status, ReplyStatus::kNotFound);
  f.expect_untouched();
}

TEST(Errors, ACommandForAnotherServerIsIgnored) {
  Fixture f("mine", kErrorsOtherServer);
  // Published on this server's command topic but addressed to another name.
  dds::Topic<protocol::Command> topic(f.client.participant(),
                                      protocol::topic_name("mine", protocol::TopicKind::kCommand));
  dds::Writer<protocol::Command> writer(f.client.participant(), topic, protocol::command_qos());
  ASSERT_TRUE(eventually([&] { return writer.matched_readers() > 0; }, 10s));
  protocol::Command shutdown = command(CommandKind::kShutdown);
  shutdown.server = "theirs";
  shutdown.client_id = f.client.client_id();
  shutdown.request_id = 1'000'000;
  writer.write(shutdown);
  EXPECT_FALSE(f.client.await(1'000'000, 1500ms));  // no reply ...
  f.expect_untouched();                             // ... and still serving
  EXPECT_NE(f.client.status().state, protocol::ServerState::kShutdown);
}

TEST(Errors, CommandsOutsideTheirStatesAreRefused) {
  InProcessServer server(server_options("fresh", kErrorsLifecycle));
  client::Client client(connect_options("fresh", kErrorsLifecycle));
  const auto refused = [&](protocol::Command c) {
    try {
      client.call(std::move(c));
    } catch (const client::ServerError& error) {
      return error.reply();
    }
    return protocol::Reply{};
  };
  protocol::Command cycle = command(CommandKind::kCycle);
  cycle.cycle.cycles = 10;
  const protocol::Reply idle = refused(cycle);
  EXPECT_EQ(idle.status, ReplyStatus::kRefused);
  EXPECT_EQ(idle.message, "cycle refused: no case is loaded: load a case or a snapshot first");
  EXPECT_EQ(refused(command(CommandKind::kQueryContacts)).status, ReplyStatus::kRefused);
  client.load_case_file(case_file("nine_disc_damped"));
  const std::uint64_t running = client.start_cycle(100'000'000);
  ASSERT_TRUE(client.wait_for_status([](const auto& s) { return s.state == protocol::ServerState::kRunning; }, 10s));
  EXPECT_EQ(refused(cycle).message, "cycle refused: a command is already running: wait for it or stop it");
  protocol::Command parameter = command(CommandKind::kSetParameter);
  parameter.parameter = {"global_damping", "", 1.0, {}};
  EXPECT_EQ(refused(parameter).message, "set_parameter refused: not while a command is running: stop it first");
  EXPECT_EQ(refused(command(CommandKind::kLoadCase)).status, ReplyStatus::kRefused);
  client.stop();
  const auto cancelled = client.await(running, 10s);
  ASSERT_TRUE(cancelled);
  EXPECT_EQ(cancelled->status, ReplyStatus::kCancelled);
}

TEST(Errors, BadParameterValuesAreRefusedWithTheReason) {
  Fixture f("bad_parameters", kErrorsParameters);
  const auto parameter = [](std::string name, double value, std::string material = {}) {
    protocol::Command c = command(CommandKind::kSetParameter);
    c.parameter = {std::move(name), std::move(material), value, {}};
    return c;
  };
  EXPECT_EQ(f.refused(parameter("contact_damping", -1)).message, "contact_damping must be >= 0");
  EXPECT_EQ(f.refused(parameter("time_step_fraction", 2)).message, "time_step_fraction must be in (0, 1]");
  EXPECT_EQ(f.refused(parameter("time_step_fraction", std::nan(""))).message,
            "parameter.value: must be a finite number of magnitude at most 1e30");
  EXPECT_EQ(f.refused(parameter("friction", 0.3, "sand")).message, "no material \"sand\" (materials: disc, wall)");
  EXPECT_EQ(f.refused(parameter("friction", -0.3, "disc")).status, ReplyStatus::kBadRequest);
  EXPECT_EQ(f.refused(parameter("stiffness", 1)).status, ReplyStatus::kNotFound);
  protocol::Command gravity = parameter("gravity", 0);
  gravity.parameter.vector = {0.0, -9.81, 1.0};
  EXPECT_EQ(f.refused(gravity).message, "gravity has a z component, but the simulation is 2D");
  f.expect_untouched();
}

TEST(Errors, SnapshotPathsStayInTheOutputDirectory) {
  Fixture f("paths", kErrorsSnapshotPaths);
  protocol::Command save = command(CommandKind::kSaveSnapshot);
  save.snapshot.path = "/etc/dem.snapshot";
  EXPECT_EQ(f.refused(save).status, ReplyStatus::kBadRequest);
  save.snapshot.path = "../outside.snapshot";
  EXPECT_NE(f.refused(save).message.find("\"../outside.snapshot\": may not leave"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(f.server.server().options().output_directory / ".." / "outside.snapshot"));
  EXPECT_EQ(f.refused(command(CommandKind::kSaveSnapshot)).status, ReplyStatus::kBadRequest);
  f.expect_untouched();
}

TEST(Errors, AnUnknownCommandKindIsABadRequest) {
  Fixture f("kinds", kErrorsUnknownKind);
  protocol::Command strange;
  strange.kind = 99;
  const protocol::Reply reply = f.refused(strange);
  EXPECT_EQ(reply.status, ReplyStatus::kBadRequest);
  EXPECT_EQ(reply.message, "unknown command kind 99");
  f.expect_untouched();
}

}  // namespace
}  // namespace dem::test
