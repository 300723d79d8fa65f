// Topics, writers and readers of one message type:
//   Topic<Status> topic(participant, "rt/dem/a/status");
//   Writer<Status> writer(participant, topic, qos);
//   writer.write(status);
#pragma once

#include <dds/dds.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/dds/entity.h"
#include "dem/dds/error.h"
#include "dem/dds/keyless_descriptor.h"
#include "dem/dds/participant.h"
#include "dem/dds/qos.h"
#include "dem/dds/type_information_guard.h"
#include "dem/dds/type_support.h"

namespace dem::dds {

// Whether a topic has its type's keys (a history per key value) or none:
// a keyless topic of a keyed type is for the peers that know the type
// without its keys - ROS 2 nodes (KeylessDescriptor) - and matches their
// endpoints alone.
enum class Keys { kDeclared, kNone };

template <SupportedType T>
class Topic {
 public:
  Topic(const Participant& participant, std::string name, Keys keys = Keys::kDeclared)
      : name_(std::move(name)), entity_(create(participant, keys)) {}

  dds_entity_t handle() const { return entity_.handle(); }
  const std::string& name() const { return name_; }

 private:
  dds_entity_t create(const Participant& participant, Keys keys) const {
    const dds_topic_descriptor_t& declared = *TypeSupport<T>::descriptor();
    protect_type_information(declared);
    // Cyclone copies what it needs of a descriptor into the topic's type.
    const auto create_with = [&](const dds_topic_descriptor_t& descriptor) {
      return check(dds_create_topic(participant.handle(), &descriptor, name_.c_str(), nullptr, nullptr),
                   "creating topic " + name_);
    };
    if (keys == Keys::kNone) return create_with(KeylessDescriptor(declared).get());
    return create_with(declared);
  }

  std::string name_;
  Entity entity_;
};

// Counts of the remote (and local) endpoints an endpoint is matched with.
std::uint32_t matched_readers(dds_entity_t writer);
std::uint32_t matched_writers(dds_entity_t reader);
// Whether a writer (by the publication handle its samples carry) is still
// matched with the reader: false once it was deleted, or its participant
// left or lost its lease.
bool writer_matched(dds_entity_t reader, dds_instance_handle_t writer);

// A sample's value, the writer it came from and its instance (its key's
// handle; one instance for a topic without keys).
template <class T>
struct Received {
  T value;
  dds_instance_handle_t writer = 0;
  dds_instance_handle_t instance = 0;
};

template <SupportedType T>
class Writer {
 public:
  Writer(const Participant& participant, const Topic<T>& topic, const Qos& qos)
      : topic_name_(topic.name()),
        entity_(check(dds_create_writer(participant.handle(), topic.handle(), endpoint_qos<T>(qos).get(), nullptr),
                      "creating a writer for " + topic_name_)) {}

  // False when the writer's history stayed full for the QoS's max blocking
  // time (a reader is not acknowledging): the sample is not sent. Any other
  // failure throws DdsError.
  bool write(const T& value) {
    const dds_return_t result = TypeSupport<T>::write(entity_.handle(), value);
    if (result == DDS_RETCODE_TIMEOUT) return false;
    check(result, "writing to " + topic_name_);
    return true;
  }

  // Waits until every matched reader acknowledged all samples written;
  // false when the timeout passed first.
  bool wait_for_acks(std::chrono::nanoseconds timeout) {
    const dds_return_t result = dds_wait_for_acks(entity_.handle(), to_duration(timeout));
    if (result == DDS_RETCODE_TIMEOUT) return false;
    check(result, "waiting for acknowledgements on " + topic_name_);
    return true;
  }

  std::uint32_t matched_readers() const { return dds::matched_readers(entity_.handle()); }
  dds_entity_t handle() const { return entity_.handle(); }
  const std::string& topic_name() const { return topic_name_; }

 private:
  std::string topic_name_;
  Entity entity_;
};

// The pointer buffer of a read or take that borrows Cyclone's samples.
// Cyclone 0.10.2 fills as many of its pointers as the largest loan the
// reader has ever had, whatever the call asks for (dds_read.c: "This
// ensures buf is properly initialized" - realloc_samples up to
// m_loan_size), so a buffer sized to a smaller request than an earlier
// one overflowed and corrupted the heap: dem_server died after some 140
// rounds of tests/service/discovery_probe, once discovery had grown past
// 256 endpoints and shrunk again (docs/RELIABILITY.md, "Discovery"). A
// reader's buffers therefore keep the largest size it ever asked for.
class LoanSlots {
 public:
  LoanSlots() = default;
  // Moved with its reader (which keeps its loans).
  LoanSlots(LoanSlots&& other) noexcept : largest_(other.largest_.load(std::memory_order_relaxed)) {}
  LoanSlots& operator=(LoanSlots&& other) noexcept {
    largest_.store(other.largest_.load(std::memory_order_relaxed), std::memory_order_relaxed);
    return *this;
  }

  // A buffer of null pointers (null: Cyclone lends its own samples) for a
  // call asking for `wanted` samples; pass its size() as the call's bufsz.
  std::vector<void*> buffer(std::size_t wanted) {
    std::size_t largest = largest_.load(std::memory_order_relaxed);
    while (wanted > largest && !largest_.compare_exchange_weak(largest, wanted, std::memory_order_relaxed)) {
    }
    return std::vector<void*>(std::max(largest, wanted), nullptr);
  }

 private:
  std::atomic<std::size_t> largest_{0};
};

// Returns a loan of received samples when it goes out of scope.
class Loan {
 public:
  Loan(dds_entity_t reader, std::vector<void*>& samples, std::int32_t count)
      : reader_(reader), samples_(samples), count_(count) {}
  ~Loan() {
    if (count_ > 0) dds_return_loan(reader_, samples_.data(), count_);
  }
  Loan(const Loan&) = delete;
  Loan& operator=(const Loan&) = delete;

 private:
  dds_entity_t reader_;
  std::vector<void*>& samples_;
  std::int32_t count_;
};

template <SupportedType T>
class Reader {
 public:
  Reader(const Participant& participant, const Topic<T>& topic, const Qos& qos)
      : topic_name_(topic.name()),
        entity_(check(dds_create_reader(participant.handle(), topic.handle(), endpoint_qos<T>(qos).get(), nullptr),
                      "creating a reader for " + topic_name_)) {}

  // Removes up to `max` samples from the reader's history and returns those
  // that carry data (not the notices that a writer went away), oldest first.
  std::vector<T> take(std::size_t max = 256) {
    std::vector<void*> samples = slots_.buffer(max);
    std::vector<dds_sample_info_t> infos(max);
    const auto count =
        check(dds_take(entity_.handle(), samples.data(), infos.data(), samples.size(), static_cast<std::uint32_t>(max)),
              "taking from " + topic_name_);
    Loan loan(entity_.handle(), samples, count);
    std::vector<T> values;
    values.reserve(static_cast<std::size_t>(count));
    for (std::int32_t i = 0; i < count; ++i) {
      if (infos[i].valid_data) values.push_back(TypeSupport<T>::from_sample(samples[i]));
    }
    return values;
  }

  // As take, with the writer and instance of each sample.
  std::vector<Received<T>> take_with_writers(std::size_t max = 256) {
    std::vector<void*> samples = slots_.buffer(max);
    std::vector<dds_sample_info_t> infos(max);
    const auto count =
        check(dds_take(entity_.handle(), samples.data(), infos.data(), samples.size(), static_cast<std::uint32_t>(max)),
              "taking from " + topic_name_);
    Loan loan(entity_.handle(), samples, count);
    std::vector<Received<T>> values;
    values.reserve(static_cast<std::size_t>(count));
    for (std::int32_t i = 0; i < count; ++i) {
      if (infos[i].valid_data) {
        values.push_back(
            {TypeSupport<T>::from_sample(samples[i]), infos[i].publication_handle, infos[i].instance_handle});
      }
    }
    return values;
  }
  bool writer_matched(dds_instance_handle_t writer) const { return dds::writer_matched(entity_.handle(), writer); }

  std::uint32_t matched_writers() const { return dds::matched_writers(entity_.handle()); }
  dds_entity_t handle() const { return entity_.handle(); }
  const std::string& topic_name() const { return topic_name_; }

 private:
  std::string topic_name_;
  Entity entity_;
  LoanSlots slots_;
};

}  // namespace dem::dds
