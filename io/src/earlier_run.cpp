#include "dem/io/earlier_run.h"

#include <algorithm>
#include <array>
#include <string_view>
#include <system_error>

namespace dem::io {

namespace {

bool written_by_a_run(const std::filesystem::directory_entry& entry) {
  const std::filesystem::path name = entry.path().filename();
  std::error_code error;
  if (entry.is_directory(error) && !entry.is_symlink(error)) return name == "vtk" || name == "checkpoints";
  constexpr std::array<std::string_view, 3> kExtensions = {".csv", ".snapshot", ".pvd"};
  const std::string extension = name.extension().string();
  return std::ranges::find(kExtensions, extension) != kExtensions.end();
}

}  // namespace

std::vector<std::string> earlier_run_entries(const std::filesystem::path& directory, RunEntries which) {
  std::vector<std::string> names;
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error)) return names;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
    if (which == RunEntries::kEvery || written_by_a_run(entry)) names.push_back(entry.path().filename().string());
  }
  std::ranges::sort(names);
  return names;
}

std::string some_names(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 4;
  std::string listed;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i) listed += (i > 0 ? ", " : "") + names[i];
  if (names.size() > kShown) listed += ", ... (" + std::to_string(names.size()) + " in all)";
  return listed;
}

void remove_entries(const std::filesystem::path& directory, const std::vector<std::string>& names) {
  std::error_code error;
  // remove_all takes a link itself away, never what it points to.
  for (const std::string& name : names) std::filesystem::remove_all(directory / name, error);
}

}  // namespace dem::io
