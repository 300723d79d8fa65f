// libFuzzer target: any bytes as a command sample off the wire - Cyclone
// DDS's own normalisation and read against the Command_ type, the
// conversion to protocol::Command (the server's command decoder), the
// server's argument checks (check_command) and then the command applied to
// a small loaded simulation: walls, servos, parameters, contact queries,
// cases and snapshots sent in the command, files named by it (confined to
// the fuzz corpus's directory). Cycling commands run at most a few cycles.
#include <string_view>

#include "dem/error.h"
#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/protocol/command_cdr.h"
#include "dem/service/command_error.h"
#include "dem/service/command_limits.h"
#include "dem/service/simulation.h"
#include "fuzz_support.h"

namespace {

using dem::protocol::CommandKind;

// Nine discs in a box (cases/ball/nine_disc_damped.case.txtpb), converted once.
const dem::io::CaseDefinition& nine_discs() {
  static const dem::io::CaseDefinition definition = [] {
    const dem::io::LoadedCase loaded = dem::io::load_case_file(DEM_FUZZ_NINE_DISC_CASE);
    return dem::io::convert_case(loaded.message, loaded.source);
  }();
  return definition;
}

dem::service::CommandLimits command_limits() {
  dem::service::CommandLimits limits;
  limits.max_payload_bytes = 1 << 20;
  limits.max_query_contacts = 1000;
  return limits;
}

// A few cycles as the server runs them: a one-stage programme of the engine's.
void cycle(dem::service::WorldSession& world, std::uint64_t cycles) {
  auto run = dem::service::CaseProgramme::one_stage(world.dimension(), cycles, {}).begin_stage(0, world);
  run.cycle(run.cycles_to_next_stop());
}

void apply(dem::service::Simulation& simulation, const dem::protocol::Command& c) {
  switch (*dem::protocol::command_kind(c.kind)) {
    case CommandKind::kLoadCase:
      simulation.install(simulation.prepare_case(c.load_case));
      break;
    case CommandKind::kSetWallVelocity:
      simulation.set_wall_velocity(c.wall_velocity);
      break;
    case CommandKind::kSetWallServo:
      simulation.set_wall_servo(c.wall_servo);
      break;
    case CommandKind::kCycle:
      cycle(simulation.world(), std::min<std::uint64_t>(static_cast<std::uint64_t>(c.cycle.cycles), 3));
      break;
    case CommandKind::kRunUntil:
      if (c.run_until.stress || c.run_until.settlement) simulation.find_wall(c.run_until.wall, c.run_until.wall_id);
      cycle(simulation.world(), 1);
      break;
    case CommandKind::kQueryContacts:
      (void)simulation.query_contacts(c.query);
      break;
    case CommandKind::kSaveSnapshot:
      (void)simulation.snapshot_bytes();
      break;
    case CommandKind::kLoadSnapshot:
      if (c.snapshot.transfer) simulation.install(simulation.prepare_snapshot(c.snapshot.data, "<transfer>"));
      break;
    case CommandKind::kSetParameter:
      (void)simulation.set_parameter(c.parameter);
      break;
    case CommandKind::kStop:
    case CommandKind::kGetState:
    case CommandKind::kShutdown:
    case CommandKind::kRunProgramme:
      (void)simulation.world().state_hash();
      break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::optional<dem::protocol::Command> command =
      dem::protocol::decode_command(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!command) return 0;  // Cyclone drops such a sample
  try {
    dem::service::check_command(*command, command_limits());
    dem::service::Simulation simulation(1, dem::fuzz::limits(), command_limits().max_query_contacts,
                                        dem::fuzz::files());
    dem::service::Simulation::Prepared prepared;
    prepared.world = std::make_unique<dem::service::WorldSession>(dem::World(nine_discs().world));
    prepared.programme = dem::service::CaseProgramme(nine_discs().stages);
    prepared.case_name = "nine_discs";
    prepared.contact_models = nine_discs().world.contact_models;
    simulation.install(std::move(prepared));
    apply(simulation, *command);
  } catch (const dem::service::CommandError&) {
  } catch (const std::exception& error) {
    dem::fuzz::unexpected("command", error);
  }
  return 0;
}
