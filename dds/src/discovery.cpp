#include "dem/dds/discovery.h"

#include <dds/dds.h>

#include <algorithm>

#include "dem/dds/error.h"
#include "dem/dds/topic.h"

namespace dem::dds {

namespace {
Guid to_guid(const dds_guid_t& guid) {
  Guid bytes{};
  std::copy(std::begin(guid.v), std::end(guid.v), bytes.begin());
  return bytes;
}
}  // namespace

Guid guid_of(const Participant& participant) {
  dds_guid_t guid;
  check(dds_get_guid(participant.handle(), &guid), "reading a participant's GUID");
  return to_guid(guid);
}

PublicationMonitor::PublicationMonitor(const Participant& participant)
    : entity_(check(dds_create_reader(participant.handle(), DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr),
                    "creating a reader for DCPSPublication")) {}

std::vector<Publication> PublicationMonitor::alive() const {
  // read (not take): the built-in reader keeps one sample per writer, and
  // an instance leaves the alive state when its writer goes away.
  for (std::size_t capacity = 256;; capacity *= 4) {
    std::vector<void*> samples(capacity, nullptr);
    std::vector<dds_sample_info_t> infos(capacity);
    const auto count = check(
        dds_read_mask(entity_.handle(), samples.data(), infos.data(), capacity, static_cast<std::uint32_t>(capacity),
                      DDS_ANY_SAMPLE_STATE | DDS_ANY_VIEW_STATE | DDS_ALIVE_INSTANCE_STATE),
        "reading DCPSPublication");
    Loan loan(entity_.handle(), samples, count);
    if (static_cast<std::size_t>(count) == capacity) continue;  // there may be more: read again with room
    std::vector<Publication> publications;
    for (std::int32_t i = 0; i < count; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* endpoint = static_cast<const dds_builtintopic_endpoint_t*>(samples[i]);
      publications.push_back({endpoint->topic_name ? endpoint->topic_name : "",
                              endpoint->type_name ? endpoint->type_name : "", to_guid(endpoint->participant_key)});
    }
    return publications;
  }
}

}  // namespace dem::dds
