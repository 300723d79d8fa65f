// The C sample of a message, lent to a callback: what TypeSupport<T>
// writes, for code that serializes it elsewhere (command_cdr.cpp).
#pragma once

#include <functional>

#include "dem/protocol/messages.h"

namespace dem::protocol {

// `use` sees the idlc-generated C struct of `message`, borrowing its memory.
template <Message T>
void with_c_sample(const T& message, const std::function<void(const void*)>& use);

}  // namespace dem::protocol
