// demctl: drives and watches dem_server over DDS (docs/SERVICE.md).
//   demctl [--server NAME] [--domain ID] SUBCOMMAND ...
// Exit codes (exit_codes.h): 0 done; 1 other failure; 2 bad arguments;
// 3 no such server within --timeout; 4 the server replied with an error;
// 5 no reply in time; 6 run-until --wait ended at its cycle cap without
// meeting its condition; 7 the server's interface and demctl's cannot meet;
// 130 interrupted.
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>

#include "commands.h"
#include "dem/client/errors.h"
#include "dem/dds/error.h"
#include "dem/version.h"
#include "exit_codes.h"
#include "interrupt.h"

namespace {

// Defaults from the environment, so a shell can aim every call at one server.
void environment_defaults(demctl::Global& global) {
  if (const char* server = std::getenv("DEM_SERVER")) global.server = server;
  if (const char* domain = std::getenv("DEM_DOMAIN")) global.domain = static_cast<std::uint32_t>(std::atoi(domain));
}

}  // namespace

int main(int argc, char** argv) {
  demctl::Global global;
  environment_defaults(global);
  CLI::App app{"Drives and watches dem_server simulations over DDS (loopback only by default)."};
  app.set_version_flag("--version", "demctl " DEM_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 done, 1 other failure, 2 bad arguments, 3 no such server within --timeout,\n"
      "4 the server replied with an error, 5 no reply in time, 6 run-until --wait reached its cycle cap\n"
      "before its condition, 7 the server's interface and demctl's cannot meet, 130 interrupted.");
  app.fallthrough();  // --server and --domain may also follow the subcommand
  app.add_option("-s,--server", global.server, "server name (default $DEM_SERVER, else dem)")->capture_default_str();
  app.add_option("-d,--domain", global.domain, "DDS domain id (default $DEM_DOMAIN, else 0)")
      ->capture_default_str()
      ->check(CLI::Range(0, 232));
  app.add_option("--dds-config", global.dds_config,
                 "Cyclone DDS configuration; default $CYCLONEDDS_URI, else the repository's loopback-only file");
  app.add_option("--timeout", global.timeout, "seconds to find the server")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("-q,--quiet", global.quiet, "no progress bar");

  std::function<int()> action;

  double discovery = 1.5;
  std::string servers_sweep;
  auto* servers = app.add_subcommand("servers", "list the servers alive on the domain");
  servers->add_option("--wait", discovery, "seconds of discovery")->capture_default_str()->check(CLI::PositiveNumber);
  servers->add_option("--sweep", servers_sweep, "only the servers of this sweep (named <sweep>_<task>)");
  servers->callback([&] { action = [&] { return demctl::servers(global, discovery, servers_sweep); }; });

  bool json = false;
  auto* status = app.add_subcommand("status", "the server's state, plates and contacts");
  status->add_flag("--json", json, "one JSON object with the messages' field names (docs/SERVICE.md), for scripts");
  status->callback([&] { action = [&] { return demctl::status(global, json); }; });

  std::string case_file;
  bool on_server = false;
  bool binary = false;
  auto* load = app.add_subcommand("load", "load a case (sent as text; the server reports file, line and field)");
  load->add_option("CASE", case_file, "case file in protobuf text format")->required();
  load->add_flag("--on-server", on_server,
                 "CASE is a path on the server's file system (in a directory it was started with --read-dir)");
  load->add_flag("--binary", binary, "CASE is a serialized dem.proto.Case");
  load->callback([&] { action = [&] { return demctl::load(global, case_file, on_server, binary); }; });

  std::string wall;
  std::vector<double> values;
  auto* velocity =
      app.add_subcommand("wall-velocity", "move a wall: velocity of its point P, angular velocity about z");
  velocity->add_option("WALL", wall, "wall name")->required();
  velocity->add_option("VALUES", values, "VX VY [VZ] [OMEGA] in m/s and rad/s")->required()->expected(2, 4);
  velocity->callback([&] { action = [&] { return demctl::wall_velocity(global, wall, values); }; });

  double stress = 0.0;
  double gain = 0.0;
  double max_speed = 0.0;
  auto* servo = app.add_subcommand("servo", "servo-control a wall to a normal stress (Randall 1989, 4.1)");
  servo->add_option("WALL", wall, "wall name")->required();
  servo->add_option("STRESS", stress, "target normal stress, Pa (compressive positive)")->required();
  servo->add_option("--gain", gain, "m/(Pa s); default chosen by the server from the contact stiffness");
  servo->add_option("--max-speed", max_speed, "m/s; default a twentieth of the mean radius per step");
  servo->callback([&] { action = [&] { return demctl::servo(global, wall, stress, gain, max_speed); }; });

  std::int64_t cycles = 0;
  bool wait = false;
  auto* cycle = app.add_subcommand("cycle", "run N cycles (returns once accepted, or at the end with --wait)");
  cycle->add_option("N", cycles, "number of cycles")->required();
  cycle->add_flag("-w,--wait", wait, "wait for the end, with a progress bar (Ctrl-C stops the run)");
  cycle->callback([&] { action = [&] { return demctl::cycle(global, cycles, wait); }; });

  dem::protocol::RunUntilArgs until;
  double until_stress = 0.0;
  double until_settlement = 0.0;
  double until_energy = 0.0;
  auto* run_until = app.add_subcommand("run-until",
                                       "run until a plate's stress or settlement, or the kinetic energy, "
                                       "reaches a value, at most --max-cycles");
  run_until->add_option("--wall", until.wall, "the plate for --stress and --settlement");
  auto* stress_option = run_until->add_option("--stress", until_stress, "Pa");
  auto* settlement_option = run_until->add_option("--settlement", until_settlement, "m");
  auto* energy_option = run_until->add_option("--kinetic-energy", until_energy, "J: stop below");
  run_until->add_option("--max-cycles", until.max_cycles, "cycle cap")->required();
  run_until->add_option("--check-interval", until.check_interval, "cycles between checks (default every cycle)");
  run_until->add_flag("-w,--wait", wait,
                      "wait for the end, with a progress bar; exit 6 when the cycle cap comes before the condition");
  run_until->callback([&] {
    if (stress_option->count() > 0) until.stress = until_stress;
    if (settlement_option->count() > 0) until.settlement = until_settlement;
    if (energy_option->count() > 0) until.kinetic_energy = until_energy;
    action = [&] { return demctl::run_until(global, until, wait); };
  });

  std::uint32_t first_stage = 0;
  std::uint32_t stage_count = 0;
  auto* programme = app.add_subcommand("run-programme",
                                       "run the loaded case's stages as dem_run does (trim, place "
                                       "walls, wall motions, stop conditions)");
  programme->add_option("--from", first_stage, "the first stage to run, counted from 1 (default: the first)");
  programme->add_option("--stages", stage_count, "how many stages to run (default: to the last)");
  programme->add_flag("-w,--wait", wait, "wait for the end, with a progress bar (Ctrl-C stops the run)");
  programme->callback([&] { action = [&] { return demctl::run_programme(global, first_stage, stage_count, wait); }; });

  bool force = false;
  auto* stop = app.add_subcommand("stop", "stop the running cycle, run-until or run-programme");
  stop->add_flag("--force", force, "also another client's run (docs/SERVICE.md)");
  stop->callback([&] { action = [&] { return demctl::stop(global, force); }; });

  dem::protocol::ContactQueryArgs query;
  std::vector<double> box;
  double min_force = 0.0;
  std::string csv;
  int limit = 20;
  auto* contacts = app.add_subcommand("contacts", "query contacts: all, on a wall, in a box, above a force");
  auto* wall_option = contacts->add_option("--wall", query.wall, "contacts on this wall");
  auto* box_option =
      contacts->add_option("--box", box, "XMIN,YMIN,XMAX,YMAX: contact points inside")->delimiter(',')->expected(4);
  auto* force_option = contacts->add_option("--min-force", min_force, "N: contacts carrying more");
  std::int32_t particle = -1;
  auto* particle_option =
      contacts->add_option("--particle", particle, "the contacts of this particle (its id, kept through trims)");
  contacts->add_option("--csv", csv, "write every contact to this file");
  contacts->add_option("--limit", limit, "rows to print")->capture_default_str();
  contacts->callback([&] {
    query.wall_set = wall_option->count() > 0;
    if (box_option->count() > 0) {
      query.box_set = true;
      query.box_min = {box[0], box[1], 0.0};
      query.box_max = {box[2], box[3], 0.0};
    }
    if (force_option->count() > 0) query.min_normal_force = min_force;
    if (particle_option->count() > 0) query.particle = particle;
    action = [&] { return demctl::contacts(global, query, csv, limit); };
  });

  std::string snapshot_file;
  auto* snapshot = app.add_subcommand("snapshot", "save or load the whole state (protobuf) for exact restart");
  snapshot->require_subcommand(1);
  auto* save = snapshot->add_subcommand("save", "save to FILE here (or in the server's output directory)");
  save->add_option("FILE", snapshot_file)->required();
  save->add_flag("--on-server", on_server, "FILE is relative to the server's output directory");
  save->callback([&] { action = [&] { return demctl::snapshot_save(global, snapshot_file, on_server); }; });
  auto* restore = snapshot->add_subcommand("load", "load from FILE here (or in the server's output directory)");
  restore->add_option("FILE", snapshot_file)->required();
  restore->add_flag("--on-server", on_server, "FILE is relative to the server's output directory");
  restore->callback([&] { action = [&] { return demctl::snapshot_load(global, snapshot_file, on_server); }; });

  std::string parameter;
  std::string value;
  auto* set = app.add_subcommand("set",
                                 "set a parameter: contact_damping, global_damping, local_damping, "
                                 "time_step_fraction, friction.MATERIAL, gravity GX,GY[,GZ]");
  set->add_option("PARAM", parameter)->required();
  set->add_option("VALUE", value)->required();
  set->callback([&] { action = [&] { return demctl::set(global, parameter, value); }; });

  demctl::MonitorOptions monitor_options;
  std::uint64_t samples = 0;
  auto* monitor = app.add_subcommand("monitor", "live table of plate stress, settlement and contact statistics");
  auto* samples_option = monitor->add_option("-n,--samples", samples, "stop after N rows (default: Ctrl-C)");
  monitor->add_option("--csv", monitor_options.csv, "record the rows in this file too");
  monitor->add_option("--wall", monitor_options.walls, "plates to show (default: every wall)");
  auto* sweep_option = monitor->add_option("--sweep", monitor_options.sweep,
                                           "follow every server of this sweep (named <sweep>_<task>) as they come "
                                           "and go, each row naming its server");
  monitor->add_flag("--all", monitor_options.all, "follow every server of the domain, as --sweep does")
      ->excludes(sweep_option);
  monitor
      ->add_option("--idle-exit", monitor_options.idle_exit,
                   "with --sweep or --all: stop once none of those servers has been there for S seconds")
      ->check(CLI::PositiveNumber);
  monitor->callback([&] {
    if (samples_option->count() > 0) monitor_options.samples = samples;
    action = [&] { return demctl::monitor(global, monitor_options); };
  });

  demctl::RecordOptions record_options;
  std::uint64_t record_samples = 0;
  double record_duration = 0.0;
  auto* record = app.add_subcommand("record",
                                    "record the telemetry to an MCAP file (ros2msg schemas, CDR messages: "
                                    "a ROS 2 bag, for Foxglove and Python's dem.recording)");
  record->add_option("FILE", record_options.file, "the .mcap file to write")->required();
  auto* record_samples_option = record->add_option("-n,--samples", record_samples,
                                                   "stop after N plate forces samples (default: Ctrl-C or the "
                                                   "server stopping)");
  auto* record_duration_option =
      record->add_option("--duration", record_duration, "stop after this many seconds")->check(CLI::PositiveNumber);
  record->callback([&] {
    if (record_samples_option->count() > 0) record_options.samples = record_samples;
    if (record_duration_option->count() > 0) record_options.duration = record_duration;
    action = [&] { return demctl::record(global, record_options); };
  });

  bool no_wait = false;
  auto* shutdown = app.add_subcommand("shutdown", "stop the server cleanly (waits until it has stopped)");
  shutdown->add_flag("--no-wait", no_wait, "return once the server accepted");
  shutdown->add_flag("--force", force, "also while another client's run is going on");
  shutdown->callback([&] { action = [&] { return demctl::shutdown(global, !no_wait, force); }; });

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? demctl::kOk : demctl::kBadArguments;
  }

  demctl::watch_interrupts();
  try {
    return action();
  } catch (const demctl::BadArguments& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kBadArguments;
  } catch (const std::invalid_argument& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kBadArguments;
  } catch (const dem::client::LocalFileError& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kBadArguments;
  } catch (const dem::client::InterfaceMismatch& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kInterfaceMismatch;
  } catch (const dem::client::NoSuchServer& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kNoSuchServer;
  } catch (const dem::client::ServerError& error) {
    std::cerr << "demctl: server " << global.server << ": " << dem::protocol::to_string(error.status()) << ": "
              << error.what() << '\n';
    return demctl::kServerError;
  } catch (const dem::client::ReplyTimeout& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kNoReply;
  } catch (const std::exception& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kFailure;
  }
}
