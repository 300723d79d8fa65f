#include "dem/service/command_error.h"

#include <new>

#include "dem/io/resource_limits.h"

namespace dem::service {

std::string failure_reason(const std::exception& error) {
  if (dynamic_cast<const std::bad_alloc*>(&error) != nullptr) return io::out_of_memory_reason();
  return error.what();
}

}  // namespace dem::service
