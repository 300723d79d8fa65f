#include "json.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <type_traits>

namespace demctl {
namespace {

using dem::protocol::Stamp;
using dem::protocol::Vector3;

// A tiny writer: members separated by commas, strings escaped (RFC 8259),
// numbers in the shortest form that reads back to the same double.
class Json {
 public:
  Json& begin() {
    separate();
    text_ += '{';
    first_ = true;
    return *this;
  }
  Json& end() {
    text_ += '}';
    first_ = false;
    return *this;
  }
  Json& begin_array() {
    separate();
    text_ += '[';
    first_ = true;
    return *this;
  }
  Json& end_array() {
    text_ += ']';
    first_ = false;
    return *this;
  }
  Json& key(const char* name) {
    separate();
    string(name);
    text_ += ':';
    first_ = true;  // the value follows without a comma
    return *this;
  }
  Json& value(double number) {
    separate();
    if (!std::isfinite(number)) {
      text_ += "null";  // JSON has no NaN or infinity
    } else {
      std::array<char, 32> buffer{};
      text_.append(buffer.data(), std::to_chars(buffer.data(), buffer.data() + buffer.size(), number).ptr);
    }
    return *this;
  }
  template <typename Integer>
  requires std::is_integral_v<Integer> Json& value(Integer number) {
    separate();
    if constexpr (std::is_same_v<Integer, bool>) {
      text_ += number ? "true" : "false";
    } else {
      text_ += std::to_string(static_cast<std::conditional_t<std::is_signed_v<Integer>, long long, unsigned long long>>(number));
    }
    return *this;
  }
  Json& value(const std::string& text) {
    separate();
    string(text);
    return *this;
  }
  Json& value(const Vector3& v) { return begin().key("x").value(v.x).key("y").value(v.y).key("z").value(v.z).end(); }
  Json& value(const Stamp& s) { return begin().key("sec").value(s.sec).key("nanosec").value(s.nanosec).end(); }
  template <typename T>
  Json& field(const char* name, const T& v) {
    return key(name).value(v);
  }
  std::string text() const { return text_; }

 private:
  void separate() {
    if (!first_) text_ += ',';
    first_ = false;
  }
  void string(std::string_view s) {
    text_ += '"';
    for (const char c : s) {
      if (c == '"' || c == '\\') {
        text_ += '\\';
        text_ += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
        text_ += escaped;
      } else {
        text_ += c;
      }
    }
    text_ += '"';
  }

  std::string text_;
  bool first_ = true;
};

}  // namespace

std::string state_json(const dem::protocol::Reply& reply) {
  const dem::protocol::Status& s = reply.state;
  Json json;
  json.begin().key("status").begin();
  json.field("server", s.server).field("state", static_cast<int>(s.state))
      .field("state_name", std::string(dem::protocol::to_string(s.state))).field("case_name", s.case_name)
      .field("dimension", static_cast<int>(s.dimension)).field("particles", s.particles).field("walls", s.walls)
      .field("cycle", s.cycle).field("time", s.time).field("time_step", s.time_step).field("command", s.command)
      .field("command_client", s.command_client).field("command_request_id", s.command_request_id)
      .field("command_cycles_done", s.command_cycles_done).field("command_cycles_total", s.command_cycles_total)
      .field("progress", s.progress).field("message", s.message).field("commands_served", s.commands_served)
      .field("telemetry_dropped", s.telemetry_dropped).field("stamp", s.stamp);
  json.end();

  const dem::protocol::PlateForces& p = reply.plates;
  json.key("plates").begin();
  json.field("server", p.server).field("cycle", p.cycle).field("time", p.time).field("stamp", p.stamp);
  json.key("walls").begin_array();
  for (const dem::protocol::WallForce& w : p.walls) {
    json.begin().field("name", w.name).field("id", w.id).field("force", w.force).field("moment", w.moment)
        .field("normal_force", w.normal_force).field("area", w.area).field("normal_stress", w.normal_stress)
        .field("position", w.position).field("displacement", w.displacement).field("settlement", w.settlement)
        .field("contacts", w.contacts).end();
  }
  json.end_array().end();

  const dem::protocol::ContactStats& c = reply.stats;
  json.key("stats").begin();
  json.field("server", c.server).field("cycle", c.cycle).field("time", c.time).field("stamp", c.stamp)
      .field("particles", c.particles).field("contacts", c.contacts).field("wall_contacts", c.wall_contacts)
      .field("sliding_contacts", c.sliding_contacts).field("sliding_fraction", c.sliding_fraction)
      .field("coordination_number", c.coordination_number).field("mean_normal_force", c.mean_normal_force)
      .field("max_normal_force", c.max_normal_force).field("histogram_bin_width", c.histogram_bin_width);
  json.key("histogram").begin_array();
  for (const std::uint32_t count : c.histogram) json.value(count);
  json.end_array();
  json.field("kinetic_energy", c.kinetic_energy).field("out_of_balance", c.out_of_balance);
  json.end();

  json.field("state_hash", reply.state_hash).end();
  return json.text();
}

}  // namespace demctl
