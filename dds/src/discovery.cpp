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

EndpointMonitor::EndpointMonitor(const Participant& participant, Kind kind)
    : kind_(kind),
      entity_(check(dds_create_reader(
                        participant.handle(),
                        kind == Kind::kWriters ? DDS_BUILTIN_TOPIC_DCPSPUBLICATION : DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION,
                        nullptr, nullptr),
                    kind == Kind::kWriters ? "creating a reader for DCPSPublication"
                                           : "creating a reader for DCPSSubscription")) {}

std::vector<Endpoint> EndpointMonitor::alive() const {
  // read (not take): the built-in reader keeps one sample per endpoint, and
  // an instance leaves the alive state when its endpoint goes away.
  for (std::size_t capacity = 256;; capacity *= 4) {
    std::vector<void*> samples = slots_.buffer(capacity);  // (topic.h, LoanSlots)
    std::vector<dds_sample_info_t> infos(capacity);
    const auto count = check(dds_read_mask(entity_.handle(), samples.data(), infos.data(), samples.size(),
                                           static_cast<std::uint32_t>(capacity),
                                           DDS_ANY_SAMPLE_STATE | DDS_ANY_VIEW_STATE | DDS_ALIVE_INSTANCE_STATE),
                             "reading discovery's endpoints");
    Loan loan(entity_.handle(), samples, count);
    if (static_cast<std::size_t>(count) == capacity) continue;  // there may be more: read again with room
    std::vector<Endpoint> endpoints;
    for (std::int32_t i = 0; i < count; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* endpoint = static_cast<const dds_builtintopic_endpoint_t*>(samples[i]);
      Endpoint e{endpoint->topic_name ? endpoint->topic_name : "", endpoint->type_name ? endpoint->type_name : "",
                 to_guid(endpoint->participant_key), "", kind_ == Kind::kWriters};
      void* data = nullptr;
      std::size_t size = 0;
      if (endpoint->qos && dds_qget_userdata(endpoint->qos, &data, &size) && data != nullptr) {
        e.user_data.assign(static_cast<const char*>(data), size);
        dds_free(data);
      }
      endpoints.push_back(std::move(e));
    }
    return endpoints;
  }
}

}  // namespace dem::dds
