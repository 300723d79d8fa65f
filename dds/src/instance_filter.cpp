#include "dem/dds/instance_filter.h"

#include "dem/dds/error.h"

namespace dem::dds {

namespace {

bool accepts_sample(const dds_sample_info_t* info, void* filter) {
  return static_cast<const OwnInstanceFilter*>(filter)->accepts(info->publication_handle, info->instance_handle);
}

}  // namespace

OwnInstanceFilter::OwnInstanceFilter(dds_entity_t topic) : topic_(topic) {
  // Cyclone hands `this` to the thread that delivers samples (in-process,
  // a writer's) through its own locks, which a ThreadSanitizer build does
  // not see: this release, read by accepts' acquire, is the hand-over the
  // checker (and a reader of the code) can see.
  published_.store(true, std::memory_order_release);
  // Sample-info filters are judged before a sample is decoded (Cyclone
  // 0.10.2, dds_rhc_default.c content_filter_accepts); a sample filter
  // would decode every other client's reply to turn it away.
  dds_topic_filter filter{};
  filter.mode = DDS_TOPIC_FILTER_SAMPLEINFO_ARG;
  filter.f.sampleinfo_arg = &accepts_sample;
  filter.arg = this;
  check(dds_set_topic_filter_extended(topic, &filter), "setting a topic's instance filter");
}

OwnInstanceFilter::~OwnInstanceFilter() {
  // Taken off the topic first (its readers are gone by now), then the mutex
  // taken once: the last accepts, run on Cyclone's delivering thread, has
  // ended before the object does, and is seen to (as in the constructor).
  dds_topic_filter none{};
  none.mode = DDS_TOPIC_FILTER_NONE;
  (void)dds_set_topic_filter_extended(topic_, &none);
  std::lock_guard lock(mutex_);
}

void OwnInstanceFilter::learn(dds_instance_handle_t writer, dds_instance_handle_t instance) {
  std::lock_guard lock(mutex_);
  own_[writer] = instance;
}

bool OwnInstanceFilter::accepts(dds_instance_handle_t writer, dds_instance_handle_t instance) const {
  (void)published_.load(std::memory_order_acquire);
  std::lock_guard lock(mutex_);
  const auto found = own_.find(writer);
  return found == own_.end() || found->second == instance;
}

}  // namespace dem::dds
