#include "dem/service/state_cache.h"

namespace dem::service {

void StateCache::publish(protocol::Reply get_state) {
  std::lock_guard lock(mutex_);
  get_state_ = std::move(get_state);
}

std::optional<protocol::Reply> StateCache::get_state() const {
  std::lock_guard lock(mutex_);
  return get_state_;
}

}  // namespace dem::service
