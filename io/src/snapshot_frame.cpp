#include "dem/io/snapshot_frame.h"

#include <openssl/evp.h>

#include <array>
#include <cstdint>
#include <stdexcept>

#include "dem/io/snapshot_conversion.h"

namespace dem::io {
namespace {

void put_u64(std::string& out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
}

std::uint64_t get_u64(std::string_view in) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(in[static_cast<std::size_t>(i)]);
  return value;
}

}  // namespace

std::string sha256(std::string_view bytes) {
  std::array<unsigned char, 32> digest{};
  unsigned int size = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest.data(), &size, EVP_sha256(), nullptr) != 1 || size != 32) {
    throw std::runtime_error("SHA-256 failed (OpenSSL)");
  }
  return std::string(reinterpret_cast<const char*>(digest.data()), digest.size());
}

std::string frame_snapshot(std::string_view payload) {
  std::string framed;
  framed.reserve(kSnapshotHeaderSize + payload.size());
  framed += kSnapshotMagic;
  put_u64(framed, payload.size());
  framed += sha256(payload);
  framed += payload;
  return framed;
}

std::string_view unframe_snapshot(std::string_view bytes, std::string_view source) {
  const std::string name(source);
  if (bytes.size() < kSnapshotHeaderSize || bytes.substr(0, kSnapshotMagic.size()) != kSnapshotMagic) {
    throw SnapshotError(name + ": not a dem snapshot (it does not start with the \"" + std::string(kSnapshotMagic) +
                        "\" header; snapshots written before the header was added must be saved again)");
  }
  const std::uint64_t length = get_u64(bytes.substr(8, 8));
  const std::string_view payload = bytes.substr(kSnapshotHeaderSize);
  if (length > payload.size()) {
    throw SnapshotError(name + ": truncated: its header promises " + std::to_string(length) + " bytes of snapshot, " +
                        std::to_string(payload.size()) + " follow");
  }
  if (length < payload.size()) {
    throw SnapshotError(name + ": " + std::to_string(payload.size() - length) +
                        " bytes follow the snapshot its header describes (" + std::to_string(length) + " bytes)");
  }
  if (sha256(payload) != bytes.substr(16, 32)) {
    throw SnapshotError(name + ": corrupt: its SHA-256 checksum does not match its contents");
  }
  return payload;
}

}  // namespace dem::io
