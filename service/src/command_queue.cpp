#include "dem/service/command_queue.h"

namespace dem::service {

bool CommandQueue::push(ReceivedCommand command) {
  {
    std::lock_guard lock(mutex_);
    if (commands_.size() >= capacity_) return false;
    ++pending_[command.command.client_id];
    commands_.push_back(std::move(command));
  }
  ready_.notify_one();
  return true;
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
  std::vector<ReceivedCommand> all(std::make_move_iterator(commands_.begin()),
                                   std::make_move_iterator(commands_.end()));
  commands_.clear();
  return all;
}

void CommandQueue::put_back(std::vector<ReceivedCommand> commands) {
  {
    std::lock_guard lock(mutex_);
    commands_.insert(commands_.begin(), std::make_move_iterator(commands.begin()),
                     std::make_move_iterator(commands.end()));
  }
  ready_.notify_one();
}

void CommandQueue::done(const std::string& client) {
  std::lock_guard lock(mutex_);
  const auto found = pending_.find(client);
  if (found == pending_.end()) return;
  if (--found->second == 0) pending_.erase(found);
}

std::size_t CommandQueue::pending(const std::string& client) const {
  std::lock_guard lock(mutex_);
  const auto found = pending_.find(client);
  return found == pending_.end() ? 0 : found->second;
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
