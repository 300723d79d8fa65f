// The files a server reads and writes for its clients stay inside the
// directories it was given - whatever the path: absolute, "..", or a link
// planted in an allowed directory - and a refusal never shows a byte of
// the file it refused (docs/RELIABILITY.md).
#include <gtest/gtest.h>

#include <fstream>

#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::CommandKind;
using protocol::ReplyStatus;
namespace fs = std::filesystem;

protocol::Reply reply_to(client::Client& client, protocol::Command c) {
  const std::optional<protocol::Reply> reply = client.await(client.send(std::move(c)), 20s);
  if (!reply) ADD_FAILURE() << "no reply";
  return reply.value_or(protocol::Reply{});
}

protocol::Reply load_path(client::Client& client, const std::string& path) {
  protocol::Command c;
  c.kind = static_cast<std::uint8_t>(CommandKind::kLoadCase);
  c.load_case.path = path;
  return reply_to(client, c);
}

// A file outside the allowed directories, with a line a leak would show.
fs::path secret_file(const fs::path& directory) {
  fs::create_directories(directory);
  const fs::path secret = directory / "secret.txt";
  std::ofstream(secret) << "the-secret-first-line\n1,2,3\n";
  return secret;
}

TEST(Files, CasesAndParticleFilesAreReadOnlyFromTheAllowedDirectories) {
  const fs::path base = output_directory("files_cases");
  const fs::path allowed = base / "allowed";
  fs::create_directories(allowed);
  const fs::path secret = secret_file(base / "outside");
  fs::copy_file(case_file("nine_disc_damped"), allowed / "nine.case.txtpb");
  fs::create_symlink(secret, allowed / "link.case.txtpb");
  service::ServerOptions options = server_options("files", kFilesCaseFiles);
  options.read_directories = {allowed};
  InProcessServer server(options);
  client::Client client(connect_options("files", kFilesCaseFiles));

  EXPECT_TRUE(load_path(client, (allowed / "nine.case.txtpb").string()).ok());
  for (const std::string& path : {secret.string(), (allowed / ".." / "outside" / "secret.txt").string(),
                                  (allowed / "link.case.txtpb").string(), std::string("/etc/passwd")}) {
    const protocol::Reply reply = load_path(client, path);
    EXPECT_EQ(reply.status, ReplyStatus::kNotFound) << path;
    EXPECT_NE(
        reply.message.find("not a file in the directories this server reads (" + fs::canonical(allowed).string() + ")"),
        std::string::npos)
        << reply.message;
    EXPECT_EQ(reply.message.find("the-secret"), std::string::npos) << reply.message;
    EXPECT_EQ(reply.message.find("root:"), std::string::npos) << reply.message;
  }

  // A case sent as text names a particle file outside: refused, unread.
  protocol::Command text;
  text.kind = static_cast<std::uint8_t>(CommandKind::kLoadCase);
  text.load_case.text = read_text(case_file("nine_disc_damped")) + "\nparticles { csv_file { path: \"" +
                        secret.string() + "\" material: \"disc\" } }\n";
  const protocol::Reply reply = reply_to(client, text);
  EXPECT_EQ(reply.status, ReplyStatus::kInvalidCase);
  EXPECT_NE(reply.message.find("not a file in the directories this server reads"), std::string::npos) << reply.message;
  EXPECT_EQ(reply.message.find("the-secret"), std::string::npos) << reply.message;
  EXPECT_EQ(client.get_state().state.case_name, "nine_disc_damped");  // untouched
}

// Without --read-dir a server reads no file a client names - not the
// directory it was started in, which may be "/" (issue 37) - and says how
// to allow it.
TEST(Files, WithoutAReadDirectoryServerSideLoadsAreRefusedSayingHowToAllowThem) {
  service::ServerOptions options = server_options("noreads", kFilesNoReadDirectory);
  options.read_directories.clear();
  InProcessServer server(options);
  client::Client client(connect_options("noreads", kFilesNoReadDirectory));
  for (const std::string& path : {std::string("/etc/passwd"), case_file("nine_disc_damped").string()}) {
    const protocol::Reply reply = load_path(client, path);
    EXPECT_EQ(reply.status, ReplyStatus::kRefused) << path;
    EXPECT_NE(reply.message.find("Start dem_server with --read-dir DIR"), std::string::npos) << reply.message;
    EXPECT_EQ(reply.message.find("root:"), std::string::npos) << reply.message;
  }
  EXPECT_TRUE(client.load_case_file(case_file("nine_disc_damped")).ok());  // a case sent as text still loads
  // A sent case that names a particle file: that file is a server-side read too.
  protocol::Command text;
  text.kind = static_cast<std::uint8_t>(CommandKind::kLoadCase);
  text.load_case.text = read_text(case_file("nine_disc_damped")) +
                        "\nparticles { csv_file { path: \"/etc/passwd\" material: \"disc\" } }\n";
  const protocol::Reply particles = reply_to(client, text);
  EXPECT_EQ(particles.status, ReplyStatus::kInvalidCase);
  EXPECT_NE(particles.message.find("start dem_server with --read-dir DIR"), std::string::npos) << particles.message;
  EXPECT_EQ(particles.message.find("root:"), std::string::npos) << particles.message;
}

// A file in a read directory that is no case, or a particle file that is
// no table, is named with its line and column - never with its text: it
// may be a secret kept beside the cases.
TEST(Files, AServerSideFileThatDoesNotParseIsNamedByLineAndColumnWithoutItsText) {
  const fs::path allowed = output_directory("files_hidden") / "allowed";
  fs::create_directories(allowed);
  std::ofstream(allowed / "secret.txt") << "root:x:0:0:root:/root:/bin/bash\n";
  std::ofstream(allowed / "number.case.txtpb")
      << "name: \"n\"\nmaterial { density: 99999999999999999999999999999999999999x }\n";
  std::ofstream(allowed / "bed.csv") << "x,y,r\n1,2,0.5\n3,the-secret-field,0.5\n";
  service::ServerOptions options = server_options("hidden", kFilesHiddenContent);
  options.read_directories = {allowed};
  InProcessServer server(options);
  client::Client client(connect_options("hidden", kFilesHiddenContent));

  protocol::Reply reply = load_path(client, (allowed / "secret.txt").string());
  EXPECT_EQ(reply.status, ReplyStatus::kInvalidCase);
  EXPECT_NE(reply.message.find("secret.txt:1:"), std::string::npos) << reply.message;
  for (const std::string leak : {"root", "bash", "x:0"}) {
    EXPECT_EQ(reply.message.find(leak), std::string::npos) << reply.message;
  }
  reply = load_path(client, (allowed / "number.case.txtpb").string());
  EXPECT_EQ(reply.status, ReplyStatus::kInvalidCase);
  EXPECT_NE(reply.message.find("number.case.txtpb:2:"), std::string::npos) << reply.message;
  EXPECT_EQ(reply.message.find("9999"), std::string::npos) << reply.message;

  protocol::Command text;
  text.kind = static_cast<std::uint8_t>(CommandKind::kLoadCase);
  text.load_case.text = read_text(case_file("nine_disc_damped")) + "\nparticles { csv_file { path: \"" +
                        (allowed / "bed.csv").string() + "\" material: \"disc\" } }\n";
  reply = reply_to(client, text);
  EXPECT_EQ(reply.status, ReplyStatus::kInvalidCase);
  EXPECT_NE(reply.message.find("bed.csv:3: column 2 (y): is not a number"), std::string::npos) << reply.message;
  EXPECT_EQ(reply.message.find("the-secret"), std::string::npos) << reply.message;
}

TEST(Files, SnapshotsAreNotWrittenOrReadThroughLinks) {
  service::ServerOptions options = server_options("links", kFilesSnapshotLinks);
  const fs::path outside = output_directory("files_links_outside");
  const fs::path secret = secret_file(outside);
  fs::create_directories(options.output_directory);
  fs::create_directory_symlink(outside, options.output_directory / "escape");
  fs::create_symlink(secret, options.output_directory / "planted.snapshot");
  InProcessServer server(options);
  client::Client client(connect_options("links", kFilesSnapshotLinks));
  client.load_case_file(case_file("nine_disc_damped"));

  protocol::Command save;
  save.kind = static_cast<std::uint8_t>(CommandKind::kSaveSnapshot);
  save.snapshot.path = "escape/x.snapshot";
  protocol::Reply reply = reply_to(client, save);
  EXPECT_EQ(reply.status, ReplyStatus::kBadRequest);
  EXPECT_NE(reply.message.find("its directory lies outside"), std::string::npos) << reply.message;
  EXPECT_FALSE(fs::exists(outside / "x.snapshot"));

  save.snapshot.path = "planted.snapshot";
  reply = reply_to(client, save);
  EXPECT_EQ(reply.status, ReplyStatus::kBadRequest);
  EXPECT_NE(reply.message.find("is a link"), std::string::npos) << reply.message;
  EXPECT_EQ(read_text(secret), "the-secret-first-line\n1,2,3\n");

  protocol::Command load;
  load.kind = static_cast<std::uint8_t>(CommandKind::kLoadSnapshot);
  load.snapshot.path = "planted.snapshot";
  reply = reply_to(client, load);
  EXPECT_EQ(reply.status, ReplyStatus::kBadRequest);
  EXPECT_EQ(reply.message.find("the-secret"), std::string::npos) << reply.message;
  EXPECT_TRUE(client.save_snapshot("inside/kept.snapshot").ok());  // its own files still work
}

// The files a server writes under fixed names - a case's tables, ParaView
// files, snapshots beside them and checkpoints - are not written through a
// link planted in its output directory: not a table that is a link to
// another file, not a case directory that leads elsewhere.
TEST(Files, TablesAndCheckpointsAreNotWrittenThroughLinks) {
  service::ServerOptions options = server_options("own", kFilesOwnDirectory);
  options.checkpoints.cycles = 10;
  const fs::path outside = output_directory("files_own_outside");
  const fs::path secret = secret_file(outside);
  fs::create_directories(options.output_directory / "nine_disc_damped");
  fs::create_symlink(secret, options.output_directory / "nine_disc_damped" / "walls.csv");
  fs::create_directory_symlink(outside, options.output_directory / "nine_disc_undamped");
  {
    InProcessServer server(options);
    client::Client client(connect_options("own", kFilesOwnDirectory));
    client.load_case_file(case_file("nine_disc_damped"));
    EXPECT_TRUE(client.cycle(50).ok());  // the simulation goes on; only its files are not written
    client.load_case_file(case_file("nine_disc_undamped"));
    EXPECT_TRUE(client.cycle(50).ok());
    EXPECT_TRUE(client.save_snapshot("inside/kept.snapshot").ok());  // its own files still work
  }
  EXPECT_EQ(read_text(secret), "the-secret-first-line\n1,2,3\n");
  std::vector<std::string> written;
  for (const auto& entry : fs::directory_iterator(outside)) written.push_back(entry.path().filename().string());
  EXPECT_EQ(written, std::vector<std::string>{"secret.txt"});
  EXPECT_FALSE(fs::exists(options.output_directory / "nine_disc_damped" / "checkpoints"));
}

}  // namespace
}  // namespace dem::test
