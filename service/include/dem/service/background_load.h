// Preparing a case or a snapshot - parsing, validation, packing generation,
// building the world - on a thread of its own, so the engine thread keeps
// answering while it runs: get_state as always, stop (which abandons the
// load) and shutdown at once; other commands wait their turn, in order. A
// load that outlasts its time limit is abandoned too. An abandoned
// preparation is told to stop: a random packing ends at its next question
// (every few thousand attempts); parsing and building the world are not
// interrupted but bounded by the resource limits. Its result is dropped;
// until its thread has ended, another load is answered busy
// (docs/RELIABILITY.md).
#pragma once

#include <atomic>
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
  // Given what to ask whether the load was abandoned (stop()).
  using Prepare = std::function<Simulation::Prepared(std::function<bool()> stopped)>;

  explicit BackgroundLoad(Prepare prepare);
  ~BackgroundLoad();  // joins the thread unless detached
  // Lets the thread run to its end unwatched (it holds only copies of
  // what it needs). A process ending with one running must _Exit
  // (running() says so): static destructors would race it.
  void detach();
  static int running();
  BackgroundLoad(const BackgroundLoad&) = delete;
  BackgroundLoad& operator=(const BackgroundLoad&) = delete;

  // Tells the preparation to end (it was abandoned).
  void stop();

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
    std::atomic<bool> stopped{false};
  };
  std::shared_ptr<Shared> shared_;
  std::thread thread_;
};

}  // namespace dem::service
