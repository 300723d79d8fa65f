#include "subcommands.h"

#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "monitor.h"
#include "record.h"

namespace demctl {
namespace {

// Each subcommand keeps its parsed options in a value of its own, shared
// by its parse callback and the action it sets.
template <typename Options>
std::shared_ptr<Options> options_of() {
  return std::make_shared<Options>();
}

void add_servers(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    double discovery = 1.5;
    std::string sweep;
  };
  auto o = options_of<Options>();
  auto* servers = app.add_subcommand("servers", "list the servers alive on the domain");
  servers->add_option("--wait", o->discovery, "seconds of discovery")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  servers->add_option("--sweep", o->sweep, "only the servers of this sweep (named <sweep>_<task>)");
  servers->callback([&, o] { action = [&, o] { return demctl::servers(global, o->discovery, o->sweep); }; });
}

void add_status_and_load(CLI::App& app, const Global& global, Action& action) {
  auto json = std::make_shared<bool>(false);
  auto* status = app.add_subcommand("status", "the server's state, plates and contacts");
  status->add_flag("--json", *json, "one JSON object with the messages' field names (docs/SERVICE.md), for scripts");
  status->callback([&, json] { action = [&, json] { return demctl::status(global, *json); }; });

  struct Options {
    std::string case_file;
    bool on_server = false;
    bool binary = false;
  };
  auto o = options_of<Options>();
  auto* load = app.add_subcommand("load", "load a case (sent as text; the server reports file, line and field)");
  load->add_option("CASE", o->case_file, "case file in protobuf text format")->required();
  load->add_flag("--on-server", o->on_server,
                 "CASE is a path on the server's file system (in a directory it was started with --read-dir)");
  load->add_flag("--binary", o->binary, "CASE is a serialized dem.proto.Case");
  load->callback([&, o] { action = [&, o] { return demctl::load(global, o->case_file, o->on_server, o->binary); }; });
}

void add_wall_controls(CLI::App& app, const Global& global, Action& action) {
  struct Velocity {
    std::string wall;
    std::vector<double> values;
  };
  auto v = options_of<Velocity>();
  auto* velocity =
      app.add_subcommand("wall-velocity", "move a wall: velocity of its point P, angular velocity about z");
  velocity->add_option("WALL", v->wall, "wall name")->required();
  velocity->add_option("VALUES", v->values, "VX VY [VZ] [OMEGA] in m/s and rad/s")->required()->expected(2, 4);
  velocity->callback([&, v] { action = [&, v] { return wall_velocity(global, v->wall, v->values); }; });

  struct Servo {
    std::string wall;
    double stress = 0.0;
    double gain = 0.0;
    double max_speed = 0.0;
  };
  auto s = options_of<Servo>();
  auto* servo = app.add_subcommand("servo", "servo-control a wall to a normal stress (Randall 1989, 4.1)");
  servo->add_option("WALL", s->wall, "wall name")->required();
  servo->add_option("STRESS", s->stress, "target normal stress, Pa (compressive positive)")->required();
  servo->add_option("--gain", s->gain, "m/(Pa s); default chosen by the server from the contact stiffness");
  servo->add_option("--max-speed", s->max_speed, "m/s; default a twentieth of the mean radius per step");
  servo->callback(
      [&, s] { action = [&, s] { return demctl::servo(global, s->wall, s->stress, s->gain, s->max_speed); }; });
}

void add_cycle(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    std::int64_t cycles = 0;
    bool wait = false;
  };
  auto o = options_of<Options>();
  auto* cycle = app.add_subcommand("cycle", "run N cycles (returns once accepted, or at the end with --wait)");
  cycle->add_option("N", o->cycles, "number of cycles")->required();
  cycle->add_flag("-w,--wait", o->wait, "wait for the end, with a progress bar (Ctrl-C stops the run)");
  cycle->callback([&, o] { action = [&, o] { return demctl::cycle(global, o->cycles, o->wait); }; });
}

void add_run_until(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    dem::protocol::RunUntilArgs until;
    double stress = 0.0;
    double settlement = 0.0;
    double energy = 0.0;
    bool wait = false;
  };
  auto o = options_of<Options>();
  auto* run_until = app.add_subcommand("run-until",
                                       "run until a plate's stress or settlement, or the kinetic energy, "
                                       "reaches a value, at most --max-cycles");
  run_until->add_option("--wall", o->until.wall, "the plate for --stress and --settlement");
  auto* stress = run_until->add_option("--stress", o->stress, "Pa");
  auto* settlement = run_until->add_option("--settlement", o->settlement, "m");
  auto* energy = run_until->add_option("--kinetic-energy", o->energy, "J: stop below");
  run_until->add_option("--max-cycles", o->until.max_cycles, "cycle cap")->required();
  run_until->add_option("--check-interval", o->until.check_interval, "cycles between checks (default every cycle)");
  run_until->add_flag("-w,--wait", o->wait,
                      "wait for the end, with a progress bar; exit 6 when the cycle cap comes before the condition");
  run_until->callback([&, o, stress, settlement, energy] {
    if (stress->count() > 0) o->until.stress = o->stress;
    if (settlement->count() > 0) o->until.settlement = o->settlement;
    if (energy->count() > 0) o->until.kinetic_energy = o->energy;
    action = [&, o] { return demctl::run_until(global, o->until, o->wait); };
  });
}

void add_run_programme_and_stop(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    std::uint32_t first_stage = 0;
    std::uint32_t stage_count = 0;
    bool wait = false;
  };
  auto o = options_of<Options>();
  auto* programme = app.add_subcommand("run-programme",
                                       "run the loaded case's stages as dem_run does (trim, place "
                                       "walls, wall motions, stop conditions)");
  programme->add_option("--from", o->first_stage, "the first stage to run, counted from 1 (default: the first)");
  programme->add_option("--stages", o->stage_count, "how many stages to run (default: to the last)");
  programme->add_flag("-w,--wait", o->wait, "wait for the end, with a progress bar (Ctrl-C stops the run)");
  programme->callback(
      [&, o] { action = [&, o] { return demctl::run_programme(global, o->first_stage, o->stage_count, o->wait); }; });

  auto force = std::make_shared<bool>(false);
  auto* stop = app.add_subcommand("stop", "stop the running cycle, run-until or run-programme");
  stop->add_flag("--force", *force, "also another client's run (docs/SERVICE.md)");
  stop->callback([&, force] { action = [&, force] { return demctl::stop(global, *force); }; });
}

void add_contacts(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    dem::protocol::ContactQueryArgs query;
    std::vector<double> box;
    double min_force = 0.0;
    std::int32_t particle = -1;
    std::string csv;
    int limit = 20;
  };
  auto o = options_of<Options>();
  auto* contacts = app.add_subcommand("contacts", "query contacts: all, on a wall, in a box, above a force");
  auto* wall = contacts->add_option("--wall", o->query.wall, "contacts on this wall");
  auto* box =
      contacts->add_option("--box", o->box, "XMIN,YMIN,XMAX,YMAX: contact points inside")->delimiter(',')->expected(4);
  auto* force = contacts->add_option("--min-force", o->min_force, "N: contacts carrying more");
  auto* particle =
      contacts->add_option("--particle", o->particle, "the contacts of this particle (its id, kept through trims)");
  contacts->add_option("--csv", o->csv, "write every contact to this file");
  contacts->add_option("--limit", o->limit, "rows to print")->capture_default_str();
  contacts->callback([&, o, wall, box, force, particle] {
    dem::protocol::ContactQueryArgs& query = o->query;
    query.wall_set = wall->count() > 0;
    if (box->count() > 0) {
      query.box_set = true;
      query.box_min = {o->box[0], o->box[1], 0.0};
      query.box_max = {o->box[2], o->box[3], 0.0};
    }
    if (force->count() > 0) query.min_normal_force = o->min_force;
    if (particle->count() > 0) query.particle = o->particle;
    action = [&, o] { return demctl::contacts(global, o->query, o->csv, o->limit); };
  });
}

void add_snapshot_and_set(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    std::string file;
    bool on_server = false;
  };
  auto o = options_of<Options>();
  auto* snapshot = app.add_subcommand("snapshot", "save or load the whole state (protobuf) for exact restart");
  snapshot->require_subcommand(1);
  auto* save = snapshot->add_subcommand("save", "save to FILE here (or in the server's output directory)");
  save->add_option("FILE", o->file)->required();
  save->add_flag("--on-server", o->on_server, "FILE is relative to the server's output directory");
  save->callback([&, o] { action = [&, o] { return snapshot_save(global, o->file, o->on_server); }; });
  auto* restore = snapshot->add_subcommand("load", "load from FILE here (or in the server's output directory)");
  restore->add_option("FILE", o->file)->required();
  restore->add_flag("--on-server", o->on_server, "FILE is relative to the server's output directory");
  restore->callback([&, o] { action = [&, o] { return snapshot_load(global, o->file, o->on_server); }; });

  struct Parameter {
    std::string name;
    std::string value;
  };
  auto p = options_of<Parameter>();
  auto* set = app.add_subcommand("set",
                                 "set a parameter: contact_damping, global_damping, local_damping, "
                                 "time_step_fraction, friction.MATERIAL, gravity GX,GY[,GZ]");
  set->add_option("PARAM", p->name)->required();
  set->add_option("VALUE", p->value)->required();
  set->callback([&, p] { action = [&, p] { return demctl::set(global, p->name, p->value); }; });
}

void add_monitor(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    MonitorOptions monitor;
    std::uint64_t samples = 0;
  };
  auto o = options_of<Options>();
  auto* monitor = app.add_subcommand("monitor", "live table of plate stress, settlement and contact statistics");
  auto* samples = monitor->add_option("-n,--samples", o->samples, "stop after N rows (default: Ctrl-C)");
  monitor->add_option("--csv", o->monitor.csv, "record the rows in this file too");
  monitor->add_option("--wall", o->monitor.walls, "plates to show (default: every wall)");
  auto* sweep = monitor->add_option("--sweep", o->monitor.sweep,
                                    "follow every server of this sweep (named <sweep>_<task>) as they come "
                                    "and go, each row naming its server");
  monitor->add_flag("--all", o->monitor.all, "follow every server of the domain, as --sweep does")->excludes(sweep);
  monitor
      ->add_option("--idle-exit", o->monitor.idle_exit,
                   "with --sweep or --all: stop once none of those servers has been there for S seconds")
      ->check(CLI::PositiveNumber);
  monitor->callback([&, o, samples] {
    if (samples->count() > 0) o->monitor.samples = o->samples;
    action = [&, o] { return demctl::monitor(global, o->monitor); };
  });
}

void add_record(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    RecordOptions record;
    std::uint64_t samples = 0;
    double duration = 0.0;
  };
  auto o = options_of<Options>();
  auto* record = app.add_subcommand("record",
                                    "record the telemetry to an MCAP file (ros2msg schemas, CDR messages: "
                                    "a ROS 2 bag, for Foxglove and Python's dem.recording)");
  record->add_option("FILE", o->record.file, "the .mcap file to write")->required();
  auto* samples = record->add_option("-n,--samples", o->samples,
                                     "stop after N plate forces samples (default: Ctrl-C or the "
                                     "server stopping)");
  auto* duration =
      record->add_option("--duration", o->duration, "stop after this many seconds")->check(CLI::PositiveNumber);
  record->callback([&, o, samples, duration] {
    if (samples->count() > 0) o->record.samples = o->samples;
    if (duration->count() > 0) o->record.duration = o->duration;
    action = [&, o] { return demctl::record(global, o->record); };
  });
}

void add_shutdown(CLI::App& app, const Global& global, Action& action) {
  struct Options {
    bool no_wait = false;
    bool force = false;
  };
  auto o = options_of<Options>();
  auto* shutdown = app.add_subcommand("shutdown", "stop the server cleanly (waits until it has stopped)");
  shutdown->add_flag("--no-wait", o->no_wait, "return once the server accepted");
  shutdown->add_flag("--force", o->force, "also while another client's run is going on");
  shutdown->callback([&, o] { action = [&, o] { return demctl::shutdown(global, !o->no_wait, o->force); }; });
}

}  // namespace

void add_subcommands(CLI::App& app, const Global& global, Action& action) {
  add_servers(app, global, action);
  add_status_and_load(app, global, action);
  add_wall_controls(app, global, action);
  add_cycle(app, global, action);
  add_run_until(app, global, action);
  add_run_programme_and_stop(app, global, action);
  add_contacts(app, global, action);
  add_snapshot_and_set(app, global, action);
  add_monitor(app, global, action);
  add_record(app, global, action);
  add_shutdown(app, global, action);
}

}  // namespace demctl
