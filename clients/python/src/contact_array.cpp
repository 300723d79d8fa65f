#include "contact_array.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string_view>
#include <tuple>
#include <type_traits>

namespace dem::python {

namespace py = pybind11;
using protocol::ContactEntry;
using protocol::Fields;
using protocol::Vector3;

namespace {

// One column: numpy's format of a value, how many values, and where.
struct Column {
  const char* name;
  const char* format;
  std::size_t size;  // of one value, bytes (its alignment too)
  std::size_t count;
  std::size_t offset = 0;
};

template <class T>
Column column_of(std::string_view name) {
  if constexpr (std::is_same_v<T, Vector3>) {
    return {name.data(), "<f8", sizeof(double), 3};
  } else if constexpr (std::is_same_v<T, double>) {
    return {name.data(), "<f8", sizeof(double), 1};
  } else if constexpr (std::is_same_v<T, std::int32_t>) {
    return {name.data(), "<i4", sizeof(std::int32_t), 1};
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    return {name.data(), "<u8", sizeof(std::uint64_t), 1};
  } else {
    static_assert(std::is_same_v<T, bool>, "a ContactEntry member with no numpy column: add its format here");
    return {name.data(), "?", sizeof(bool), 1};
  }
}

template <class T>
void put(std::byte* at, const T& value) {
  if constexpr (std::is_same_v<T, Vector3>) {
    const double xyz[3] = {value.x, value.y, value.z};
    std::memcpy(at, xyz, sizeof xyz);
  } else {
    std::memcpy(at, &value, sizeof value);
  }
}

struct Layout {
  std::vector<Column> columns;
  std::size_t itemsize = 0;
};

const Layout& layout() {
  static const Layout kLayout = [] {
    Layout l;
    std::apply(
        [&](const auto&... f) {
          (l.columns.push_back(column_of<std::remove_cvref_t<decltype(ContactEntry{}.*f.member)>>(f.name)), ...);
        },
        Fields<ContactEntry>::list);
    std::size_t offset = 0, alignment = 1;
    for (Column& c : l.columns) {
      offset = (offset + c.size - 1) / c.size * c.size;
      c.offset = offset;
      offset += c.size * c.count;
      alignment = std::max(alignment, c.size);
    }
    l.itemsize = (offset + alignment - 1) / alignment * alignment;
    return l;
  }();
  return kLayout;
}

}  // namespace

py::dtype contact_dtype() {
  py::list names, formats, offsets;
  for (const Column& c : layout().columns) {
    names.append(c.name);
    formats.append(c.count == 1 ? py::object(py::str(c.format)) : py::object(py::make_tuple(c.format, c.count)));
    offsets.append(c.offset);
  }
  py::dict spec;
  spec["names"] = names;
  spec["formats"] = formats;
  spec["offsets"] = offsets;
  spec["itemsize"] = layout().itemsize;
  return py::dtype::from_args(spec);
}

py::array contact_array(const std::vector<ContactEntry>& contacts) {
  py::array array(contact_dtype(), std::vector<py::ssize_t>{static_cast<py::ssize_t>(contacts.size())});
  auto* rows = static_cast<std::byte*>(array.mutable_data());
  const Layout& l = layout();
  std::memset(rows, 0, contacts.size() * l.itemsize);  // the padding too
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    std::byte* row = rows + i * l.itemsize;
    std::size_t column = 0;
    std::apply([&](const auto&... f) { (put(row + l.columns[column++].offset, contacts[i].*f.member), ...); },
               Fields<ContactEntry>::list);
  }
  return array;
}

}  // namespace dem::python
