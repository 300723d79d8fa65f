#include "json.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace demctl {
namespace {

// A tiny writer: members separated by commas, strings escaped (RFC 8259),
// numbers in the shortest form that reads back to the same double.
class Json {
 public:
  Json& begin() {
    separate();
    text_ += '{';
    first_ = true;
    return *this;
  }
  Json& end() {
    text_ += '}';
    first_ = false;
    return *this;
  }
  Json& begin_array() {
    separate();
    text_ += '[';
    first_ = true;
    return *this;
  }
  Json& end_array() {
    text_ += ']';
    first_ = false;
    return *this;
  }
  Json& key(std::string_view name) {
    separate();
    string(name);
    text_ += ':';
    first_ = true;  // the value follows without a comma
    return *this;
  }
  Json& value(double number) {
    separate();
    if (!std::isfinite(number)) {
      text_ += "null";  // JSON has no NaN or infinity
    } else {
      std::array<char, 32> buffer{};
      text_.append(buffer.data(), std::to_chars(buffer.data(), buffer.data() + buffer.size(), number).ptr);
    }
    return *this;
  }
  template <typename Integer>
  requires std::is_integral_v<Integer> Json& value(Integer number) {
    separate();
    if constexpr (std::is_same_v<Integer, bool>) {
      text_ += number ? "true" : "false";
    } else {
      text_ += std::to_string(
          static_cast<std::conditional_t<std::is_signed_v<Integer>, long long, unsigned long long>>(number));
    }
    return *this;
  }
  Json& value(const std::string& text) {
    separate();
    string(text);
    return *this;
  }
  template <typename T>
  Json& value(const std::vector<T>& values) {
    begin_array();
    for (const T& v : values) value(v);
    return end_array();
  }
  // A message: every member by its IDL name (dem::protocol::Fields); an
  // enumeration as its number, then its name as <member>_name.
  template <dem::protocol::Message T>
  Json& value(const T& message) {
    begin();
    std::apply([&](const auto&... f) { (member(f.name, message.*f.member), ...); }, dem::protocol::Fields<T>::list);
    return end();
  }
  template <typename T>
  Json& field(const char* name, const T& v) {
    return key(name).value(v);
  }
  std::string text() const { return text_; }

 private:
  template <typename T>
  void member(std::string_view name, const T& v) {
    if constexpr (std::is_enum_v<T>) {
      key(name).value(static_cast<std::underlying_type_t<T>>(v));
      key(std::string(name) + "_name").value(std::string(dem::protocol::to_string(v)));
    } else {
      key(name).value(v);
    }
  }

  void separate() {
    if (!first_) text_ += ',';
    first_ = false;
  }
  void string(std::string_view s) {
    text_ += '"';
    for (const char c : s) {
      if (c == '"' || c == '\\') {
        text_ += '\\';
        text_ += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
        text_ += escaped;
      } else {
        text_ += c;
      }
    }
    text_ += '"';
  }

  std::string text_;
  bool first_ = true;
};

}  // namespace

std::string state_json(const dem::protocol::Reply& reply) {
  Json json;
  json.begin().key("status").value(reply.state).key("plates").value(reply.plates).key("stats").value(reply.stats);
  json.field("state_hash", reply.state_hash).end();
  return json.text();
}

}  // namespace demctl
