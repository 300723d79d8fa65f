// A reader that takes samples as the bytes on the wire: the CDR
// serialization with its 4-byte encapsulation header, which ROS 2 bags and
// Foxglove carry as "cdr" messages - taken without converting them to C or
// C++ values, as rmw_cyclonedds hands out serialized messages.
//   SerializedReader reader(participant, topic, qos);
//   for (const SerializedSample& sample : reader.take()) file.write(sample.bytes);
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <string>
#include <vector>

#include "dem/dds/entity.h"
#include "dem/dds/error.h"
#include "dem/dds/participant.h"
#include "dem/dds/qos.h"
#include "dem/dds/topic.h"

namespace dem::dds {

struct SerializedSample {
  std::string bytes;                  // encapsulation header (CDR_LE: 00 01 00 00) and payload
  std::int64_t source_timestamp = 0;  // ns since the Unix epoch, by the writer's clock
};

class SerializedReader {
 public:
  template <SupportedType T>
  SerializedReader(const Participant& participant, const Topic<T>& topic, const Qos& qos)
      : topic_name_(topic.name()),
        entity_(check(dds_create_reader(participant.handle(), topic.handle(), endpoint_qos<T>(qos).get(), nullptr),
                      "creating a reader for " + topic_name_)) {}

  // Removes up to `max` samples from the reader's history and returns those
  // that carry data, oldest first.
  std::vector<SerializedSample> take(std::size_t max = 256);

  std::uint32_t matched_writers() const { return dds::matched_writers(entity_.handle()); }
  dds_entity_t handle() const { return entity_.handle(); }
  const std::string& topic_name() const { return topic_name_; }

 private:
  std::string topic_name_;
  Entity entity_;
};

}  // namespace dem::dds
