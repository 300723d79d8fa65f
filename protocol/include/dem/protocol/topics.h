// Topic and type names on the wire, in ROS 2's conventions (docs/DDS.md):
// topics "rt/dem/<server>/<name>" (the ROS 2 topic /dem/<server>/<name>),
// types "dem_interfaces::msg::dds_::<Type>_".
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace dem::protocol {

enum class TopicKind { kCommand, kReply, kStatus, kPlateForces, kContactStats, kRegionMeasures, kNameClaim };

// "rt/dem/<server>/command", ".../reply", ".../status", ".../plate_forces", ".../contact_stats",
// ".../region_measures", ".../_name_claim" (a server's claim to its name, a writer that never
// writes: service/name_claim.h; hidden from `ros2 topic list` by the leading underscore, as ROS 2
// hides such names).
std::string topic_name(std::string_view server, TopicKind kind);
// "rt/dem/<server>/": what every topic of the server begins with.
std::string topics_of(std::string_view server);

// The partition of a client's own replies, "dem_reply_<client_id>" (a
// character other than a letter, digit, '_', '-' or '.' as '_', so no name
// is a DDS partition pattern): the server writes a client's replies in it
// once the client's reader is there, so a client receives no other
// client's replies (docs/DDS.md, "Replies").
std::string reply_partition(std::string_view client_id);

// A server name is one ROS 2 name token: a letter, then letters, digits and
// underscores (at most 64 characters), so every topic name is a valid ROS 2 name.
bool valid_server_name(std::string_view name);

// The server whose status topic this is, if it is one.
std::optional<std::string> server_of_status_topic(std::string_view topic_name);

inline constexpr std::string_view kStatusTypeName = "dem_interfaces::msg::dds_::Status_";

}  // namespace dem::protocol
