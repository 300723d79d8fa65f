#include "dem/client/mcap_writer.h"

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace dem::client {
namespace {

// Record opcodes (MCAP spec, "Records").
constexpr std::uint8_t kHeader = 0x01, kFooter = 0x02, kSchema = 0x03, kChannel = 0x04, kMessage = 0x05, kChunk = 0x06,
                       kMessageIndex = 0x07, kChunkIndex = 0x08, kStatistics = 0x0B, kSummaryOffset = 0x0E,
                       kDataEnd = 0x0F;
constexpr std::string_view kMagic("\x89MCAP0\r\n", 8);
// A chunk is closed at about this size: big enough for efficient reading,
// small enough that a reader never waits long for the next.
constexpr std::size_t kChunkSize = 1u << 20;

// Little-endian fields, strings (uint32 length + bytes) and maps (uint32
// byte length + entries), as every record is made of.
template <typename Integer>
void put_integer(std::string& out, Integer value) {
  for (std::size_t i = 0; i < sizeof(Integer); ++i)
    out += static_cast<char>((static_cast<std::uint64_t>(value) >> (8 * i)) & 0xFF);
}
void put_string(std::string& out, std::string_view text) {
  put_integer(out, static_cast<std::uint32_t>(text.size()));
  out += text;
}
std::string record(std::uint8_t opcode, std::string_view content) {
  std::string bytes(1, static_cast<char>(opcode));
  put_integer(bytes, static_cast<std::uint64_t>(content.size()));
  bytes += content;
  return bytes;
}

constexpr std::array<std::uint32_t, 256> crc_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[i] = c;
  }
  return table;
}
constexpr std::array<std::uint32_t, 256> kCrcTable = crc_table();

}  // namespace

std::uint32_t crc32_update(std::uint32_t state, std::string_view bytes) {
  for (const char byte : bytes) state = kCrcTable[(state ^ static_cast<std::uint8_t>(byte)) & 0xFFu] ^ (state >> 8);
  return state;
}

McapWriter::McapWriter(const std::filesystem::path& path, std::string_view profile, std::string_view library)
    : path_(path), data_crc_(0xFFFFFFFFu) {
  errno = 0;
  out_.open(path, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
  put(kMagic);
  std::string header;
  put_string(header, profile);
  put_string(header, library);
  put_record(kHeader, header);
}

McapWriter::~McapWriter() {
  if (closed_) return;
  try {
    close();
  } catch (const std::exception&) {  // a destructor cannot report it; close() explicitly to see it
  }
}

void McapWriter::put(std::string_view bytes) {
  out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out_) throw std::runtime_error("cannot write " + path_.string() + ": " + std::strerror(errno));
  data_crc_ = crc32_update(data_crc_, bytes);
  position_ += bytes.size();
}

void McapWriter::put_record(std::uint8_t opcode, std::string_view content) { put(record(opcode, content)); }

std::uint16_t McapWriter::add_schema(std::string_view name, std::string_view encoding, std::string_view data) {
  const auto id = static_cast<std::uint16_t>(schema_records_.size() + 1);
  std::string content;
  put_integer(content, id);
  put_string(content, name);
  put_string(content, encoding);
  put_string(content, data);  // uint32-length-prefixed bytes, as a string
  put_record(kSchema, content);
  schema_records_.push_back(record(kSchema, content));
  return id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema, std::string_view topic, std::string_view message_encoding,
                                      const std::map<std::string, std::string>& metadata) {
  const auto id = static_cast<std::uint16_t>(channel_records_.size() + 1);
  std::string content;
  put_integer(content, id);
  put_integer(content, schema);
  put_string(content, topic);
  put_string(content, message_encoding);
  std::string entries;
  for (const auto& [key, value] : metadata) {
    put_string(entries, key);
    put_string(entries, value);
  }
  put_string(content, entries);
  put_record(kChannel, content);
  channel_records_.push_back(record(kChannel, content));
  channel_message_counts_[id] = 0;
  return id;
}

void McapWriter::write(std::uint16_t channel, std::uint64_t log_time, std::uint64_t publish_time,
                       std::string_view data) {
  if (channel == 0 || channel > channel_records_.size()) {
    throw std::invalid_argument("MCAP message on channel " + std::to_string(channel) + ", which was not added");
  }
  std::string content;
  put_integer(content, channel);
  put_integer(content, sequence_[channel]++);
  put_integer(content, log_time);
  put_integer(content, publish_time);
  content += data;
  if (chunk_.empty()) chunk_start_time_ = chunk_end_time_ = log_time;
  chunk_start_time_ = std::min(chunk_start_time_, log_time);
  chunk_end_time_ = std::max(chunk_end_time_, log_time);
  chunk_index_[channel].emplace_back(log_time, chunk_.size());
  chunk_ += record(kMessage, content);
  if (message_count_ == 0) first_time_ = last_time_ = log_time;
  first_time_ = std::min(first_time_, log_time);
  last_time_ = std::max(last_time_, log_time);
  ++message_count_;
  ++channel_message_counts_[channel];
  if (chunk_.size() >= kChunkSize) flush();
}

void McapWriter::flush() {
  if (chunk_.empty()) {
    out_.flush();
    return;
  }
  ChunkIndex index{chunk_start_time_, chunk_end_time_, position_, 0, {}, 0, chunk_.size()};
  std::string content;
  put_integer(content, chunk_start_time_);
  put_integer(content, chunk_end_time_);
  put_integer(content, static_cast<std::uint64_t>(chunk_.size()));  // uncompressed size
  put_integer(content, crc32(chunk_));
  put_string(content, "");  // no compression
  put_integer(content, static_cast<std::uint64_t>(chunk_.size()));
  content += chunk_;
  put_record(kChunk, content);
  index.length = position_ - index.offset;
  // Each channel's messages in the chunk: log time and offset in the chunk's records.
  const std::uint64_t indexes_start = position_;
  for (const auto& [channel, entries] : chunk_index_) {
    std::string message_index;
    put_integer(message_index, channel);
    std::string list;
    for (const auto& [time, offset] : entries) {
      put_integer(list, time);
      put_integer(list, offset);
    }
    put_string(message_index, list);
    index.message_index_offsets[channel] = position_;
    put_record(kMessageIndex, message_index);
  }
  index.message_index_length = position_ - indexes_start;
  chunk_indexes_.push_back(std::move(index));
  chunk_.clear();
  chunk_index_.clear();
  out_.flush();
  if (!out_) throw std::runtime_error("cannot write " + path_.string() + ": " + std::strerror(errno));
}

void McapWriter::close() {
  if (closed_) return;
  closed_ = true;
  flush();
  std::string data_end;
  put_integer(data_end, data_crc_ ^ 0xFFFFFFFFu);
  put_record(kDataEnd, data_end);

  // The summary: its groups, each found again through a summary offset.
  const std::uint64_t summary_start = position_;
  std::string summary;
  std::string offsets;
  auto group = [&](std::uint8_t opcode, const std::vector<std::string>& records) {
    if (records.empty()) return;
    const std::uint64_t start = summary_start + summary.size();
    for (const std::string& r : records) summary += r;
    std::string offset;
    put_integer(offset, opcode);
    put_integer(offset, start);
    put_integer(offset, summary_start + summary.size() - start);
    offsets += record(kSummaryOffset, offset);
  };
  group(kSchema, schema_records_);
  group(kChannel, channel_records_);
  std::string statistics;
  put_integer(statistics, message_count_);
  put_integer(statistics, static_cast<std::uint16_t>(schema_records_.size()));
  put_integer(statistics, static_cast<std::uint32_t>(channel_records_.size()));
  put_integer(statistics, std::uint32_t{0});  // attachments
  put_integer(statistics, std::uint32_t{0});  // metadata
  put_integer(statistics, static_cast<std::uint32_t>(chunk_indexes_.size()));
  put_integer(statistics, first_time_);
  put_integer(statistics, last_time_);
  std::string counts;
  for (const auto& [channel, count] : channel_message_counts_) {
    put_integer(counts, channel);
    put_integer(counts, count);
  }
  put_string(statistics, counts);
  group(kStatistics, {record(kStatistics, statistics)});
  std::vector<std::string> chunk_index_records;
  for (const ChunkIndex& c : chunk_indexes_) {
    std::string content;
    put_integer(content, c.start_time);
    put_integer(content, c.end_time);
    put_integer(content, c.offset);
    put_integer(content, c.length);
    std::string index_offsets;
    for (const auto& [channel, offset] : c.message_index_offsets) {
      put_integer(index_offsets, channel);
      put_integer(index_offsets, offset);
    }
    put_string(content, index_offsets);
    put_integer(content, c.message_index_length);
    put_string(content, "");
    put_integer(content, c.size);  // compressed size: the same, uncompressed
    put_integer(content, c.size);
    chunk_index_records.push_back(record(kChunkIndex, content));
  }
  group(kChunkIndex, chunk_index_records);

  // The footer's CRC covers the summary, the summary offsets and the
  // footer's own fields before it.
  const std::uint64_t summary_offset_start = summary_start + summary.size();
  std::string footer_fields;
  put_integer(footer_fields, summary_start);
  put_integer(footer_fields, summary_offset_start);
  std::string footer_prefix(1, static_cast<char>(kFooter));
  put_integer(footer_prefix, std::uint64_t{20});
  footer_prefix += footer_fields;
  std::uint32_t summary_crc = crc32_update(0xFFFFFFFFu, summary);
  summary_crc = crc32_update(summary_crc, offsets);
  summary_crc = crc32_update(summary_crc, footer_prefix) ^ 0xFFFFFFFFu;
  put(summary);
  put(offsets);
  put_integer(footer_fields, summary_crc);
  put_record(kFooter, footer_fields);
  put(kMagic);
  out_.close();
  if (!out_) throw std::runtime_error("cannot write " + path_.string() + ": " + std::strerror(errno));
}

}  // namespace dem::client
