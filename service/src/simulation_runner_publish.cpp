// What the engine thread tells: the status (the topic, every reply and the
// StateCache's get_state), the telemetry topics and get_state's readout -
// built here and nowhere else, from one sample of the world.
#include "dem/service/simulation_runner.h"
#include "dem/service/world_view.h"

namespace dem::service {

using protocol::CommandKind;
using protocol::ReplyStatus;

// --- publishing ----------------------------------------------------------

void SimulationRunner::send(const ReceivedCommand& received, protocol::Reply reply) {
  reply.state = status();
  reply.state.commands_served = cache_.count_reply();
  replies_.send(received, std::move(reply));
}

protocol::Status SimulationRunner::status() const {
  protocol::Status s;
  s.server = options_.name;
  s.state = lifecycle_.state();
  s.message = message_;
  s.commands_served = cache_.served();
  s.telemetry_dropped = telemetry_.dropped();
  s.stamp = protocol::now_stamp();
  if (simulation_.loaded()) {
    const WorldSession& world = simulation_.world();
    s.case_name = simulation_.case_name();
    s.dimension = simulation_.dimension();
    s.particles = world.particle_count();
    s.walls = wall_count(world);
    s.cycle = world.cycle_count();
    s.time = world.time();
    s.time_step = world.time_step();
  }
  if (run_ && lifecycle_.running()) describe_run(s);
  return s;
}

// The run going on as the status shows it: the command that started it (a
// one-shot run's programme shows as a running command of no client), its
// cycles, and how far it is by its stages' own measures (the cap of a
// stage that ends on a stress would put its end at a few per cent).
void SimulationRunner::describe_run(protocol::Status& s) const {
  const ProgrammeRun& run = *run_;
  const WorldSession& world = simulation_.world();
  s.command = "programme";
  if (const ReceivedCommand* started = run.command()) {
    s.command = std::string(protocol::to_string(*protocol::command_kind(started->command.kind)));
    s.command_client = started->command.client_id;
    s.command_request_id = started->command.request_id;
  }
  s.command_cycles_done = run.done(world);
  s.command_cycles_total = run.total();  // every stage's length or cap: a bound, not a forecast
  if (!run.stage_running() || run.over()) {
    s.progress = run.progress(0.0);
    return;
  }
  const StageProgress stage = run.programme().progress(run.stage(), run.stage_cycles(world.cycle_count()), world);
  s.progress = run.progress(stage.fraction);
  if (run.of_case()) s.message = stage_label(run.stage()) + ": " + stage.text;
}

// A new state goes to the cache before the status topic: a client that
// sees a run start (or a case loaded) on the topic and then asks get_state
// is answered with that state, not the one before it.
void SimulationRunner::announce() {
  refresh_cache(true);
  publish_status();
}

void SimulationRunner::publish_status() {
  telemetry_.publish(status());
  last_status_ = std::chrono::steady_clock::now();
}

// The readout changes only with the world (a cycle, a load, a state put
// back): wall motions, servos and parameters show from the next cycle on.
// So it is worked out once per state, however many ask - get_state, the
// StateCache and the telemetry read the same one.
const SimulationRunner::Readout& SimulationRunner::readout() const {
  const WorldSession& world = simulation_.world();
  if (!readout_ || readout_->generation != world_generation_ || readout_->cycle != world.cycle_count()) {
    Readout readout{world_generation_, world.cycle_count(), {}, {}, std::nullopt};
    readout.plates.server = options_.name;
    readout.plates.cycle = world.cycle_count();
    readout.plates.time = world.time();
    readout.plates.walls = read_walls(world);
    readout.stats = read_contact_stats(world);
    readout.stats.server = options_.name;
    readout.stats.cycle = world.cycle_count();
    readout.stats.time = world.time();
    readout_ = std::move(readout);
  }
  return *readout_;
}

protocol::Reply SimulationRunner::get_state() const {
  protocol::Reply reply;
  if (simulation_.loaded()) {
    const Readout& now = readout();
    // The hash is get_state's alone (a pass over the whole state): not for the telemetry.
    if (!now.hash) readout_->hash = simulation_.world().state_hash();
    reply.plates = now.plates;
    reply.stats = now.stats;
    reply.plates.stamp = protocol::now_stamp();
    reply.stats.stamp = reply.plates.stamp;
    reply.state_hash = *now.hash;
  }
  reply.message = std::string(protocol::to_string(lifecycle_.state())) +
                  (simulation_.loaded() ? ", case " + simulation_.case_name() + " at cycle " +
                                              std::to_string(simulation_.world().cycle_count())
                                        : std::string());
  return reply;
}

// After a chunk of cycles or a batch of commands, at a pace that costs at
// most about 1/40 of the engine thread's time (get_state reads every
// contact and hashes the state: on a large world that is not free), or
// `always` when a run ends. Meanwhile the cache is a little older (the
// replies say which cycle), and a client whose command it does not show
// yet has its get_state answered by the engine thread.
void SimulationRunner::refresh_cache(bool always) {
  if (!always && !refresh_pacing_.due()) return;
  refresh_pacing_.run([this] {
    protocol::Reply reply = get_state();
    reply.state = status();
    cache_.publish(std::move(reply));
  });
  for (const std::string& client : awaiting_refresh_) queue_.done(client);
  awaiting_refresh_.clear();
}

void SimulationRunner::publish_telemetry(bool scheduled) {
  const WorldSession& world = simulation_.world();
  const Readout& now = readout();
  protocol::PlateForces plates = now.plates;
  protocol::ContactStats stats = now.stats;
  plates.stamp = protocol::now_stamp();
  stats.stamp = plates.stamp;
  telemetry_.publish(plates, stats);
  if (std::optional<protocol::RegionTelemetry> regions = world.read_regions()) {
    regions->server = options_.name;
    regions->cycle = plates.cycle;
    regions->time = plates.time;
    regions->stamp = plates.stamp;
    telemetry_.publish(*regions);
  }
  // The case's stages write their rows at the case's output interval instead.
  if (!run_ || !run_->of_case()) recorder_.record(world);
  if (scheduled) schedule_.published(world.cycle_count(), world.time());
  last_telemetry_cycle_ = world.cycle_count();
  telemetry_published_ = true;
}

}  // namespace dem::service
