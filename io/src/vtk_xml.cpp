#include "vtk_xml.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "format_number.h"

namespace dem::io::vtk {
namespace {

template <typename Integer>
void append_integer(std::string& text, Integer value) {
  std::array<char, 24> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  text.append(buffer.data(), result.ptr);
}

void separate(std::string& values) {
  if (!values.empty()) values += ' ';
}

void append_array(std::string& xml, const DataArray& array, const char* indent) {
  xml += indent;
  xml += "<DataArray type=\"" + array.type + "\" Name=\"" + array.name + "\"";
  if (array.components != 1) xml += " NumberOfComponents=\"" + std::to_string(array.components) + "\"";
  xml += " NumberOfTuples=\"" + std::to_string(array.tuples()) + "\" format=\"ascii\">\n";
  xml += indent;
  xml += "  ";
  xml += array.values;
  xml += '\n';
  xml += indent;
  xml += "</DataArray>\n";
}

void append_data(std::string& xml, const char* element, const std::vector<DataArray>& arrays,
                 const std::string& scalars = {}) {
  xml += "      <";
  xml += element;
  if (!scalars.empty()) xml += " Scalars=\"" + scalars + "\"";
  xml += ">\n";
  for (const DataArray& array : arrays) append_array(xml, array, "        ");
  xml += "      </";
  xml += element;
  xml += ">\n";
}

void append_cells(std::string& xml, const char* element, const Cells& cells) {
  DataArray connectivity{.name = "connectivity", .type = "Int64"};
  for (std::int64_t point : cells.connectivity) connectivity.add(point);
  DataArray offsets{.name = "offsets", .type = "Int64"};
  for (std::int64_t offset : cells.offsets) offsets.add(offset);
  append_data(xml, element, {connectivity, offsets});
}

}  // namespace

void DataArray::add(double value) {
  separate(values);
  values += format_number(value);
  ++count;
}

void DataArray::add(std::int64_t value) {
  separate(values);
  append_integer(values, value);
  ++count;
}

void DataArray::add(std::uint64_t value) {
  separate(values);
  append_integer(values, value);
  ++count;
}

void DataArray::add(std::string_view text) {
  for (const char c : text) {
    separate(values);
    append_integer(values, static_cast<int>(static_cast<unsigned char>(c)));
  }
  separate(values);
  values += '0';
  ++count;
}

void Cells::add(std::initializer_list<std::int64_t> points) {
  connectivity.insert(connectivity.end(), points.begin(), points.end());
  offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
}

std::string to_xml(const PolyData& data) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <PolyData>\n";
  if (!data.field_data.empty()) {
    xml += "    <FieldData>\n";
    for (const DataArray& array : data.field_data) append_array(xml, array, "      ");
    xml += "    </FieldData>\n";
  }
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(data.points.size()) + "\" NumberOfVerts=\"" +
         std::to_string(data.verts.size()) + "\" NumberOfLines=\"" + std::to_string(data.lines.size()) +
         "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(data.polys.size()) + "\">\n";
  append_data(xml, "PointData", data.point_data, data.point_scalars);
  append_data(xml, "CellData", data.cell_data);
  DataArray points{.name = "Points", .type = "Float64", .components = 3};
  for (const auto& point : data.points) points.add(point);
  append_data(xml, "Points", {points});
  append_cells(xml, "Verts", data.verts);
  append_cells(xml, "Lines", data.lines);
  append_cells(xml, "Polys", data.polys);
  xml +=
      "    </Piece>\n"
      "  </PolyData>\n"
      "</VTKFile>\n";
  return xml;
}

void write_file(const std::filesystem::path& path, std::string_view text) {
  std::error_code error;
  if (path.has_parent_path()) {
    std::filesystem::create_directories(path.parent_path(), error);
    if (error) {
      throw std::runtime_error("cannot create the output directory " + path.parent_path().string() + ": " +
                               error.message());
    }
  }
  std::filesystem::path temporary = path;
  temporary += ".partial";
  {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) {
      throw std::runtime_error("cannot write " + path.string() + ": " +
                               (errno != 0 ? std::strerror(errno) : "the stream failed"));
    }
  }
  std::filesystem::rename(temporary, path, error);
  if (error) throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
}

}  // namespace dem::io::vtk
