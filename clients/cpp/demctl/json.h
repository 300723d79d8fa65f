// demctl status --json: the get_state reply as one JSON object for scripts,
// with the field names of the messages in idl/dem/telemetry.idl (the
// ROS 2 message fields): {"status": {...}, "plates": {...}, "stats": {...},
// "state_hash": N}. A test compares the names with the IDL's.
#pragma once

#include <string>

#include "dem/protocol/messages.h"

namespace demctl {

std::string state_json(const dem::protocol::Reply& reply);

}  // namespace demctl
