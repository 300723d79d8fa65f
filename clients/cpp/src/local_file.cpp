#include "dem/client/local_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "dem/client/errors.h"

namespace dem::client {

std::string read_local_file(const std::filesystem::path& path) {
  // A directory opens as a stream on Linux, and reading it fails deep in
  // the library ("basic_filebuf::underflow"): say what it is instead.
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw LocalFileError("cannot read " + path.string() + ": it is a directory, not a file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LocalFileError("cannot read " + path.string() + ": " + std::strerror(errno));
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw LocalFileError("cannot read " + path.string() + ": " + std::strerror(errno));
  return bytes;
}

}  // namespace dem::client
