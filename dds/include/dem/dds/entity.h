// RAII ownership of one Cyclone DDS entity handle: deleted with its owner,
// movable, not copyable. Children must not outlive their parent (deleting
// a participant deletes what it created); the classes here keep that order
// by construction.
#pragma once

#include <dds/dds.h>

#include <utility>

namespace dem::dds {

class Entity {
 public:
  Entity() = default;
  explicit Entity(dds_entity_t handle) : handle_(handle) {}
  ~Entity() { reset(); }
  Entity(Entity&& other) noexcept : handle_(std::exchange(other.handle_, 0)) {}
  Entity& operator=(Entity&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, 0);
    }
    return *this;
  }
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;

  dds_entity_t handle() const { return handle_; }
  explicit operator bool() const { return handle_ > 0; }

  // Deletes the entity now. A failure here (the parent already deleted it)
  // leaves nothing to clean up, so it is not an error.
  void reset() {
    if (handle_ > 0) dds_delete(handle_);
    handle_ = 0;
  }

 private:
  dds_entity_t handle_ = 0;
};

}  // namespace dem::dds
