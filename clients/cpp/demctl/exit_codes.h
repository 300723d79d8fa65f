// demctl's exit codes (docs/SERVICE.md), one per kind of failure so scripts
// can tell them apart.
#pragma once

namespace demctl {

inline constexpr int kOk = 0;
inline constexpr int kFailure = 1;            // anything else: a file that cannot be written, a DDS error
inline constexpr int kBadArguments = 2;       // the command line is wrong
inline constexpr int kNoSuchServer = 3;       // no server of that name answered within --timeout
inline constexpr int kServerError = 4;        // the server replied with an error (its message is printed)
inline constexpr int kNoReply = 5;            // the server was found but its reply did not come in time
inline constexpr int kConditionNotMet = 6;    // run-until --wait reached its cycle cap before its condition
inline constexpr int kInterfaceMismatch = 7;  // the server's interface and demctl's cannot meet (versions named)
inline constexpr int kInterrupted = 130;      // Ctrl-C while waiting for a run (the run was stopped)

}  // namespace demctl
