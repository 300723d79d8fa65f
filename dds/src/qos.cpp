#include "dem/dds/qos.h"

#include <new>
#include <utility>

namespace dem::dds {

dds_duration_t to_duration(std::chrono::nanoseconds duration) {
  if (duration == std::chrono::nanoseconds::max()) return DDS_INFINITY;
  return static_cast<dds_duration_t>(duration.count());
}

namespace {
dds_qos_t* create_qos() {
  dds_qos_t* qos = dds_create_qos();
  if (qos == nullptr) throw std::bad_alloc();
  return qos;
}
}  // namespace

Qos::Qos() : qos_(create_qos()) {}
Qos::~Qos() {
  if (qos_ != nullptr) dds_delete_qos(qos_);
}
Qos::Qos(const Qos& other) : qos_(create_qos()) { dds_copy_qos(qos_, other.qos_); }
Qos& Qos::operator=(const Qos& other) {
  if (this != &other) dds_copy_qos(qos_, other.qos_);
  return *this;
}
Qos::Qos(Qos&& other) noexcept : qos_(std::exchange(other.qos_, nullptr)) {}
Qos& Qos::operator=(Qos&& other) noexcept {
  std::swap(qos_, other.qos_);
  return *this;
}

Qos& Qos::reliable(std::chrono::nanoseconds max_blocking) {
  dds_qset_reliability(qos_, DDS_RELIABILITY_RELIABLE, to_duration(max_blocking));
  return *this;
}
Qos& Qos::best_effort() {
  dds_qset_reliability(qos_, DDS_RELIABILITY_BEST_EFFORT, 0);
  return *this;
}
Qos& Qos::keep_last(std::int32_t depth) {
  dds_qset_history(qos_, DDS_HISTORY_KEEP_LAST, depth);
  return *this;
}
Qos& Qos::keep_all() {
  dds_qset_history(qos_, DDS_HISTORY_KEEP_ALL, DDS_LENGTH_UNLIMITED);
  return *this;
}
Qos& Qos::volatile_durability() {
  dds_qset_durability(qos_, DDS_DURABILITY_VOLATILE);
  return *this;
}
Qos& Qos::transient_local(std::int32_t late_joiner_depth) {
  dds_qset_durability(qos_, DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_durability_service(qos_, 0, DDS_HISTORY_KEEP_LAST, late_joiner_depth, DDS_LENGTH_UNLIMITED,
                              DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
  return *this;
}
Qos& Qos::user_data(std::string_view data) {
  dds_qset_userdata(qos_, data.data(), data.size());
  return *this;
}

Qos& Qos::partitions(const std::vector<std::string>& names) {
  std::vector<const char*> pointers;
  pointers.reserve(names.size());
  for (const std::string& name : names) pointers.push_back(name.c_str());
  dds_qset_partition(qos_, static_cast<std::uint32_t>(pointers.size()), pointers.data());
  return *this;
}

Qos& Qos::resource_limits(std::int32_t max_samples, std::int32_t max_instances, std::int32_t max_samples_per_instance) {
  dds_qset_resource_limits(qos_, max_samples, max_instances, max_samples_per_instance);
  return *this;
}

}  // namespace dem::dds
