// Rows of comma-separated values, numbers in the shortest form that reads
// back to the same double (as the engine's own tables in io/).
#pragma once

#include <charconv>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace demctl {

class CsvWriter {
 public:
  CsvWriter(const std::string& path, std::string_view header) : path_(path), out_(path) {
    if (!out_) throw std::runtime_error("cannot write " + path);
    out_ << header << '\n';
  }

  template <typename... Fields>
  void row(const Fields&... fields) {
    std::string line;
    (append(line, fields), ...);
    line.back() = '\n';
    out_ << line;
    if (!out_) throw std::runtime_error("cannot write " + path_);
  }
  // A row built a cell at a time with add (tables whose columns follow a
  // field list).
  template <typename T>
  static void add(std::string& line, const T& value) {
    append(line, value);
  }
  void built_row(std::string line) {
    line.back() = '\n';
    out_ << line;
    if (!out_) throw std::runtime_error("cannot write " + path_);
  }
  void flush() { out_.flush(); }

 private:
  template <typename T>
  static void append(std::string& line, const T& value) {
    if constexpr (std::is_same_v<T, std::vector<double>>) {
      for (const double v : value) append(line, v);
      return;
    } else if constexpr (std::is_same_v<T, bool>) {
      line += value ? "1" : "0";
    } else if constexpr (std::is_arithmetic_v<T>) {
      char buffer[32];
      const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
      line.append(buffer, end);
    } else {
      line += value;
    }
    line += ',';
  }

  std::string path_;
  std::ofstream out_;
};

}  // namespace demctl
