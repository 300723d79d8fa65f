// The interface judged at discovery, on both sides (docs/DDS.md, "Evolving
// the wire"): every endpoint declares its ROS 2 type hash and the version;
// a server logs a client whose Command is of dem_interfaces 0.1.0 as soon
// as discovery finds it, naming the fields its commands lack; a client
// that meets a server of that older interface is told so at connection
// (InterfaceMismatch), not left waiting for replies that cannot come.
#include <dds/dds.h>
#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "dem/dds/discovery.h"
#include "dem/protocol/interface_check.h"
#include "dem/protocol/interface_version.h"
#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"
#include "dem/protocol/type_support.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::TopicKind;

// The user data a build of the package's 0.1.0 files declared (ROS 2 Iron's form).
std::string user_data_of_010(std::string_view type_name, std::string_view versions) {
  const auto found = std::find_if(protocol::kOlderForms.begin(), protocol::kOlderForms.end(),
                                  [&](const auto& f) { return f.type_name == type_name && f.versions == versions; });
  EXPECT_NE(found, protocol::kOlderForms.end()) << type_name;
  return "typehash=" + std::string(found->hash) + ";";
}

// A reader or writer created with the C API, so its USER_DATA is the one given.
dds_entity_t endpoint(const dds::Participant& participant, dds_entity_t topic, const dds::Qos& qos,
                      const std::string& user_data, bool writer) {
  dds::Qos with = qos;
  with.user_data(user_data);
  const dds_entity_t entity = writer ? dds_create_writer(participant.handle(), topic, with.get(), nullptr)
                                     : dds_create_reader(participant.handle(), topic, with.get(), nullptr);
  EXPECT_GT(entity, 0) << dds_strretcode(entity);
  return entity;
}

TEST(Interfaces, EveryEndpointDeclaresItsTypeHashAndTheVersion) {
  InProcessServer server(server_options("declared", kInterfaceMismatchServer));
  dds::Participant watcher(kInterfaceMismatchServer);
  dds::EndpointMonitor writers(watcher, dds::EndpointMonitor::Kind::kWriters);
  dds::EndpointMonitor readers(watcher, dds::EndpointMonitor::Kind::kReaders);
  const auto declared = [&](const std::string& topic, bool writer) {
    for (const dds::Endpoint& e : writer ? writers.alive() : readers.alive()) {
      if (e.topic_name == topic) return e.user_data;
    }
    return std::string();
  };
  const std::string status = protocol::topic_name("declared", TopicKind::kStatus);
  const std::string command = protocol::topic_name("declared", TopicKind::kCommand);
  ASSERT_TRUE(eventually([&] { return !declared(status, true).empty() && !declared(command, false).empty(); }, 10s));
  EXPECT_EQ(declared(status, true), protocol::endpoint_user_data("dem_interfaces::msg::dds_::Status_"));
  EXPECT_EQ(declared(command, false),
            "typehash=" + std::string(protocol::type_hash_of("dem_interfaces::msg::dds_::Command_")) +
                ";dem_interfaces=" + std::string(protocol::kInterfaceVersion) + ";");
}

TEST(Interfaces, AServerLogsAClientOfAnOlderInterfaceWhenDiscoveryFindsIt) {
  auto log = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(64);
  spdlog::default_logger()->sinks().push_back(log);
  const auto warned = [&](const std::string& text) {
    for (const std::string& line : log->last_formatted()) {
      if (line.find("[warning]") != std::string::npos && line.find(text) != std::string::npos) return true;
    }
    return false;
  };
  {
    InProcessServer server(server_options("wire", kInterfaceMismatchServer));
    // A client built from the package's first files: its Command writer
    // declares that Command's hash (the test's writer carries today's type,
    // so nothing is sent that the server could misread).
    dds::Participant old(kInterfaceMismatchServer);
    dds::Topic<protocol::Command> topic(old, protocol::topic_name("wire", TopicKind::kCommand));
    const dds_entity_t writer =
        endpoint(old, topic.handle(), protocol::command_qos(),
                 user_data_of_010("dem_interfaces::msg::dds_::Command_", "0.1.0 as of 0308f76"), true);
    const std::string expected =
        "rt/dem/wire/command: a writer of Command built from dem_interfaces 0.1.0 as of 0308f76, whose Command lacks "
        "force, programme_steps, query.particle_set, query.particle: its samples cannot be read by this server "
        "(dem_interfaces "
        "0.3.0) and are dropped; rebuild it from dem_interfaces 0.3.0";
    EXPECT_TRUE(eventually([&] { return warned(expected); }, 10s));
    dds_delete(writer);
  }
  std::vector<std::shared_ptr<spdlog::sinks::sink>>& sinks = spdlog::default_logger()->sinks();
  sinks.erase(std::remove(sinks.begin(), sinks.end(), log), sinks.end());
}

TEST(Interfaces, AClientIsToldAtConnectionThatTheServerIsOfAnOlderInterface) {
  // A server of the package's first files: its status is readable (Status
  // has not changed), its command reader and reply writer are 0.1.0's.
  dds::Participant old(kInterfaceMismatchClient);
  dds::Topic<protocol::Status> status_topic(old, protocol::topic_name("old", TopicKind::kStatus));
  dds::Topic<protocol::Command> command_topic(old, protocol::topic_name("old", TopicKind::kCommand));
  dds::Topic<protocol::Reply> reply_topic(old, protocol::topic_name("old", TopicKind::kReply));
  dds::Writer<protocol::Status> status(old, status_topic, protocol::status_qos());
  const dds_entity_t commands =
      endpoint(old, command_topic.handle(), protocol::command_qos(),
               user_data_of_010("dem_interfaces::msg::dds_::Command_", "0.1.0 as of 0308f76"), false);
  const dds_entity_t replies =
      endpoint(old, reply_topic.handle(), protocol::reply_qos(),
               user_data_of_010("dem_interfaces::msg::dds_::Reply_", "0.1.0 as of 0308f76 to 0ff9d3e"), true);
  protocol::Status idle;
  idle.server = "old";
  idle.state = protocol::ServerState::kIdle;
  status.write(idle);

  auto options = connect_options("old", kInterfaceMismatchClient);
  options.timeout = 2s;
  try {
    client::Client client(options);
    ADD_FAILURE() << "connected to a server whose commands it cannot send";
  } catch (const client::InterfaceMismatch& error) {
    const std::string text = error.what();
    std::printf("%s\n", text.c_str());
    EXPECT_TRUE(text.starts_with("server \"old\" cannot meet this client: ")) << text;
    EXPECT_NE(
        text.find(
            "rt/dem/old/command: a reader of Command built from dem_interfaces 0.1.0 as of 0308f76, whose "
            "Command lacks force, programme_steps, query.particle_set, query.particle: it cannot read the samples of "
            "this client (dem_interfaces 0.3.0)"),
        std::string::npos)
        << text;
    EXPECT_NE(text.find("rt/dem/old/reply: a writer of Reply built from dem_interfaces 0.1.0"), std::string::npos)
        << text;
  }
  dds_delete(commands);
  dds_delete(replies);
}

}  // namespace
}  // namespace dem::test
