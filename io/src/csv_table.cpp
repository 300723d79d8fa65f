#include "dem/io/csv_table.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace dem::io {

namespace {

// The project's tables quote nothing: a field is what lies between commas.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw CsvTableError(file.string() + ": cannot be read");
  CsvTable table;
  table.file_ = file;
  std::string line;
  if (!std::getline(in, line) || line.empty()) throw CsvTableError(file.string() + ": has no header line");
  table.header_ = fields_of(line);
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::vector<std::string> fields = fields_of(line);
    if (fields.size() != table.header_.size()) {
      throw CsvTableError(file.string() + ":" + std::to_string(number) + ": " + std::to_string(fields.size()) +
                          " fields where the header has " + std::to_string(table.header_.size()));
    }
    table.rows_.push_back(std::move(fields));
    table.lines_.push_back(number);
  }
  return table;
}

bool CsvTable::has(std::string_view column) const {
  return std::find(header_.begin(), header_.end(), column) != header_.end();
}

std::size_t CsvTable::index(std::string_view column) const {
  const auto found = std::find(header_.begin(), header_.end(), column);
  if (found == header_.end()) throw CsvTableError(file_.string() + ": no column " + std::string(column));
  return static_cast<std::size_t>(found - header_.begin());
}

const std::string& CsvTable::text(std::size_t row, std::string_view column) const {
  return rows_.at(row)[index(column)];
}

double CsvTable::number(std::size_t row, std::string_view column) const {
  const std::string& field = text(row, column);
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (field.empty() || end != field.c_str() + field.size()) {
    throw CsvTableError(file_.string() + ":" + std::to_string(lines_.at(row)) + ": column " + std::string(column) +
                        " is not a number (\"" + field + "\")");
  }
  return value;
}

std::vector<double> CsvTable::column(std::string_view name) const {
  std::vector<double> values;
  values.reserve(rows_.size());
  for (std::size_t row = 0; row < rows_.size(); ++row) values.push_back(number(row, name));
  return values;
}

}  // namespace dem::io
