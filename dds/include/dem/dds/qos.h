// Quality-of-service policies, built fluently and owned (RAII over
// dds_qos_t):  Qos().reliable(1s).keep_all().transient_local()
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace dem::dds {

// A DDS duration from a std::chrono one; nanoseconds::max() is infinity.
dds_duration_t to_duration(std::chrono::nanoseconds duration);

class Qos {
 public:
  Qos();
  ~Qos();
  Qos(const Qos& other);
  Qos& operator=(const Qos& other);
  Qos(Qos&& other) noexcept;
  Qos& operator=(Qos&& other) noexcept;

  // Reliable delivery; a write waits at most max_blocking for room in the
  // writer's history (then reports a timeout) - 0 never waits.
  Qos& reliable(std::chrono::nanoseconds max_blocking);
  Qos& best_effort();
  Qos& keep_last(std::int32_t depth);
  Qos& keep_all();
  Qos& volatile_durability();
  // A writer keeps its last `late_joiner_depth` samples for readers that
  // join later (which ask for transient-local too). Cyclone keeps for them
  // the durability service's history, not the writer's own - one sample
  // unless said: this sets both.
  Qos& transient_local(std::int32_t late_joiner_depth = 1);
  Qos& resource_limits(std::int32_t max_samples, std::int32_t max_instances, std::int32_t max_samples_per_instance);
  // USER_DATA: bytes discovery hands to every peer with the endpoint (ROS 2
  // puts its type hash there, "typehash=RIHS01_...;").
  Qos& user_data(std::string_view data);
  // The partitions of the endpoint's implicit publisher or subscriber: a
  // reader and a writer match only when they share one ("" is the default
  // partition, where every endpoint is unless told).
  Qos& partitions(const std::vector<std::string>& names);

  const dds_qos_t* get() const { return qos_; }

 private:
  dds_qos_t* qos_;
};

}  // namespace dem::dds
