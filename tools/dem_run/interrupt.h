// Ctrl-C (SIGINT) or SIGTERM during a run: a flag the run polls between
// cycles, so it stops cleanly and writes what it reached. A second signal
// ends the program at once (the handler is reset after the first).
#pragma once

namespace dem::run {

void watch_interrupts();
bool interrupted();

}  // namespace dem::run
