// The engine thread's runs started: a cycle or run_until command as a
// programme of one stage of its own, a run_programme command or the
// one-shot mode with the case's stages - all one ProgrammeRun, stepped by
// the one driver (simulation_runner_stages.cpp) and ended by the one end
// (simulation_runner_end.cpp); who may stop them; the chunks' size and the
// periodic checkpoints.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "dem/service/command_error.h"
#include "dem/service/simulation_runner.h"

namespace dem::service {

using protocol::CommandKind;
using protocol::ReplyStatus;

namespace {

constexpr std::uint64_t kMaxChunk = 1'000'000;

// run_until's conditions as the engine's stop rule (dem/programme.h): all
// that are set, at once, checked every check_interval cycles.
StopConditions run_until_conditions(const protocol::RunUntilArgs& until, const Simulation& simulation) {
  require_argument(until.max_cycles > 0,
                   "run_until needs a maximum cycle count > 0, got " + std::to_string(until.max_cycles));
  require_argument(until.check_interval >= 0, "the check interval must be >= 0");
  require_argument(until.stress || until.settlement || until.kinetic_energy,
                   "run_until needs a condition: a plate's stress or settlement, or the kinetic energy");
  for (const auto& value : {until.stress, until.settlement, until.kinetic_energy}) {
    require_argument(!value || std::isfinite(*value), "run_until's thresholds must be finite");
  }
  StopConditions conditions;
  if (until.stress || until.settlement) {
    const WallId wall = simulation.find_wall(until.wall, until.wall_id);
    if (until.stress) conditions.wall_stress_above = WallThreshold{wall, *until.stress};
    if (until.settlement) conditions.wall_settlement_above = WallThreshold{wall, *until.settlement};
  }
  conditions.kinetic_energy_below = until.kinetic_energy;
  conditions.check_interval = until.check_interval > 0 ? static_cast<std::uint64_t>(until.check_interval) : 1;
  return conditions;
}

std::string stage_named(const CaseProgramme& programme, std::size_t stage) {
  const std::string& name = programme.stage_name(stage);
  return "stage " + std::to_string(stage + 1) + (name.empty() ? std::string() : " (\"" + name + "\")");
}

// run_programme in steps: a run resumes, and returns to sample, only where
// the stages go on as if never interrupted - before a stage's end, and in a
// stage with stop conditions on one of its checks (counted from its start).
void check_steps(const protocol::ProgrammeStepsArgs& steps, const CaseProgramme& programme, std::size_t first,
                 std::size_t count) {
  const auto check_interval = [&](std::size_t stage) -> std::uint64_t {
    const StopConditions& until = programme.stage_until(stage);
    return has_stop_condition(until) ? std::max<std::uint64_t>(until.check_interval, 1) : 1;
  };
  const std::uint64_t done = steps.stage_cycles_done;
  require_argument(steps.resume || done == 0, "stage_cycles_done is for a resumed run: set resume");
  require_argument(done == 0 || done < programme.stage_cycles(first),
                   stage_named(programme, first) + " runs at most " + std::to_string(programme.stage_cycles(first)) +
                       " cycles: it cannot be resumed after " + std::to_string(done));
  require_argument(done % check_interval(first) == 0,
                   stage_named(programme, first) + " resumes only on one of its condition checks, every " +
                       std::to_string(check_interval(first)) + " cycles, not after " + std::to_string(done));
  if (steps.sample_every == 0) return;
  for (std::size_t stage = first; stage < first + count; ++stage) {
    require_argument(steps.sample_every % check_interval(stage) == 0,
                     "sample_every " + std::to_string(steps.sample_every) + " is not a multiple of " +
                         stage_named(programme, stage) + "'s condition check interval, " +
                         std::to_string(check_interval(stage)) + " cycles: a run returns only where it resumes");
  }
}

}  // namespace

// --- starting runs -----------------------------------------------------------

void SimulationRunner::start_command_run(const ReceivedCommand& received, CommandKind kind) {
  const protocol::Command& command = received.command;
  std::uint64_t cycles = 0;
  StopConditions until;
  if (kind == CommandKind::kCycle) {
    require_argument(command.cycle.cycles > 0,
                     "the cycle count must be > 0, got " + std::to_string(command.cycle.cycles));
    cycles = static_cast<std::uint64_t>(command.cycle.cycles);
  } else {
    until = run_until_conditions(command.run_until, simulation_);
    cycles = static_cast<std::uint64_t>(command.run_until.max_cycles);
  }
  spdlog::info("request {} from {}: {} accepted, up to {} cycles from cycle {}", command.request_id, command.client_id,
               protocol::to_string(kind), cycles, simulation_.world().cycle_count());
  RunPlan plan{.programme = CaseProgramme::one_stage(simulation_.dimension(), cycles, until)};
  start(std::move(plan), &received, std::string(protocol::to_string(kind)) + " running");
}

void SimulationRunner::run_programme() {
  const std::size_t stages = simulation_.programme().stage_count();  // the initial case: Server requires one
  if (const std::optional<io::ResumePoint> point = std::exchange(resumed_, std::nullopt)) {
    if (point->stage >= stages) return;
    start(case_plan(point->stage, stages - point->stage, point->stage_cycles), nullptr,
          "programme of " + std::to_string(stages - point->stage) + " stages running");
  } else {
    start(case_plan(0, stages), nullptr, "programme of " + std::to_string(stages) + " stages running");
    record_row();  // the series start where the programme does, as dem_run's
  }
  serve(true);
}

void SimulationRunner::run_programme(const ReceivedCommand& received) {
  const protocol::ProgrammeArgs& args = received.command.programme;
  const std::size_t stages = simulation_.programme().stage_count();
  if (stages == 0) {
    throw CommandError(ReplyStatus::kRefused, "run_programme refused: " + simulation_.case_name() +
                                                  " has no stages (a snapshot keeps none; load the case)");
  }
  const std::size_t first = args.first_stage == 0 ? 0 : args.first_stage - 1;
  if (first >= stages) {
    throw CommandError(ReplyStatus::kBadRequest, "first_stage " + std::to_string(args.first_stage) + " is past the " +
                                                     std::to_string(stages) + " stages of " + simulation_.case_name());
  }
  if (args.stage_count > stages - first) {
    throw CommandError(ReplyStatus::kBadRequest, std::to_string(args.stage_count) + " stages from stage " +
                                                     std::to_string(first + 1) + " go past the " +
                                                     std::to_string(stages) + " of " + simulation_.case_name());
  }
  const std::size_t count = args.stage_count == 0 ? stages - first : args.stage_count;
  const protocol::ProgrammeStepsArgs& steps = received.command.programme_steps;
  check_steps(steps, simulation_.programme(), first, count);
  RunPlan plan = case_plan(first, count, steps.resume ? steps.stage_cycles_done : 0);
  plan.sample_every = steps.sample_every;
  plan.stage_ends = steps.stage_ends;
  start(std::move(plan), &received, "programme of " + std::to_string(count) + " stages running");
  if (!steps.resume) record_row();  // a resumed run's series has its rows up to here
}

RunPlan SimulationRunner::case_plan(std::size_t first, std::size_t count, std::uint64_t first_done) const {
  return RunPlan{.programme = simulation_.programme(),
                 .first = first,
                 .count = count,
                 .first_done = first_done,
                 .of_case = true,
                 .output_interval = simulation_.output_interval()};
}

void SimulationRunner::start(RunPlan plan, const ReceivedCommand* command, std::string message) {
  // The first good state is a whole copy of the world, taken first: a copy
  // that memory cannot hold fails the command with nothing started (and
  // the command kept, for its failed reply).
  const std::size_t first = plan.first;
  const std::size_t count = plan.count;
  run_.emplace(std::move(plan), simulation_.world(), command ? std::optional(*command) : std::nullopt);
  if (run_->of_case()) {
    checkpoints_.begin_programme(simulation_.world().cycle_count());
    spdlog::info("running the programme of {}: stages {} to {}, up to {} cycles", simulation_.case_name(), first + 1,
                 first + count, run_->total());
  }
  owner_left_logged_ = false;
  lifecycle_.take(Transition::kStartRun);
  message_ = std::move(message);
  announce();
}

// The run ends at the next turn of the loop, where it is when that is a good state.
std::string SimulationRunner::stop() {
  if (!run_going() || run_->outcome() != ProgrammeOutcome::kRunning) return "nothing was running";
  run_->stop("stopped by request");
  const std::string at = " at cycle " + std::to_string(simulation_.world().cycle_count());
  if (run_->of_case()) return "stopping the programme" + at + " in " + stage_label(run_->stage());
  const std::string what = std::string(protocol::to_string(*protocol::command_kind(run_->command()->command.kind)));
  return "stopped " + what + at + " after " + std::to_string(run_->done(simulation_.world())) + " cycles";
}

// --- who may stop a run ----------------------------------------------------

const ReceivedCommand* SimulationRunner::run_owner() const {
  return run_going() ? run_->command() : nullptr;  // a one-shot programme has none: the server's own
}

// A run belongs to the client (the DDS writer) that started it. Another
// may stop it, or shut the server down under it, only with force, or once
// the owner has left the domain (then the run is orphaned: it goes on, and
// anyone may end it). Who may send commands at all is DDS Security's to
// say (its permissions), not this.
std::optional<std::string> SimulationRunner::ownership_refusal(const ReceivedCommand& received) const {
  const ReceivedCommand* owner = run_owner();
  if (owner == nullptr || owner->writer == 0 || received.writer == owner->writer) return std::nullopt;
  const std::string run = std::string(protocol::to_string(*protocol::command_kind(owner->command.kind))) +
                          " (request " + std::to_string(owner->command.request_id) + ") of client " +
                          owner->command.client_id;
  if (received.command.force) {
    spdlog::warn("{} ends the {} with force", received.command.client_id, run);
    return std::nullopt;
  }
  if (!writer_alive_(owner->writer)) {
    spdlog::info("{} ends the {}, whose client has left", received.command.client_id, run);
    return std::nullopt;
  }
  return "the running " + run +
         " belongs to that client, which is still here; send it with force to end it anyway "
         "(demctl stop --force)";
}

// Once per run, between chunks: said in the log and the status.
void SimulationRunner::note_owner_left() {
  const ReceivedCommand* owner = run_owner();
  if (owner_left_logged_ || owner == nullptr || owner->writer == 0 || writer_alive_(owner->writer)) return;
  owner_left_logged_ = true;
  spdlog::warn(
      "client {}, which started the running {}, has left the domain: the run goes on, and any client may "
      "stop it",
      owner->command.client_id, protocol::to_string(*protocol::command_kind(owner->command.kind)));
  message_ += "; its client has left";
}

// --- chunks and checkpoints ------------------------------------------------

std::uint64_t SimulationRunner::chunk_cycles(std::uint64_t limit) const {
  const WorldSession& world = simulation_.world();
  const auto target = std::chrono::duration<double>(options_.chunk_duration).count();
  const auto by_rate = cycles_per_second_ > 0.0 ? static_cast<std::uint64_t>(cycles_per_second_ * target) : 1;
  return std::clamp<std::uint64_t>(
      std::min({by_rate, limit, schedule_.cycles_until_due(world.cycle_count(), world.time(), world.time_step())}), 1,
      kMaxChunk);
}

void SimulationRunner::timed(std::uint64_t cycles, const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (seconds > 0.0) {
    const double rate = static_cast<double>(cycles) / seconds;
    cycles_per_second_ = cycles_per_second_ > 0.0 ? 0.5 * (cycles_per_second_ + rate) : rate;
  }
}

void SimulationRunner::write_checkpoint(std::size_t stage, std::uint64_t stage_cycles) {
  try {
    checkpoints_.write(simulation_.world(), simulation_.snapshot_info(), recorder_, stage, stage_cycles);
  } catch (const std::exception& error) {
    // A checkpoint is insurance: its failure is said, the run goes on.
    spdlog::error("the checkpoint at cycle {} could not be written: {}", simulation_.world().cycle_count(),
                  error.what());
  }
}

}  // namespace dem::service
