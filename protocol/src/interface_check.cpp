#include "dem/protocol/interface_check.h"

#include <algorithm>

#include "dem/protocol/interface_version.h"

namespace dem::protocol {

using Kind = PeerVerdict::Kind;

std::string_view type_hash_of(std::string_view type_name) {
  const auto found =
      std::find_if(kTypeHashes.begin(), kTypeHashes.end(), [&](const TypeHash& t) { return t.type_name == type_name; });
  return found == kTypeHashes.end() ? std::string_view() : found->hash;
}

std::string endpoint_user_data(std::string_view type_name) {
  const std::string_view hash = type_hash_of(type_name);
  if (hash.empty()) return {};
  return "typehash=" + std::string(hash) + ";dem_interfaces=" + std::string(kInterfaceVersion) + ";";
}

std::string_view peer_type_hash(std::string_view user_data) {
  // ROS 2's form: "key=value;" pairs; the hash is "typehash=RIHS01_<64 hex>".
  constexpr std::string_view kKey = "typehash=";
  for (std::size_t at = 0; at < user_data.size();) {
    const std::size_t end = std::min(user_data.find(';', at), user_data.size());
    const std::string_view pair = user_data.substr(at, end - at);
    if (pair.starts_with(kKey)) return pair.substr(kKey.size());
    at = end + 1;
  }
  return {};
}

namespace {

// "Command_" of "dem_interfaces::msg::dds_::Command_", as the .msg names it: "Command".
std::string_view message_name(std::string_view type_name) {
  std::string_view name = type_name.substr(type_name.rfind(':') + 1);
  if (name.ends_with('_')) name.remove_suffix(1);
  return name;
}

std::string_view peer_version(std::string_view user_data) {
  constexpr std::string_view kKey = "dem_interfaces=";
  const std::size_t at = user_data.find(kKey);
  if (at == std::string_view::npos) return {};
  const std::string_view rest = user_data.substr(at + kKey.size());
  return rest.substr(0, rest.find(';'));
}

}  // namespace

namespace {

PeerVerdict judged(const dds::Endpoint& peer, std::string_view self);

}  // namespace

PeerVerdict judge_peer(const dds::Endpoint& peer, std::string_view self) {
  PeerVerdict verdict = judged(peer, self);
  verdict.peer = peer;
  return verdict;
}

namespace {

PeerVerdict judged(const dds::Endpoint& peer, std::string_view self) {
  const std::string_view ours = type_hash_of(peer.type_name);
  if (ours.empty()) return {};
  const std::string_view theirs = peer_type_hash(peer.user_data);
  const std::string_view name = message_name(peer.type_name);
  const std::string role = peer.writer ? "a writer" : "a reader";
  const std::string where = std::string(peer.topic_name) + ": " + role + " of " + std::string(name);
  const std::string mine = std::string(self) + " (dem_interfaces " + std::string(kInterfaceVersion) + ")";
  if (theirs.empty()) {
    return {Kind::kNoTypeHash, where +
                                   " declares no type hash (dem before 0.2.0, ROS 2 before Iron, or another "
                                   "DDS program): whether its " +
                                   std::string(name) + " is " + mine + "'s cannot be checked"};
  }
  if (theirs == ours) return {Kind::kSame, where + " of " + mine + "'s form"};
  const auto older = std::find_if(kOlderForms.begin(), kOlderForms.end(), [&](const OlderForm& f) {
    return f.type_name == peer.type_name && f.hash == theirs;
  });
  const std::string_view version = peer_version(peer.user_data);
  const std::string from = version.empty() ? std::string() : " (it says dem_interfaces " + std::string(version) + ")";
  if (older == kOlderForms.end()) {
    return {Kind::kUnknownForm, where + " built from other message files than " + mine + ": type hash " +
                                    std::string(theirs) + from + ", no recorded version of dem_interfaces; " +
                                    "their samples will not deserialize on either side"};
  }
  const std::string built = where + " built from dem_interfaces " + std::string(older->versions) + from + ", whose " +
                            std::string(name) + " " + std::string(older->difference);
  // The peer reads what this side writes, or writes what this side reads.
  const bool meets = peer.writer ? older->read_by_current : older->reads_current;
  if (meets) {
    return {Kind::kOlderCompatible, built + ": " + mine + (peer.writer ? " reads" : " is read by") +
                                        " it still (the fields it lacks are at the end)"};
  }
  return {Kind::kIncompatible, built + ": " +
                                   (peer.writer ? "its samples cannot be read by " + mine + " and are dropped"
                                                : "it cannot read the samples of " + mine) +
                                   "; rebuild it from dem_interfaces " + std::string(kInterfaceVersion)};
}

}  // namespace

}  // namespace dem::protocol
