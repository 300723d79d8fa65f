// One CSV output file with a header row. Numbers are written in the shortest
// form that reads back to the same double (std::to_chars), so nothing is lost
// to rounding; booleans as 0/1; text quoted only when it must be (RFC 4180).
#pragma once

#include <concepts>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "dem/ids.h"

namespace dem::io {

void append_field(std::string& line, double value);
void append_field(std::string& line, bool value);
void append_field(std::string& line, std::string_view text);
inline void append_field(std::string& line, const char* text) { append_field(line, std::string_view(text)); }
void append_field(std::string& line, std::int64_t value);
void append_field(std::string& line, std::uint64_t value);
template <std::integral T>
requires(!std::same_as<T, bool>) void append_field(std::string& line, T value) {
  if constexpr (std::signed_integral<T>) {
    append_field(line, static_cast<std::int64_t>(value));
  } else {
    append_field(line, static_cast<std::uint64_t>(value));
  }
}
// An id (dem/ids.h) as its value, the number the wire and the files carry.
template <typename Tag>
void append_field(std::string& line, Id<Tag> id) {
  append_field(line, static_cast<std::int64_t>(id.value()));
}

// How long each table of a run was when it was checkpointed (file name ->
// bytes): a resumed run cuts each back to that and appends, so no row is
// lost or written twice (docs/RELIABILITY.md).
using TableSizes = std::map<std::string, std::uint64_t, std::less<>>;

class CsvFile {
 public:
  // Creates the directory if it is missing and writes the header. With
  // `resume`, a table it lists is instead cut back to its size there and
  // appended to (it must start with the same header). Throws
  // std::runtime_error naming the file when it cannot be written, or
  // cannot be resumed.
  CsvFile(const std::filesystem::path& directory, std::string_view file_name, std::string_view header,
          const TableSizes* resume = nullptr);

  template <typename... Fields>
  void write_row(const Fields&... fields) {
    std::string line;
    (append_separated(line, fields), ...);
    line += '\n';
    write_line(line);
  }

  // A row of the leading fields followed by a run of numbers (tables whose
  // columns depend on the dimension).
  template <typename... Fields>
  void write_row_then(const std::vector<double>& numbers, const Fields&... fields) {
    std::string line;
    (append_separated(line, fields), ...);
    for (const double value : numbers) append_separated(line, value);
    line += '\n';
    write_line(line);
  }

  // A row built by the caller, a field at a time with add_field (tables
  // whose columns follow a field list).
  template <typename Field>
  static void add_field(std::string& line, const Field& field) {
    append_separated(line, field);
  }
  void write_built_row(std::string line) {
    line += '\n';
    write_line(line);
  }

  // Pushes buffered rows to the file, so a long run can be watched as it
  // grows; throws std::runtime_error naming the file when that fails.
  void flush();

  const std::filesystem::path& path() const { return path_; }
  // Bytes in the file, buffered rows included.
  std::uint64_t bytes() { return static_cast<std::uint64_t>(out_.tellp()); }

 private:
  template <typename Field>
  static void append_separated(std::string& line, const Field& field) {
    if (!line.empty()) line += ',';
    append_field(line, field);
  }

  void write_line(std::string_view line);
  void resume_at(std::string_view header, std::uint64_t size);
  void check() const;

  std::filesystem::path path_;
  std::ofstream out_;
};

}  // namespace dem::io
