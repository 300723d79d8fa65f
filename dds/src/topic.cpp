#include "dem/dds/topic.h"

namespace dem::dds {

std::uint32_t matched_readers(dds_entity_t writer) {
  dds_publication_matched_status_t status{};
  check(dds_get_publication_matched_status(writer, &status), "reading a writer's matched status");
  return status.current_count;
}

std::uint32_t matched_writers(dds_entity_t reader) {
  dds_subscription_matched_status_t status{};
  check(dds_get_subscription_matched_status(reader, &status), "reading a reader's matched status");
  return status.current_count;
}

}  // namespace dem::dds
