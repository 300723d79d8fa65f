#include "format_number.h"

#include <array>
#include <charconv>

namespace dem::io {

std::string format_number(double value) {
  // The longest shortest-round-trip double, "-2.2250738585072014e-308", fits easily.
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace dem::io
