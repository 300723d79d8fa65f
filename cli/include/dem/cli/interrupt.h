// Ctrl-C (SIGINT) or SIGTERM while a program runs or waits: a flag its
// loops poll, so it stops cleanly (dem_run writes what it reached; demctl
// stops the run it waits on). A second signal ends the program at once
// (the handler is reset after the first): a stuck program can still be
// stopped.
#pragma once

namespace dem::cli {

void watch_interrupts();
bool interrupted();

}  // namespace dem::cli
