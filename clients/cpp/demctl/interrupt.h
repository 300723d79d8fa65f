// Ctrl-C while demctl waits (monitor, cycle --wait): a flag the waiting
// loops poll, set by a SIGINT/SIGTERM handler that does nothing else.
#pragma once

namespace demctl {

void watch_interrupts();
bool interrupted();

}  // namespace demctl
