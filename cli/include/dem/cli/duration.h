// A time span as people read it on a progress line.
#pragma once

#include <string>

namespace dem::cli {

// "42 s", "3 min 05 s", "2 h 05 min" (rounded to the second).
std::string duration_text(double seconds);

}  // namespace dem::cli
