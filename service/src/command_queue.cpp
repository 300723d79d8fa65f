#include "dem/service/command_queue.h"

namespace dem::service {

void CommandQueue::push(ReceivedCommand command) {
  {
    std::lock_guard lock(mutex_);
    commands_.push_back(std::move(command));
  }
  ready_.notify_one();
}

std::optional<ReceivedCommand> CommandQueue::pop(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return shutdown_ || !commands_.empty(); });
  if (shutdown_ || commands_.empty()) return std::nullopt;
  ReceivedCommand command = std::move(commands_.front());
  commands_.pop_front();
  return command;
}

std::vector<ReceivedCommand> CommandQueue::take_all() {
  std::lock_guard lock(mutex_);
  std::vector<ReceivedCommand> all(std::make_move_iterator(commands_.begin()), std::make_move_iterator(commands_.end()));
  commands_.clear();
  return all;
}

void CommandQueue::request_shutdown() {
  {
    std::lock_guard lock(mutex_);
    shutdown_ = true;
  }
  ready_.notify_all();
}

bool CommandQueue::shutdown_requested() const {
  std::lock_guard lock(mutex_);
  return shutdown_;
}

}  // namespace dem::service
