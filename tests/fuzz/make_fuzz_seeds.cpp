// Writes the fuzz targets' binary seeds (docs/FUZZING.md) from the text
// seeds in corpus/case_text:
//   corpus/case_binary/<case>.bin    each case serialized
//   corpus/snapshot/<case>.snapshot  a world of each case after 20 cycles,
//                                    as fuzz_snapshot reads it (a 1 byte, then
//                                    the payload), and one framed file (a 0 byte)
//   corpus/command/<kind>.cdr        a command sample of each kind
// Run when the schemas change: build/tests/fuzz/make_fuzz_seeds.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <variant>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/snapshot_file.h"
#include "dem/io/snapshot_frame.h"
#include "dem/protocol/command_cdr.h"

namespace {

using namespace dem;
using protocol::CommandKind;
namespace fs = std::filesystem;

const fs::path kFuzz = DEM_FUZZ_DIR;

void write(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  std::cout << path.lexically_relative(kFuzz).string() << " (" << bytes.size() << " bytes)\n";
}

protocol::Command command(CommandKind kind) {
  protocol::Command c;
  c.server = "fuzz";
  c.client_id = "seed-1";
  c.request_id = 7;
  c.kind = static_cast<std::uint8_t>(kind);
  return c;
}

}  // namespace

int main() {
  std::string small_snapshot;
  for (const auto& entry : fs::directory_iterator(kFuzz / "corpus/case_text")) {
    const std::string stem = entry.path().stem().stem().string();
    io::LoadedCase loaded;
    try {
      loaded = io::load_case_file(entry.path());
    } catch (const io::CaseError&) {
      continue;  // a seed that does not parse has no binary form
    }
    write(kFuzz / "corpus/case_binary" / (stem + ".bin"), loaded.message.SerializeAsString());
    loaded.source.directory = kFuzz / "corpus/files";
    try {
      const io::AnyCaseDefinition definition = io::convert_any_case(loaded.message, loaded.source);
      std::visit(
          [&](const auto& d) {
            BasicWorld<std::decay_t<decltype(d.world.particles[0].position)>::RowsAtCompileTime> world(d.world);
            world.cycle(20);
            const std::string framed = io::serialize_snapshot(world.snapshot(), io::SnapshotInfo{d.name, ""});
            const std::string payload(io::unframe_snapshot(framed, stem));
            write(kFuzz / "corpus/snapshot" / (stem + ".snapshot"), '\x01' + payload);
            if (stem == "nine_disc_damped") {
              write(kFuzz / "corpus/snapshot" / (stem + "_framed.snapshot"), '\x00' + framed);
              small_snapshot = framed;
            }
          },
          definition);
    } catch (const std::exception& error) {
      std::cout << stem << ": no snapshot (" << error.what() << ")\n";
    }
  }

  const fs::path commands = kFuzz / "corpus/command";
  protocol::Command c = command(CommandKind::kLoadCase);
  std::ifstream text(kFuzz / "corpus/case_text/nine_disc_damped.case.txtpb");
  c.load_case.text.assign(std::istreambuf_iterator<char>(text), {});
  write(commands / "load_case_text.cdr", protocol::encode_command(c));
  c = command(CommandKind::kLoadCase);
  c.load_case.path = "valid.case.txtpb";
  write(commands / "load_case_path.cdr", protocol::encode_command(c));
  c = command(CommandKind::kSetWallVelocity);
  c.wall_velocity.wall = "top";
  c.wall_velocity.twist.linear = {0, -12, 0};
  write(commands / "set_wall_velocity.cdr", protocol::encode_command(c));
  c = command(CommandKind::kSetWallServo);
  c.wall_servo.wall = "top";
  c.wall_servo.target_stress = 1e6;
  write(commands / "set_wall_servo.cdr", protocol::encode_command(c));
  c = command(CommandKind::kCycle);
  c.cycle.cycles = 100;
  write(commands / "cycle.cdr", protocol::encode_command(c));
  c = command(CommandKind::kRunUntil);
  c.run_until.wall = "top";
  c.run_until.stress = 1e5;
  c.run_until.max_cycles = 1000;
  write(commands / "run_until.cdr", protocol::encode_command(c));
  c = command(CommandKind::kQueryContacts);
  c.query.wall_set = true;
  c.query.wall = "bottom";
  c.query.box_set = true;
  c.query.box_max = {300, 300, 0};
  c.query.min_normal_force = 0.0;
  write(commands / "query_contacts.cdr", protocol::encode_command(c));
  c = command(CommandKind::kSaveSnapshot);
  c.snapshot.path = "kept.snapshot";
  write(commands / "save_snapshot.cdr", protocol::encode_command(c));
  c = command(CommandKind::kLoadSnapshot);
  c.snapshot.transfer = true;
  c.snapshot.data = small_snapshot;
  write(commands / "load_snapshot.cdr", protocol::encode_command(c));
  c = command(CommandKind::kSetParameter);
  c.parameter.name = "friction";
  c.parameter.material = "disc";
  c.parameter.value = 0.3;
  write(commands / "set_parameter.cdr", protocol::encode_command(c));
  c = command(CommandKind::kRunProgramme);
  c.programme = {2, 1};
  c.programme_steps = {.sample_every = 10, .stage_ends = true, .resume = true, .stage_cycles_done = 20};
  write(commands / "run_programme_steps.cdr", protocol::encode_command(c));
  for (const auto kind :
       {CommandKind::kStop, CommandKind::kGetState, CommandKind::kShutdown, CommandKind::kRunProgramme}) {
    write(commands / (std::string(protocol::to_string(kind)) + ".cdr"), protocol::encode_command(command(kind)));
  }
  return 0;
}
