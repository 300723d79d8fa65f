// The frame around a serialized snapshot, in files and in transfers alike:
// a header with the payload's length and SHA-256, so any corruption (a
// flipped byte, a truncated copy, bytes appended) is refused before a
// byte of it is believed, rather than loaded as a different state.
//
//   offset  size  content
//        0     8  "DEMSNAP1"  (magic; the last byte is the frame's version)
//        8     8  payload length, little-endian
//       16    32  SHA-256 of the payload
//       48     n  the serialized dem.proto.Snapshot
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace dem::io {

inline constexpr std::string_view kSnapshotMagic = "DEMSNAP1";
inline constexpr std::size_t kSnapshotHeaderSize = 48;

// The payload with its header in front.
std::string frame_snapshot(std::string_view payload);

// The payload, once the header's length and checksum match it. Throws
// SnapshotError "<source>: ..." naming what is wrong (no header, truncated,
// trailing bytes, checksum mismatch).
std::string_view unframe_snapshot(std::string_view bytes, std::string_view source);

// SHA-256 of the bytes (32 bytes), for the frame and its tests.
std::string sha256(std::string_view bytes);

}  // namespace dem::io
