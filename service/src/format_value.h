// Numbers in reply and status messages: the shortest form ostream gives
// (6 significant digits), as people read them.
#pragma once

#include <sstream>
#include <string>

namespace dem::service {

inline std::string format_value(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace dem::service
