// io::CsvTable: a table the project wrote, read back by column name, with
// errors that name the file, the line and the column.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <string>

#include "dem/io/csv_table.h"
#include "io_test_support.h"

namespace dem::io {
namespace {

std::filesystem::path write_file(const std::string& test, const std::string& text) {
  const std::filesystem::path directory = test::fresh_directory(test);
  std::filesystem::create_directories(directory);
  const std::filesystem::path file = directory / "table.csv";
  std::ofstream(file) << text;
  return file;
}

std::string message_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const CsvTableError& error) {
    return error.what();
  }
  return "no error";
}

TEST(CsvTable, ReadsColumnsByNameAsTextAndNumbers) {
  const CsvTable table = CsvTable::read(
      write_file("csv_table_columns", "cycle,stress,label,last\n0,1.5e3,a,\n50,inf,b,x\n\n100,-2,c,y\n"));
  EXPECT_EQ(table.rows(), 3u);
  EXPECT_TRUE(table.has("stress"));
  EXPECT_FALSE(table.has("strain"));
  EXPECT_EQ(table.text(1, "label"), "b");
  EXPECT_EQ(table.text(0, "last"), "");  // a row's last field may be empty
  EXPECT_DOUBLE_EQ(table.number(0, "stress"), 1500.0);
  EXPECT_TRUE(std::isinf(table.number(1, "stress")));
  EXPECT_EQ(table.column("cycle"), (std::vector<double>{0, 50, 100}));
}

TEST(CsvTable, ErrorsNameTheFileTheLineAndTheColumn) {
  EXPECT_NE(message_of([] { CsvTable::read("/nonexistent/table.csv"); }).find("/nonexistent/table.csv: cannot be read"),
            std::string::npos);
  EXPECT_NE(message_of([] { CsvTable::read(write_file("csv_table_empty", "")); }).find("has no header line"),
            std::string::npos);
  EXPECT_NE(message_of([] {
              CsvTable::read(write_file("csv_table_short", "a,b\n1,2\n3\n"));
            }).find("table.csv:3: 1 fields where the header has 2"),
            std::string::npos);
  const CsvTable table = CsvTable::read(write_file("csv_table_bad_number", "a,b\n\n1,2x\n"));
  EXPECT_NE(message_of([&] { table.number(0, "b"); }).find("table.csv:3: column b is not a number (\"2x\")"),
            std::string::npos);
  EXPECT_NE(message_of([&] { table.column("c"); }).find("no column c"), std::string::npos);
}

}  // namespace
}  // namespace dem::io
