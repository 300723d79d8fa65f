#include "dem/dds/waitset.h"

#include "dem/dds/error.h"
#include "dem/dds/qos.h"

namespace dem::dds {

GuardCondition::GuardCondition(const Participant& participant)
    : entity_(check(dds_create_guardcondition(participant.handle()), "creating a guard condition")) {}

void GuardCondition::trigger() {
  check(dds_set_guardcondition(entity_.handle(), true), "triggering a guard condition");
}
void GuardCondition::reset() { check(dds_set_guardcondition(entity_.handle(), false), "resetting a guard condition"); }
bool GuardCondition::triggered() const {
  bool value = false;
  check(dds_read_guardcondition(entity_.handle(), &value), "reading a guard condition");
  return value;
}

ReadCondition::ReadCondition(dds_entity_t reader)
    : entity_(check(dds_create_readcondition(reader, DDS_ANY_STATE), "creating a read condition")) {}

WaitSet::WaitSet(const Participant& participant)
    : entity_(check(dds_create_waitset(participant.handle()), "creating a wait set")) {}

void WaitSet::attach(dds_entity_t condition, std::intptr_t token) {
  check(dds_waitset_attach(entity_.handle(), condition, static_cast<dds_attach_t>(token)),
        "attaching a condition to a wait set");
  ++attached_;
}

std::vector<std::intptr_t> WaitSet::wait(std::chrono::nanoseconds timeout) {
  std::vector<dds_attach_t> triggered(attached_ == 0 ? 1 : attached_);
  const auto count = check(dds_waitset_wait(entity_.handle(), triggered.data(), triggered.size(), to_duration(timeout)),
                           "waiting on a wait set");
  std::vector<std::intptr_t> tokens;
  for (std::int32_t i = 0; i < count && static_cast<std::size_t>(i) < triggered.size(); ++i) {
    tokens.push_back(static_cast<std::intptr_t>(triggered[static_cast<std::size_t>(i)]));
  }
  return tokens;
}

}  // namespace dem::dds
