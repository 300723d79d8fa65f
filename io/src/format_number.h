// Numbers as text in the shortest form that reads back to the same double,
// for messages and CSV files alike: 0.1 stays "0.1", 1e-7 stays "1e-07".
#pragma once

#include <string>

namespace dem::io {

std::string format_number(double value);

}  // namespace dem::io
