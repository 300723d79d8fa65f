// Which files a server may read when a request names them (a case's path in
// load_case, a case's csv_file): only regular files inside the directories
// it was given, judged after resolving "..", "." and every symbolic link,
// so neither a relative path, an absolute one nor a link planted in an
// allowed directory reaches anything else. Errors name the request and the
// allowed directories, never a byte of the file. (Writing - snapshots in
// the output directory - is in snapshot_file.h; the output directory's
// own files are checked by own_directory below.)
#pragma once

#include <filesystem>
#include <stdexcept>
#include <vector>

namespace dem::io {

class FileAccessError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FileAccess {
 public:
  // Each directory as its canonical path; one that does not exist allows nothing.
  explicit FileAccess(const std::vector<std::filesystem::path>& roots);

  // The canonical path of `requested` (a relative one starts from `base`)
  // when it names a regular file inside one of the directories; throws
  // FileAccessError otherwise.
  std::filesystem::path readable(const std::filesystem::path& requested, const std::filesystem::path& base = {}) const;

  const std::vector<std::filesystem::path>& roots() const { return roots_; }

 private:
  std::vector<std::filesystem::path> roots_;
};

// A file for the server to write or read back inside `root` (its output
// directory): `requested` must be relative, without "..", and resolve - its
// directories' links followed, as far as they exist - inside `root`; a
// link in the place of the file itself is refused. Returns root/requested;
// throws FileAccessError otherwise.
std::filesystem::path inside_directory(const std::filesystem::path& root, const std::filesystem::path& requested);

// A directory of the server's own files inside `root` (a case's tables,
// ParaView files and checkpoints, written under fixed names): as
// inside_directory, and no link in it, in its vtk/ or checkpoints/, nor
// either of those a link - a link planted there would have the server
// write, or truncate, a file elsewhere. Checked when the server starts
// writing there. Returns root/requested; throws FileAccessError.
std::filesystem::path own_directory(const std::filesystem::path& root, const std::filesystem::path& requested);

// Whether `path` (canonical) lies inside `root` (canonical), component by component.
bool lies_within(const std::filesystem::path& path, const std::filesystem::path& root);

}  // namespace dem::io
