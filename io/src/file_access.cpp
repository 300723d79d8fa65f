#include "dem/io/file_access.h"

#include <algorithm>
#include <system_error>

namespace dem::io {

bool lies_within(const std::filesystem::path& path, const std::filesystem::path& root) {
  auto p = path.begin();
  for (auto r = root.begin(); r != root.end(); ++r, ++p) {
    if (r->empty() && std::next(r) == root.end()) break;  // a trailing separator
    if (p == path.end() || *p != *r) return false;
  }
  return true;
}

std::filesystem::path inside_directory(const std::filesystem::path& root, const std::filesystem::path& requested) {
  const std::string name = requested.string();
  if (requested.empty() || requested.is_absolute()) {
    throw FileAccessError("\"" + name + "\": a path relative to " + root.string() + " is needed");
  }
  for (const auto& part : requested) {
    if (part == "..") throw FileAccessError("\"" + name + "\": may not leave " + root.string() + " (\"..\")");
  }
  std::error_code error;
  std::filesystem::create_directories(root, error);
  const std::filesystem::path canonical_root = std::filesystem::canonical(root, error);
  if (error) throw FileAccessError(root.string() + ": " + error.message());
  const std::filesystem::path target = root / requested;
  // weakly_canonical resolves the links of the part that exists.
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(target.parent_path(), error);
  if (error || !lies_within(resolved, canonical_root)) {
    throw FileAccessError("\"" + name + "\": its directory lies outside " + root.string() + " (a link?)");
  }
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(target, error))) {
    throw FileAccessError("\"" + name + "\": is a link; the server writes and reads only files of its own");
  }
  return target;
}

std::filesystem::path own_directory(const std::filesystem::path& root, const std::filesystem::path& requested) {
  const std::filesystem::path directory = inside_directory(root, requested);
  const auto refuse = [&](const std::filesystem::path& link) {
    throw FileAccessError(link.string() + " is a link; the server writes only files of its own in " + root.string());
  };
  std::error_code error;
  for (const std::filesystem::path& part : {directory, directory / "vtk", directory / "checkpoints"}) {
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(part, error))) refuse(part);
    for (const auto& entry : std::filesystem::directory_iterator(part, error)) {
      if (entry.is_symlink(error)) refuse(entry.path());
    }
  }
  return directory;
}

FileAccess::FileAccess(const std::vector<std::filesystem::path>& roots) {
  for (const auto& root : roots) {
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::canonical(root, error);
    if (!error && std::filesystem::is_directory(canonical, error)) roots_.push_back(canonical);
  }
}

std::filesystem::path FileAccess::readable(const std::filesystem::path& requested,
                                           const std::filesystem::path& base) const {
  std::string allowed;
  for (const auto& root : roots_) allowed += (allowed.empty() ? "" : ", ") + root.string();
  if (allowed.empty()) allowed = "none";
  const std::string name = requested.string();
  if (requested.empty()) throw FileAccessError("no file named");
  const std::filesystem::path joined = requested.is_absolute() || base.empty() ? requested : base / requested;
  std::error_code error;
  // canonical() resolves every link and "..": what is checked is what would be opened.
  const std::filesystem::path canonical = std::filesystem::canonical(joined, error);
  const bool inside = !error && std::any_of(roots_.begin(), roots_.end(),
                                            [&](const auto& root) { return lies_within(canonical, root); });
  if (roots_.empty()) {
    throw FileAccessError(name +
                          ": this server reads no files for clients; start dem_server with --read-dir DIR "
                          "(repeatable) to let it read files from DIR");
  }
  // Whether a file outside exists is not said either.
  if (!inside) {
    throw FileAccessError(name + ": not a file in the directories this server reads (" + allowed + ")");
  }
  if (!std::filesystem::is_regular_file(canonical, error)) {
    throw FileAccessError(name + ": not a regular file");
  }
  return canonical;
}

}  // namespace dem::io
