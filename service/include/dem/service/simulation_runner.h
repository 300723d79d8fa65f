// The engine thread: executes commands in arrival order between chunks of
// cycles, steps the world, and publishes telemetry and status. The only
// thread that touches the simulation; the reception thread hands it
// commands through the CommandQueue and nothing else.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dem/io/pacing.h"
#include "dem/protocol/messages.h"
#include "dem/service/background_load.h"
#include "dem/service/command_queue.h"
#include "dem/service/health_watch.h"
#include "dem/service/lifecycle.h"
#include "dem/service/options.h"
#include "dem/service/output_recorder.h"
#include "dem/service/programme_run.h"
#include "dem/service/reply_sender.h"
#include "dem/service/server_checkpoints.h"
#include "dem/service/simulation.h"
#include "dem/service/state_cache.h"
#include "dem/service/telemetry_publisher.h"
#include "dem/service/telemetry_schedule.h"

namespace dem::service {

class SimulationRunner {
 public:
  SimulationRunner(const ServerOptions& options, CommandQueue& queue, ReplySender& replies,
                   TelemetryPublisher& telemetry, StateCache& cache);

  // Loads the case given at start; throws CommandError when it cannot (and
  // when a one-shot run's case has no stages to run). With `resume`, the
  // world continues from the newest checkpoint of the case
  // (<output>/<case>/checkpoints) into its tables, a one-shot run from
  // where its programme stood; CommandError when there is none, or it is
  // another case's.
  void load_initial_case(const std::filesystem::path& path, bool resume = false);

  // Runs until a shutdown is requested (signal or command), then returns
  // between two chunks of cycles.
  void run();
  // The one-shot mode (ServerOptions::run_programme), instead of run(): runs
  // the loaded case's loading programme stage by stage, each a stage of
  // the engine's stepped chunk by chunk by the command loop, which answers
  // commands and publishes telemetry between chunks; writes its time
  // series at the case's output interval, then the final snapshot, or
  // after a failure the last good state. Returns when the programme is
  // over: completed, stopped (stop, shutdown, a signal) or failed.
  void run_programme();
  // How the server learns whether the client that started a run is still
  // on the domain (CommandReceiver::writer_alive).
  void set_writer_check(std::function<bool(std::uint64_t)> alive) { writer_alive_ = std::move(alive); }
  // How the one-shot run ended; nothing when the server ran commands instead.
  std::optional<ProgrammeOutcome> programme_outcome() const;
  // After run() (whose loop has ended a run going on: a cancelled reply)
  // and once no more commands arrive: answers every command still queued
  // (shutting down), publishes the final telemetry and status, writes the
  // end-of-run tables and waits briefly for subscribers to acknowledge.
  void finish();

 private:
  // The command loop: commands as they arrive, and between them a chunk
  // of the run going (a cycle, run_until or programme). run() serves until
  // a shutdown request, the one-shot mode until its programme is over; a
  // run going when the shutdown comes is stopped and ended first.
  void serve(bool until_run_ends);
  void serve_once(const std::function<void()>& take_waiting);
  bool run_going() const { return run_ && !run_->over(); }  // a cycle, run_until or programme
  void execute(ReceivedCommand received);
  // The command's reply, or nothing when it starts a run (replied to when the run ends).
  std::optional<protocol::Reply> dispatch(const ReceivedCommand& received, protocol::CommandKind kind);

  // Starting runs (simulation_runner_runs.cpp): a cycle or run_until is a
  // programme of one stage of its own, run_programme and the one-shot mode
  // run the case's; all are a ProgrammeRun that the one driver below steps.
  void start_command_run(const ReceivedCommand& received, protocol::CommandKind kind);
  void run_programme(const ReceivedCommand& received);
  // The case's stages first .. first + count - 1; `first_done`: cycles of
  // the first run already (a resumed checkpoint's).
  RunPlan case_plan(std::size_t first, std::size_t count, std::uint64_t first_done = 0) const;
  // `command`: the one that starts it (none in the one-shot mode), replied to when the run ends.
  void start(RunPlan plan, const ReceivedCommand* command, std::string message);
  // Cycles for the next chunk: about options_.chunk_duration at the
  // measured rate, no further than `limit` (the run's next stop) or the
  // next telemetry.
  std::uint64_t chunk_cycles(std::uint64_t limit) const;
  // Runs `run`, a chunk of `cycles`, and measures the rate.
  void timed(std::uint64_t cycles, const std::function<void()>& run);

  // The one driver (simulation_runner_stages.cpp): between the commands, a
  // chunk of the stage running (the next begun if none runs), its row,
  // telemetry, check and checkpoint, the stage's end; or the run's end.
  void step_run();
  void run_chunk();
  void pause_run();
  bool run_unhealthy(bool always);  // fails the run when the world's health says so
  void checkpoint_if_due();
  void record_row();
  void end_stage();
  std::string stage_label(std::size_t stage) const;
  std::string in_stage() const;  // " in stage 2/3 compress" for the case's stages, else nothing

  // The one end (simulation_runner_end.cpp): the last good snapshot after
  // a failure and the world put back at it, the case's final snapshot, the
  // state, the message, and the reply to the command that started the run.
  void end_run();
  std::string failure_message();
  std::string programme_end_message();
  std::string pause_message(const RunPosition& position) const;
  protocol::Reply run_reply(ProgrammeOutcome outcome, std::uint64_t cycles_run, const RunPosition& position) const;
  std::string command_end_message(std::uint64_t cycles_run) const;
  // Writes the snapshot `bytes` gives as `name` beside the case's tables:
  // nothing, or why it could not be written.
  std::optional<std::string> write_beside_tables(const std::string& name, const std::function<std::string()>& bytes);

  // `resume`: a checkpoint the prepared world was restored from; its tables carry on.
  std::string install(Simulation::Prepared prepared, const io::ResumePoint* resume = nullptr);
  // Runs `prepare` in a BackgroundLoad while taking stop and shutdown (and
  // keeping other commands for after); throws CommandError when it is
  // stopped, outlasts options_.load_time_limit, or an abandoned one is still running.
  Simulation::Prepared prepare_in_background(const std::string& what, BackgroundLoad::Prepare prepare);
  std::string stop();
  protocol::Reply get_state() const;
  protocol::Reply save_snapshot(const protocol::SnapshotArgs& args);
  std::string load_snapshot(const protocol::SnapshotArgs& args);
  std::filesystem::path snapshot_path(const std::string& requested) const;

  void send(const ReceivedCommand& received, protocol::Reply reply);
  // Why `received` (a stop or shutdown) may not end the run going on, or
  // nothing (docs/SERVICE.md, "Who may stop a run").
  std::optional<std::string> ownership_refusal(const ReceivedCommand& received) const;
  const ReceivedCommand* run_owner() const;
  void note_owner_left();
  protocol::Status status() const;
  void describe_run(protocol::Status& status) const;
  void announce();
  void publish_status();
  // `scheduled`: the schedule's sample, from which the next is counted; an
  // extra one (a stage's end) leaves the schedule's rhythm as it was.
  void publish_telemetry(bool scheduled = true);
  void refresh_cache(bool always = false);  // the StateCache's get_state, as of now
  void write_checkpoint(std::size_t stage, std::uint64_t stage_cycles);
  // Puts the world back at `good` (a failed run's last good state) and says
  // so; when that cannot be done (no memory to build it), the world is let
  // go - drop_lost_world, after the failure's transition, leaves the server
  // idle - and says that instead.
  std::string go_back_to(const StateCheckpoint& good);
  void drop_lost_world();
  // Whatever escapes the engine thread's work between commands (memory
  // running out in a chunk, its check, the telemetry, a readout) fails the
  // run going on, as an unhealthy state does: it never ends the server.
  void fail_anything_running(const std::exception& error);

  const ServerOptions& options_;
  CommandQueue& queue_;
  ReplySender& replies_;
  TelemetryPublisher& telemetry_;
  StateCache& cache_;
  Simulation simulation_;
  OutputRecorder recorder_;
  TelemetrySchedule schedule_;
  Lifecycle lifecycle_;
  std::unique_ptr<BackgroundLoad> abandoned_;  // a load given up on, still running to its end
  ServerCheckpoints checkpoints_;
  std::optional<io::ResumePoint> resumed_;  // the checkpoint --resume started from, until its programme runs
  // The run going on; the one-shot mode keeps its programme once over, for how it ended.
  std::optional<ProgrammeRun> run_;
  std::function<bool(std::uint64_t)> writer_alive_ = [](std::uint64_t) { return true; };
  bool owner_left_logged_ = false;
  std::vector<std::string> awaiting_refresh_;  // clients whose commands the StateCache does not show yet
  io::Pacing refresh_pacing_{40};              // at most 1/40 of the engine thread
  // The plates and contact statistics of one state of the world, named
  // (stamped when sent): get_state's and the telemetry's, worked out once
  // however many ask; the state hash only when get_state asks.
  struct Readout {
    std::uint64_t generation = 0;
    std::uint64_t cycle = 0;
    protocol::PlateForces plates;
    protocol::ContactStats stats;
    std::optional<std::uint64_t> hash;
  };
  const Readout& readout() const;
  mutable std::optional<Readout> readout_;
  std::uint64_t world_generation_ = 0;       // a new world, or one put back: another readout
  bool world_lost_ = false;                  // go_back_to could not put it back
  std::vector<ReceivedCommand> unanswered_;  // taken from the queue after a shutdown request
  std::string message_ = "started";
  std::uint64_t last_telemetry_cycle_ = 0;
  bool telemetry_published_ = false;
  // Chunks take about options_.chunk_duration at the measured rate.
  double cycles_per_second_ = 0.0;
  std::chrono::steady_clock::time_point last_status_{};
};

}  // namespace dem::service
