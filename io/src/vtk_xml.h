// The VTK XML PolyData format as ParaView reads it (VTK's "VTK File
// Formats", XML section): a piece of points and cells, with named arrays of
// point, cell and field data. Numbers are ASCII in the shortest form that
// reads back to the same double, so a file is exact and can be read by eye.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace dem::io::vtk {

// One named data array: `components` numbers per tuple (3 for a vector, 4
// for a quaternion, 9 for a tensor), in VTK's type names.
struct DataArray {
  std::string name;
  std::string type;  // "Float64", "Int32", "Int64", "UInt64", "UInt8", "String"
  int components = 1;
  std::string values;     // the ASCII numbers, separated by spaces
  std::size_t count = 0;  // numbers added (strings, for "String")
  std::size_t tuples() const { return type == "String" ? count : count / static_cast<std::size_t>(components); }
  void add(double value);
  void add(std::int64_t value);
  void add(std::uint64_t value);
  void add(int value) { add(static_cast<std::int64_t>(value)); }
  void add(std::string_view text);  // "String": VTK writes each as its character codes and a 0
  template <std::size_t N>
  void add(const std::array<double, N>& tuple) {
    for (double v : tuple) add(v);
  }
};

// The cells of one kind: each a list of point indices (a vertex has one, a
// line two, a polygon three or more).
struct Cells {
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;  // the end of each cell in connectivity
  void add(std::initializer_list<std::int64_t> points);
  std::size_t size() const { return offsets.size(); }
};

struct PolyData {
  std::vector<std::array<double, 3>> points;
  Cells verts;
  Cells lines;
  Cells polys;
  std::vector<DataArray> point_data;  // one tuple per point
  std::vector<DataArray> cell_data;   // one tuple per cell, in the order verts, lines, polys
  std::vector<DataArray> field_data;  // any number of tuples: about the whole file
  std::string point_scalars;          // the point array ParaView colours by at first
};

// The file's text.
std::string to_xml(const PolyData& data);

// Writes `text` through a temporary file renamed into place, so ParaView
// never reads half a file (a .pvd is rewritten while a run goes on).
// Creates the directory; throws std::runtime_error naming the file.
void write_file(const std::filesystem::path& path, std::string_view text);

}  // namespace dem::io::vtk
