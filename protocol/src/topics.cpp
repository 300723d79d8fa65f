#include "dem/protocol/topics.h"

#include <cctype>

namespace dem::protocol {

namespace {
constexpr std::string_view kPrefix = "rt/dem/";
constexpr std::string_view kStatusSuffix = "/status";
}  // namespace

std::string topics_of(std::string_view server) { return std::string(kPrefix) + std::string(server) + "/"; }

std::string topic_name(std::string_view server, TopicKind kind) {
  std::string name(kPrefix);
  name += server;
  switch (kind) {
    case TopicKind::kCommand:
      return name + "/command";
    case TopicKind::kReply:
      return name + "/reply";
    case TopicKind::kStatus:
      return name + std::string(kStatusSuffix);
    case TopicKind::kPlateForces:
      return name + "/plate_forces";
    case TopicKind::kContactStats:
      return name + "/contact_stats";
    case TopicKind::kRegionMeasures:
      return name + "/region_measures";
    case TopicKind::kNameClaim:
      return name + "/_name_claim";
  }
  return name;
}

std::string reply_partition(std::string_view client_id) {
  std::string name = "dem_reply_";
  for (const char c : client_id) {
    name += std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.' ? c : '_';
  }
  return name;
}

bool valid_server_name(std::string_view name) {
  if (name.empty() || name.size() > 64 || std::isalpha(static_cast<unsigned char>(name.front())) == 0) return false;
  for (const char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_') return false;
  }
  return true;
}

std::optional<std::string> server_of_status_topic(std::string_view topic) {
  if (!topic.starts_with(kPrefix) || !topic.ends_with(kStatusSuffix)) return std::nullopt;
  const std::string_view server = topic.substr(kPrefix.size(), topic.size() - kPrefix.size() - kStatusSuffix.size());
  if (!valid_server_name(server)) return std::nullopt;
  return std::string(server);
}

}  // namespace dem::protocol
