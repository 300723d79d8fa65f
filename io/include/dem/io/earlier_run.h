// What an earlier run left in an output directory, so that a new run into
// it is refused rather than cutting its tables (docs/RELIABILITY.md, "An
// earlier run's output is never cut"): dem_server's case directories and
// dem_run's --out.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace dem::io {

// Which entries count as an earlier run's: every entry of a directory the
// program owns (dem_server's <out>/<case>/), or only what a run writes -
// tables (.csv), snapshots (.snapshot), ParaView series (.pvd), vtk/ and
// checkpoints/ - in a directory the user named (dem_run's --out), which may
// hold files of their own.
enum class RunEntries { kEvery, kWritten };

// Those entries of `directory`, sorted by name; none when it does not exist.
std::vector<std::string> earlier_run_entries(const std::filesystem::path& directory, RunEntries which);

// The first few names and how many in all, for a refusal: "a, b, c, d, ... (9 in all)".
std::string some_names(const std::vector<std::string>& names);

// Removes the entries named (a link itself, never what it points to).
void remove_entries(const std::filesystem::path& directory, const std::vector<std::string>& names);

}  // namespace dem::io
