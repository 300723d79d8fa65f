// Field paths into dem.proto.Case as messages spell them: "wall[2].h2".
#pragma once

#include <string>
#include <string_view>

namespace dem::io {

inline std::string indexed(std::string_view field, int index) {
  return std::string(field) + '[' + std::to_string(index) + ']';
}

}  // namespace dem::io
