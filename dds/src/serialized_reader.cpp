#include "dem/dds/serialized_reader.h"

#include <dds/ddsi/ddsi_serdata.h>

namespace dem::dds {

std::vector<SerializedSample> SerializedReader::take(std::size_t max) {
  std::vector<ddsi_serdata*> data(max, nullptr);
  std::vector<dds_sample_info_t> infos(max);
  const auto count =
      check(dds_takecdr(entity_.handle(), data.data(), static_cast<std::uint32_t>(max), infos.data(), DDS_ANY_STATE),
            "taking serialized samples from " + topic_name_);
  std::vector<SerializedSample> samples;
  samples.reserve(static_cast<std::size_t>(count));
  for (std::int32_t i = 0; i < count; ++i) {
    if (infos[i].valid_data) {
      SerializedSample sample;
      sample.bytes.resize(ddsi_serdata_size(data[i]));
      ddsi_serdata_to_ser(data[i], 0, sample.bytes.size(), sample.bytes.data());
      sample.source_timestamp = infos[i].source_timestamp;
      samples.push_back(std::move(sample));
    }
    ddsi_serdata_unref(data[i]);  // the reader lent us a reference to each
  }
  return samples;
}

}  // namespace dem::dds
