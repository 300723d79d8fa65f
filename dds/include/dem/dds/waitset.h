// Waiting for several things at once: a wait set over read conditions (a
// reader has samples) and guard conditions (another thread asks to wake up).
//   WaitSet waitset(participant);
//   ReadCondition data(reader.handle());   GuardCondition stop(participant);
//   waitset.attach(data, 1);  waitset.attach(stop, 2);
//   for (auto token : waitset.wait(100ms)) ...
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <vector>

#include "dem/dds/entity.h"
#include "dem/dds/participant.h"

namespace dem::dds {

class GuardCondition {
 public:
  explicit GuardCondition(const Participant& participant);
  void trigger();  // thread-safe: wakes a wait() this condition is attached to
  void reset();
  bool triggered() const;
  dds_entity_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

// Triggered while the reader holds samples in any state (the reader's
// owner takes them all).
class ReadCondition {
 public:
  explicit ReadCondition(dds_entity_t reader);
  dds_entity_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

class WaitSet {
 public:
  explicit WaitSet(const Participant& participant);
  void attach(const GuardCondition& condition, std::intptr_t token) { attach(condition.handle(), token); }
  void attach(const ReadCondition& condition, std::intptr_t token) { attach(condition.handle(), token); }
  // The tokens of the conditions that are triggered; empty after the timeout.
  std::vector<std::intptr_t> wait(std::chrono::nanoseconds timeout);
  dds_entity_t handle() const { return entity_.handle(); }

 private:
  void attach(dds_entity_t condition, std::intptr_t token);
  Entity entity_;
  std::size_t attached_ = 0;
};

}  // namespace dem::dds
