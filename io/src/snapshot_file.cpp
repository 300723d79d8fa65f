#include "dem/io/snapshot_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <system_error>

#include "dem/io/snapshot_frame.h"

namespace dem::io {

template <int Dim>
std::string serialize_snapshot(const WorldSnapshotT<Dim>& snapshot, const SnapshotInfo& info) {
  std::string bytes;
  if (!snapshot_to_proto(snapshot, info).SerializeToString(&bytes)) {
    throw SnapshotError("the snapshot could not be serialized (larger than 2 GiB?)");
  }
  return frame_snapshot(bytes);
}

proto::Snapshot parse_snapshot_message(std::string_view framed, std::string_view source_name) {
  const std::string source(source_name);
  const std::string_view bytes = unframe_snapshot(framed, source_name);
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw SnapshotError(source + ": larger than 2 GiB, which no snapshot is");
  }
  proto::Snapshot message;
  if (!message.ParseFromArray(bytes.data(), static_cast<int>(bytes.size()))) {
    throw SnapshotError(source + ": not a dem snapshot (the bytes are not a serialized dem.proto.Snapshot)");
  }
  if (message.format() != kSnapshotFormat) {
    throw SnapshotError(source + ": not a dem snapshot (no \"" + kSnapshotFormat + "\" format tag)");
  }
  return message;
}

template <int Dim>
LoadedSnapshotT<Dim> parse_snapshot(std::string_view bytes, std::string_view source_name,
                                    const ResourceLimits& limits) {
  const proto::Snapshot message = parse_snapshot_message(bytes, source_name);
  LoadedSnapshotT<Dim> loaded;
  try {
    loaded.snapshot = snapshot_from_proto<Dim>(message, &loaded.info, limits);
  } catch (const SnapshotError& error) {
    throw SnapshotError(std::string(source_name) + ": " + error.what());
  }
  return loaded;
}

void write_snapshot_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::error_code error;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), error);
  std::filesystem::path temporary = path;
  temporary += ".partial";
  const auto fail = [&](const std::string& why) {
    ::unlink(temporary.c_str());
    throw SnapshotError(path.string() + ": cannot write the snapshot: " + why);
  };
  // Not through a link planted where the temporary file goes.
  const int file = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (file < 0) throw SnapshotError(path.string() + ": cannot write the snapshot: " + std::strerror(errno));
  for (std::size_t written = 0; written < bytes.size();) {
    const ssize_t n = ::write(file, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = std::strerror(errno);
      ::close(file);
      fail(why);
    }
    written += static_cast<std::size_t>(n);
  }
  // On disk before the rename makes it the snapshot: a crash leaves the old
  // file or the new one, never a torn one.
  if (::fsync(file) != 0 || ::close(file) != 0) fail(std::strerror(errno));
  std::filesystem::rename(temporary, path, error);
  if (error) fail(error.message());
  const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
  const int dir = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);  // the rename itself
    ::close(dir);
  }
}

std::string read_snapshot_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SnapshotError(path.string() + ": cannot read the snapshot: " + std::strerror(errno));
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw SnapshotError(path.string() + ": cannot read the snapshot: " + std::strerror(errno));
  return bytes;
}

template std::string serialize_snapshot<2>(const WorldSnapshotT<2>&, const SnapshotInfo&);
template std::string serialize_snapshot<3>(const WorldSnapshotT<3>&, const SnapshotInfo&);
template LoadedSnapshotT<2> parse_snapshot<2>(std::string_view, std::string_view, const ResourceLimits&);
template LoadedSnapshotT<3> parse_snapshot<3>(std::string_view, std::string_view, const ResourceLimits&);

}  // namespace dem::io
