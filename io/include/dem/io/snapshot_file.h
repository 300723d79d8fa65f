// Snapshots as bytes and files: the serialized dem.proto.Snapshot that
// dem_server saves, sends and loads, in its checksummed frame
// (snapshot_frame.h).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "dem/io/snapshot_conversion.h"

namespace dem::io {

template <int Dim>
struct LoadedSnapshotT {
  WorldSnapshotT<Dim> snapshot;
  SnapshotInfo info;
};
using LoadedSnapshot = LoadedSnapshotT<2>;

template <int Dim>
std::string serialize_snapshot(const WorldSnapshotT<Dim>& snapshot, const SnapshotInfo& info);

// Checks the frame and parses its payload into a message with the snapshot
// format tag, so a caller can look at its dimension before converting it.
// Throws SnapshotError "<source_name>: not a dem snapshot ...", "... corrupt
// ..." or "... truncated ..." otherwise.
proto::Snapshot parse_snapshot_message(std::string_view bytes, std::string_view source_name = "<bytes>");

// parse_snapshot_message and snapshot_from_proto<Dim>; every error names the source.
template <int Dim = 2>
LoadedSnapshotT<Dim> parse_snapshot(std::string_view bytes, std::string_view source_name = "<bytes>",
                                    const ResourceLimits& limits = machine_limits());

// Writes through a temporary file (never through a link in its place),
// flushed to disk (fsync) and renamed into place, so a reader - or a
// restart after a crash - never sees half a snapshot; creates the
// directory. Throws SnapshotError naming the file when it cannot be written.
void write_snapshot_bytes(const std::filesystem::path& path, std::string_view bytes);
template <int Dim>
void write_snapshot_file(const std::filesystem::path& path, const WorldSnapshotT<Dim>& snapshot,
                         const SnapshotInfo& info) {
  write_snapshot_bytes(path, serialize_snapshot(snapshot, info));
}

// The file's bytes; throws SnapshotError naming the file when it cannot be read.
std::string read_snapshot_bytes(const std::filesystem::path& path);
template <int Dim = 2>
LoadedSnapshotT<Dim> read_snapshot_file(const std::filesystem::path& path) {
  return parse_snapshot<Dim>(read_snapshot_bytes(path), path.string());
}

extern template std::string serialize_snapshot<2>(const WorldSnapshotT<2>&, const SnapshotInfo&);
extern template std::string serialize_snapshot<3>(const WorldSnapshotT<3>&, const SnapshotInfo&);
extern template LoadedSnapshotT<2> parse_snapshot<2>(std::string_view, std::string_view, const ResourceLimits&);
extern template LoadedSnapshotT<3> parse_snapshot<3>(std::string_view, std::string_view, const ResourceLimits&);

}  // namespace dem::io
