#include "dem/service/background_load.h"

#include <atomic>

namespace dem::service {

namespace {
std::atomic<int> g_running{0};
}  // namespace

int BackgroundLoad::running() { return g_running.load(); }

void BackgroundLoad::detach() {
  if (thread_.joinable()) thread_.detach();
}

BackgroundLoad::BackgroundLoad(Prepare prepare) : shared_(std::make_shared<Shared>()) {
  ++g_running;
  thread_ = std::thread([shared = shared_, prepare = std::move(prepare)] {
    std::optional<Simulation::Prepared> result;
    std::exception_ptr error;
    try {
      result.emplace(prepare([shared] { return shared->stopped.load(std::memory_order_relaxed); }));
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard lock(shared->mutex);
    shared->result = std::move(result);
    shared->error = error;
    shared->done = true;
    shared->ended.notify_all();
    --g_running;
  });
}

BackgroundLoad::~BackgroundLoad() {
  if (thread_.joinable()) thread_.join();
}

void BackgroundLoad::stop() { shared_->stopped = true; }

bool BackgroundLoad::wait_for(std::chrono::milliseconds timeout) {
  std::unique_lock lock(shared_->mutex);
  return shared_->ended.wait_for(lock, timeout, [this] { return shared_->done; });
}

bool BackgroundLoad::finished() const {
  std::lock_guard lock(shared_->mutex);
  return shared_->done;
}

Simulation::Prepared BackgroundLoad::take() {
  thread_.join();
  std::lock_guard lock(shared_->mutex);
  if (shared_->error) std::rethrow_exception(shared_->error);
  return std::move(*shared_->result);
}

}  // namespace dem::service
