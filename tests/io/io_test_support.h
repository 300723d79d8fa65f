// Shared by the io tests: the data directory, the valid case every
// bad-input test starts from, and a reader of the CSV tables they write.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dem/io/case_loader.h"
#include "dem/io/case_validation.h"

namespace dem::io::test {

inline std::filesystem::path data_path(const std::string& name) {
  return std::filesystem::path(DEM_IO_TEST_DATA) / name;
}

// nine discs, a glass disc and four random discs in a box of four walls,
// with three stages and two probes (tests/io/data/valid.case.txtpb).
inline proto::Case valid_case() { return load_case_file(data_path("valid.case.txtpb")).message; }

// 21 steel and glass spheres from every kind of source (one of them a CSV
// file beside the case, so conversion needs the loaded source) in a box of
// six rectangular walls, with Hertz-Mindlin contacts and two stages
// (tests/io/data/valid_3d.case.txtpb).
inline LoadedCase valid_3d_case() { return load_case_file(data_path("valid_3d.case.txtpb")); }

// "path: message" per problem, one a line, as validate_case reports them.
inline std::string problem_text(const proto::Case& message) {
  std::string text;
  for (const CaseProblem& problem : find_case_problems(message)) {
    text += problem.path + ": " + problem.message + '\n';
  }
  return text;
}

// A fresh, empty directory for one test's output.
inline std::filesystem::path fresh_directory(const std::string& name) {
  // The pid keeps runs from two build trees apart.
  const auto directory =
      std::filesystem::temp_directory_path() / ("dem_io_tests_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(directory);
  return directory;
}

using Row = std::vector<std::string>;

// A CSV file as rows of fields; nothing the io tests write needs quotes.
inline std::vector<Row> read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    Row row;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(field);
    if (!line.empty() && line.back() == ',') row.emplace_back();  // getline drops a last empty field
    rows.push_back(row);
  }
  return rows;
}

}  // namespace dem::io::test
