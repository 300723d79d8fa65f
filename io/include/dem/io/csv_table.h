// A CSV table the project wrote (csv_file.h), read back whole: the
// columns its header names and its rows as text, numbers parsed on demand.
// For tools that judge a finished run from its tables (dem_validate's
// miyata-compression --runs). Errors name the file, the line and the
// column.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace dem::io {

class CsvTableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CsvTable {
 public:
  // Throws CsvTableError when the file cannot be read, has no header, or a
  // row has another number of fields than the header.
  static CsvTable read(const std::filesystem::path& file);

  std::size_t rows() const { return rows_.size(); }
  bool has(std::string_view column) const;
  const std::string& text(std::size_t row, std::string_view column) const;
  // The field as a number (inf and nan too); throws naming the file, line and column.
  double number(std::size_t row, std::string_view column) const;
  // Every row's field as a number.
  std::vector<double> column(std::string_view name) const;

 private:
  std::size_t index(std::string_view column) const;

  std::filesystem::path file_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> lines_;  // each row's line in the file, for errors
};

}  // namespace dem::io
