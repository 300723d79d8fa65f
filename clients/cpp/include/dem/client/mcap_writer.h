// MCAP files (https://mcap.dev/spec, major version 0), the container of
// ROS 2 bags and Foxglove: schemas, channels and timestamped messages in
// uncompressed chunks, each followed by its message indexes, and a summary
// (schemas, channels, statistics, chunk indexes, with summary offsets) so
// readers can seek; CRC-32s over the data section, every chunk and the
// summary.
//   McapWriter file("run.mcap", "ros2");
//   auto schema = file.add_schema("dem_interfaces/msg/PlateForces", "ros2msg", definition);
//   auto channel = file.add_channel(schema, "/dem/press/plate_forces", "cdr");
//   file.write(channel, log_time_ns, publish_time_ns, cdr_bytes);
//   file.close();
// A file whose writer died before close() has its chunks but no summary:
// streaming readers still read every chunk that was flushed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace dem::client {

class McapWriter {
 public:
  // Creates (truncates) the file and writes the magic and the header record.
  // Throws std::runtime_error naming the file when it cannot be written.
  McapWriter(const std::filesystem::path& path, std::string_view profile, std::string_view library = "dem");
  ~McapWriter();  // closes the file if close() was not called (errors are then lost)
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  // Ids count from 1 (0 is "no schema" in MCAP).
  std::uint16_t add_schema(std::string_view name, std::string_view encoding, std::string_view data);
  std::uint16_t add_channel(std::uint16_t schema, std::string_view topic, std::string_view message_encoding,
                            const std::map<std::string, std::string>& metadata = {});
  // A message; times are nanoseconds since the Unix epoch (log_time: when
  // it was received, publish_time: when it was sent).
  void write(std::uint16_t channel, std::uint64_t log_time, std::uint64_t publish_time, std::string_view data);
  // Ends the current chunk so what was written so far is in the file
  // (readers see whole chunks only).
  void flush();
  // Writes the last chunk, the data end, the summary and the footer.
  void close();

  const std::filesystem::path& path() const { return path_; }

 private:
  struct ChunkIndex {
    std::uint64_t start_time, end_time, offset, length;
    std::map<std::uint16_t, std::uint64_t> message_index_offsets;
    std::uint64_t message_index_length, size;
  };
  void put(std::string_view bytes);  // to the file, counted into the data section's CRC
  void put_record(std::uint8_t opcode, std::string_view content);

  std::filesystem::path path_;
  std::ofstream out_;
  std::uint64_t position_ = 0;
  std::uint32_t data_crc_;  // running CRC-32 state of the data section
  std::vector<std::string> schema_records_;
  std::vector<std::string> channel_records_;
  std::map<std::uint16_t, std::uint32_t> sequence_;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts_;
  // The chunk being filled: its records, and (log_time, offset in it) per channel.
  std::string chunk_;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;
  std::uint64_t chunk_start_time_ = 0, chunk_end_time_ = 0;
  std::vector<ChunkIndex> chunk_indexes_;
  std::uint64_t message_count_ = 0, first_time_ = 0, last_time_ = 0;
  bool closed_ = false;
};

// CRC-32 (IEEE 802.3, as zlib and MCAP): update a running state that starts
// at 0xFFFFFFFF; the checksum is the final state XOR 0xFFFFFFFF.
std::uint32_t crc32_update(std::uint32_t state, std::string_view bytes);
inline std::uint32_t crc32(std::string_view bytes) { return crc32_update(0xFFFFFFFFu, bytes) ^ 0xFFFFFFFFu; }

}  // namespace dem::client
