#include "dem/io/csv_file.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include "format_number.h"

namespace dem::io {
namespace {

template <typename Integer>
void append_integer(std::string& line, Integer value) {
  std::array<char, 24> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  line.append(buffer.data(), result.ptr);
}

// The reason the last failed call gives, when it gives one.
std::runtime_error write_failure(const std::filesystem::path& path) {
  const std::string reason = errno != 0 ? std::strerror(errno) : "the stream failed";
  return std::runtime_error("cannot write " + path.string() + ": " + reason);
}

}  // namespace

void append_field(std::string& line, double value) { line += format_number(value); }

void append_field(std::string& line, bool value) { line += value ? '1' : '0'; }

void append_field(std::string& line, std::int64_t value) { append_integer(line, value); }

void append_field(std::string& line, std::uint64_t value) { append_integer(line, value); }

void append_field(std::string& line, std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
    line += text;
    return;
  }
  line += '"';
  for (char c : text) {
    if (c == '"') line += '"';
    line += c;
  }
  line += '"';
}

CsvFile::CsvFile(const std::filesystem::path& directory, std::string_view file_name, std::string_view header,
                 const TableSizes* resume)
    : path_(directory / file_name) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw std::runtime_error("cannot create the output directory " + directory.string() + ": " + error.message());
  }
  errno = 0;
  if (resume != nullptr) {
    if (const auto found = resume->find(file_name); found != resume->end()) {
      resume_at(header, found->second);
      return;
    }
  }
  out_.open(path_, std::ios::binary | std::ios::trunc);
  if (!out_) throw write_failure(path_);
  write_line(std::string(header) + '\n');
}

void CsvFile::resume_at(std::string_view header, std::uint64_t size) {
  std::error_code error;
  const std::uint64_t now = std::filesystem::file_size(path_, error);
  std::string first;
  std::ifstream(path_) >> first;
  if (error || now < size || size < header.size() + 1 || first != header) {
    throw std::runtime_error("cannot resume " + path_.string() + ": it is not the table the checkpoint wrote (" +
                             std::to_string(size) + " bytes starting with its header)");
  }
  // The rows written after the checkpoint go: the resumed run writes them again.
  std::filesystem::resize_file(path_, size, error);
  if (error) throw std::runtime_error("cannot resume " + path_.string() + ": " + error.message());
  out_.open(path_, std::ios::binary | std::ios::app);
  if (!out_) throw write_failure(path_);
}

void CsvFile::write_line(std::string_view line) {
  out_.write(line.data(), static_cast<std::streamsize>(line.size()));
  check();
}

void CsvFile::flush() {
  out_.flush();
  check();
}

void CsvFile::check() const {
  if (!out_) throw write_failure(path_);
}

}  // namespace dem::io
