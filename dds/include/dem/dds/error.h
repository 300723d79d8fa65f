// The one place where Cyclone DDS's C return codes become exceptions
// (the model: rclcpp's throw_from_rcl_error). Everything else in dem::dds
// calls check() and never looks at a return code again.
#pragma once

#include <dds/dds.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace dem::dds {

class DdsError : public std::runtime_error {
 public:
  DdsError(dds_return_t code, std::string_view what);
  dds_return_t code() const { return code_; }

 private:
  dds_return_t code_;
};

// Throws DdsError("<what>: <Cyclone's text for the code>") when the result is
// negative; returns it otherwise (entity handles are positive).
dds_return_t check(dds_return_t result, std::string_view what);

}  // namespace dem::dds
