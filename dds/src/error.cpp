#include "dem/dds/error.h"

namespace dem::dds {

DdsError::DdsError(dds_return_t code, std::string_view what)
    : std::runtime_error(std::string(what) + ": " + dds_strretcode(code)), code_(code) {}

dds_return_t check(dds_return_t result, std::string_view what) {
  if (result < 0) throw DdsError(result, what);
  return result;
}

}  // namespace dem::dds
