#include "dem/dds/topic.h"

#include <algorithm>
#include <vector>

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

bool writer_matched(dds_entity_t reader, dds_instance_handle_t writer) {
  std::vector<dds_instance_handle_t> handles(64);
  for (;;) {
    const dds_return_t count =
        check(dds_get_matched_publications(reader, handles.data(), handles.size()), "listing a reader's writers");
    if (static_cast<std::size_t>(count) <= handles.size()) {
      return std::find(handles.begin(), handles.begin() + count, writer) != handles.begin() + count;
    }
    handles.resize(static_cast<std::size_t>(count));
  }
}

}  // namespace dem::dds
