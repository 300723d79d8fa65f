// The C sample of a command, lent to a callback: what TypeSupport<Command>
// writes, for code that serializes it elsewhere (command_cdr.cpp).
#pragma once

#include <functional>

#include "dem/protocol/messages.h"

namespace dem::protocol {

// `use` sees a dem_interfaces_msg_dds__Command_ borrowing the command's memory.
void with_command_sample(const Command& command, const std::function<void(const void*)>& use);

}  // namespace dem::protocol
