#include "global.h"

#include <algorithm>
#include <cctype>
#include <iostream>

namespace demctl {

using namespace std::chrono_literals;

std::chrono::milliseconds milliseconds(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(seconds * 1000.0));
}

bool in_sweep(const std::string& server, const std::string& sweep) {
  if (server.size() <= sweep.size() + 1 || server.compare(0, sweep.size(), sweep) != 0 || server[sweep.size()] != '_') {
    return false;
  }
  return std::all_of(server.begin() + static_cast<std::ptrdiff_t>(sweep.size()) + 1, server.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

dem::client::ConnectOptions connect_options(const Global& global) {
  dem::client::ConnectOptions options;
  options.server = global.server;
  options.domain = global.domain;
  options.dds_config = global.dds_config;
  options.timeout = milliseconds(global.timeout);
  options.reply_timeout = std::max(milliseconds(global.timeout), std::chrono::milliseconds(60s));
  // A server whose interface is an older form, or whose telemetry this
  // demctl cannot read, is said on stderr (commands work: it answered).
  options.on_interface_note = [](const std::string& note) { std::cerr << "demctl: note: " << note << '\n'; };
  return options;
}

}  // namespace demctl
