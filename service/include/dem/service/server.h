// One dem_server: the role objects composed around one DDS participant.
//
//   DDS reception thread   CommandReceiver  --CommandQueue-->  engine thread
//   engine thread          SimulationRunner -> ReplySender, TelemetryPublisher
//
// main.cpp (and the tests) build a Server, start it, and either wait for a
// shutdown command or request one (a signal).
#pragma once

#include <thread>

#include "dem/dds/participant.h"
#include "dem/protocol/interface_watch.h"
#include "dem/service/command_queue.h"
#include "dem/service/command_receiver.h"
#include "dem/service/name_claim.h"
#include "dem/service/options.h"
#include "dem/service/reply_sender.h"
#include "dem/service/simulation_runner.h"
#include "dem/service/state_cache.h"
#include "dem/service/telemetry_publisher.h"

namespace dem::service {

class Server {
 public:
  // Claims the name (name_claim.h), creates the DDS entities and loads the
  // initial case, if any; throws NameInUse when another server has the name,
  // CommandError for a bad case (or a one-shot case without stages),
  // dds::DdsError when DDS cannot start, and std::invalid_argument for a
  // server name that is not a ROS 2 name token or a one-shot run without a case.
  explicit Server(ServerOptions options);
  ~Server();  // requests a shutdown and waits for it
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  void start();
  // Thread-safe (a signal handler thread, a test): the engine thread
  // finishes its chunk of cycles, answers what is pending and stops.
  void request_shutdown();
  // Until the engine thread has finished (after a shutdown command or
  // request, or a one-shot run's programme).
  void wait();
  // After wait(): how a one-shot run's programme ended; nothing for a
  // server that ran commands.
  std::optional<ProgrammeOutcome> programme_outcome() const { return runner_.programme_outcome(); }

  const ServerOptions& options() const { return options_; }

 private:
  void engine_main();

  ServerOptions options_;
  CommandQueue queue_;
  StateCache cache_;
  dds::Participant participant_;
  // Peers whose interface does not meet the server's, logged when
  // discovery finds them (docs/DDS.md, "Evolving the wire").
  protocol::InterfaceWatch interface_watch_;
  NameClaim name_claim_;  // before anything is published under the name
  TelemetryPublisher telemetry_;
  ReplySender replies_;
  SimulationRunner runner_;
  CommandReceiver receiver_;
  std::thread engine_thread_;
};

}  // namespace dem::service
