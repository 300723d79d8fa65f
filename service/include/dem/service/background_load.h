// Preparing a case or a snapshot - parsing, validation, packing generation,
// building the world - on a thread of its own, so the engine thread keeps
// answering while it runs: get_state as always, stop (which abandons the
// load) and shutdown at once; other commands wait their turn, in order. A
// load that outlasts its time limit is abandoned too. An abandoned
// preparation cannot be interrupted (the engine's generators take no
// cancellation), so its thread runs to its end - bounded by the resource
// limits - and its result is dropped; until it has ended, another load is
// answered busy (docs/RELIABILITY.md).
#pragma once

#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "dem/service/simulation.h"

namespace dem::service {

class BackgroundLoad {
 public:
  using Prepare = std::function<Simulation::Prepared()>;

  explicit BackgroundLoad(Prepare prepare);
  ~BackgroundLoad();  // joins the thread unless detached
  // Lets the thread run to its end unwatched (it holds only copies of
  // what it needs). A process ending with one running must _Exit
  // (running() says so): static destructors would race it.
  void detach();
  static int running();
  BackgroundLoad(const BackgroundLoad&) = delete;
  BackgroundLoad& operator=(const BackgroundLoad&) = delete;

  // Waits up to `timeout` for the preparation; true when it has ended.
  bool wait_for(std::chrono::milliseconds timeout);
  bool finished() const;
  // Once finished: the prepared world, or the preparation's exception rethrown.
  Simulation::Prepared take();

 private:
  struct Shared {
    std::mutex mutex;
    std::condition_variable ended;
    bool done = false;
    std::optional<Simulation::Prepared> result;
    std::exception_ptr error;
  };
  std::shared_ptr<Shared> shared_;
  std::thread thread_;
};

}  // namespace dem::service
