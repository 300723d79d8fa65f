#include "commands.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "csv.h"
#include "dem/cli/duration.h"
#include "dem/cli/interrupt.h"
#include "dem/client/errors.h"
#include "dem/client/local_file.h"
#include "exit_codes.h"
#include "json.h"

namespace demctl {

using dem::client::Client;
using dem::protocol::Reply;
using dem::protocol::Status;
using namespace std::chrono_literals;

namespace {

Client connect(const Global& global) { return Client(connect_options(global)); }

void print(const Reply& reply) { std::cout << reply.message << '\n'; }

// A progress bar on stderr, drawn only for a person (a terminal): the
// share done, the rate in cycles per second (averaged over the last few
// status updates) and, for a cycle command, the time left at that rate;
// "at most" that for run-until, which may end before its cap. A programme
// shows its stage and how far the stage is (the server's status: a plate's
// stress against its target, or the cycles of a fixed stage), with no time
// left - its caps are bounds, millions of cycles beyond where a stress
// target ends it.
class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled && isatty(STDERR_FILENO) == 1) {}
  ~ProgressBar() { clear(); }
  void show(const Status& s) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (seen_ && s.command_cycles_done > last_cycles_ && now > last_) {
      const double rate = static_cast<double>(s.command_cycles_done - last_cycles_) /
                          std::chrono::duration<double>(now - last_).count();
      rate_ = rate_ > 0.0 ? 0.7 * rate_ + 0.3 * rate : rate;
    }
    if (!seen_ || s.command_cycles_done != last_cycles_) {
      seen_ = true;
      last_ = now;
      last_cycles_ = s.command_cycles_done;
    }
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(s.progress * kWidth + 0.5);
    const bool programme = s.command == "run_programme" || s.command == "programme";
    char pace[96] = "";
    if (rate_ > 0.0 && !programme) {
      const auto left =
          s.command_cycles_total > s.command_cycles_done ? s.command_cycles_total - s.command_cycles_done : 0;
      std::snprintf(pace, sizeof pace, ", %.0f cycles/s, %s%s left", rate_, s.command == "cycle" ? "" : "at most ",
                    dem::cli::duration_text(static_cast<double>(left) / rate_).c_str());
    } else if (rate_ > 0.0) {
      std::snprintf(pace, sizeof pace, ", %.0f cycles/s", rate_);
    }
    const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '-');
    char line[512];
    if (programme) {
      std::snprintf(line, sizeof line, "[%s] %3.0f%%  %s, cycle %llu%s", bar.c_str(), 100.0 * s.progress,
                    s.message.c_str(), static_cast<unsigned long long>(s.cycle), pace);
    } else {
      std::snprintf(line, sizeof line, "[%s] %3.0f%%  cycle %llu, %llu of %llu%s", bar.c_str(), 100.0 * s.progress,
                    static_cast<unsigned long long>(s.cycle), static_cast<unsigned long long>(s.command_cycles_done),
                    static_cast<unsigned long long>(s.command_cycles_total), pace);
    }
    // Erased to the line's end: the line before may have been longer.
    std::fprintf(stderr, "\r%s\033[K", line);
    std::fflush(stderr);
    shown_ = true;
  }
  void clear() {
    if (!shown_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    shown_ = false;
  }

 private:
  bool enabled_;
  bool shown_ = false;
  bool seen_ = false;  // a status of this run was shown
  std::chrono::steady_clock::time_point last_{};
  std::uint64_t last_cycles_ = 0;
  double rate_ = 0.0;
};

bool runs(const Status& status, const Client& client, std::uint64_t request) {
  return status.state == dem::protocol::ServerState::kRunning && status.command_client == client.client_id() &&
         status.command_request_id == request;
}

// A cycle, run_until or run_programme just sent: with `wait`, shows progress until its
// reply (Ctrl-C stops the run); without, returns once the server has
// accepted it (it shows in the status) or refused it (a reply).
int follow_run(const Global& global, Client& client, std::uint64_t request, bool wait, bool until = false) {
  if (!wait) {
    const auto deadline = std::chrono::steady_clock::now() + milliseconds(global.timeout);
    while (std::chrono::steady_clock::now() < deadline) {
      if (std::optional<Reply> reply = client.await(request, 20ms)) {
        if (!reply->ok()) throw dem::client::ServerError(std::move(*reply));
        print(*reply);
        return kOk;
      }
      const Status status = client.status();
      if (runs(status, client, request)) {
        std::cout << "accepted: " << status.command << " of up to " << status.command_cycles_total
                  << " cycles from cycle " << status.cycle << " (request " << request << ")\n";
        return kOk;
      }
    }
    throw dem::client::ReplyTimeout("server \"" + global.server + "\" neither accepted nor refused the run in time");
  }
  ProgressBar bar(!global.quiet);
  for (;;) {
    if (std::optional<Reply> reply = client.await(request, 100ms)) {
      bar.clear();
      if (!reply->ok()) throw dem::client::ServerError(std::move(*reply));
      print(*reply);
      if (until && !reply->condition_met) {
        std::cerr << "run-until: the cycle cap (" << reply->cycles_run << " cycles) came before the condition\n";
        return kConditionNotMet;
      }
      return kOk;
    }
    if (dem::cli::interrupted()) {
      bar.clear();
      std::cerr << "interrupted: stopping the run\n";
      client.stop();
      if (std::optional<Reply> reply = client.await(request, milliseconds(global.timeout))) print(*reply);
      return kInterrupted;
    }
    if (!client.server_alive()) throw dem::client::ReplyTimeout("server \"" + global.server + "\" went away");
    const Status status = client.status();
    if (runs(status, client, request)) bar.show(status);
  }
}

double number(const std::string& text, const std::string& what) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    throw BadArguments(what + ": \"" + text + "\" is not a number");
  }
  return value;
}

}  // namespace

int servers(const Global& global, double discovery, const std::string& sweep) {
  auto found = dem::client::list_servers(global.domain, global.dds_config, milliseconds(discovery));
  if (!sweep.empty()) {
    std::erase_if(found, [&](const auto& server) { return !in_sweep(server.name, sweep); });
  }
  if (found.empty()) {
    std::cout << "no servers" << (sweep.empty() ? "" : " of sweep " + sweep) << " on DDS domain " << global.domain
              << '\n';
    return kOk;
  }
  std::printf("%-20s %-9s %-28s %12s %14s\n", "SERVER", "STATE", "CASE", "CYCLE", "TIME");
  for (const auto& server : found) {
    if (!server.status) {
      std::printf("%-20s (no status yet)\n", server.name.c_str());
      continue;
    }
    const Status& s = *server.status;
    std::printf("%-20s %-9s %-28s %12llu %14.6g\n", server.name.c_str(),
                std::string(dem::protocol::to_string(s.state)).c_str(), s.case_name.c_str(),
                static_cast<unsigned long long>(s.cycle), s.time);
  }
  return kOk;
}

int status(const Global& global, bool json) {
  Client client = connect(global);
  const Reply reply = client.get_state();
  if (json) {
    std::cout << state_json(reply) << '\n';
    return kOk;
  }
  const Status& s = reply.state;
  std::cout << "server     " << s.server << "\nstate      " << dem::protocol::to_string(s.state) << '\n';
  if (!s.case_name.empty()) {
    std::cout << "case       " << s.case_name << " (" << static_cast<int>(s.dimension) << "D, " << s.particles
              << " particles, " << s.walls << " walls)\ncycle      " << s.cycle << "\ntime       " << s.time
              << " s\ntime step  " << s.time_step << " s\n";
  }
  if (!s.command.empty()) {
    std::cout << "running    " << s.command << " " << s.command_cycles_done << " of " << s.command_cycles_total
              << " cycles (request " << s.command_request_id << " from " << s.command_client << ")\n";
  }
  std::cout << "message    " << s.message << "\nserved     " << s.commands_served << " commands\n";
  for (const auto& wall : reply.plates.walls) {
    std::printf("wall %-16s stress %12.5g Pa  settlement %12.5g m  contacts %d\n", wall.name.c_str(),
                wall.normal_stress, wall.settlement, wall.contacts);
  }
  if (!s.case_name.empty()) {
    const auto& stats = reply.stats;
    std::printf("contacts   %d (%.1f%% sliding), coordination %.3f, kinetic energy %.5g J, out-of-balance %.3g\n",
                stats.contacts, 100.0 * stats.sliding_fraction, stats.coordination_number, stats.kinetic_energy,
                stats.out_of_balance);
  }
  return kOk;
}

int load(const Global& global, const std::string& file, bool on_server, bool binary) {
  Client client = connect(global);
  if (on_server) {
    print(client.load_case_on_server(file));
  } else if (binary) {
    print(client.load_case_binary(dem::client::read_local_file(file), file));
  } else {
    print(client.load_case_file(file));
  }
  return kOk;
}

int wall_velocity(const Global& global, const std::string& wall, const std::vector<double>& values) {
  if (values.size() < 2 || values.size() > 4) throw BadArguments("wall-velocity takes VX VY [VZ] [OMEGA]");
  const dem::protocol::Vector3 velocity{values[0], values[1], values.size() > 2 ? values[2] : 0.0};
  const dem::protocol::Vector3 angular{0.0, 0.0, values.size() > 3 ? values[3] : 0.0};
  print(connect(global).set_wall_velocity(wall, velocity, angular));
  return kOk;
}

int servo(const Global& global, const std::string& wall, double stress, double gain, double max_speed) {
  print(connect(global).set_wall_servo(wall, stress, gain, max_speed));
  return kOk;
}

int cycle(const Global& global, std::int64_t cycles, bool wait) {
  if (cycles <= 0) throw BadArguments("cycle: N must be > 0, got " + std::to_string(cycles));
  Client client = connect(global);
  return follow_run(global, client, client.start_cycle(cycles), wait);
}

int run_programme(const Global& global, std::uint32_t first_stage, std::uint32_t stage_count, bool wait) {
  Client client = connect(global);
  return follow_run(global, client, client.start_run_programme(first_stage, stage_count), wait);
}

int run_until(const Global& global, const dem::protocol::RunUntilArgs& args, bool wait) {
  if (args.max_cycles <= 0) throw BadArguments("run-until: --max-cycles must be > 0");
  if (!args.stress && !args.settlement && !args.kinetic_energy) {
    throw BadArguments("run-until needs --stress, --settlement or --kinetic-energy");
  }
  if ((args.stress || args.settlement) && args.wall.empty()) {
    throw BadArguments("run-until: --stress and --settlement need --wall");
  }
  Client client = connect(global);
  return follow_run(global, client, client.start_run_until(args), wait, true);
}

int stop(const Global& global, bool force) {
  print(connect(global).stop(force));
  return kOk;
}

namespace {

// contacts --csv writes the columns of the server's contacts.csv
// (io/src/csv_writers.cpp) from the wire's fields (ContactEntry, generated
// from the IDL): the bodies as first, second_kind, second, then a column per
// number or flag and three per vector, so a field added to the IDL is a
// column here. The vectors keep contacts.csv's short names (x, nx,
// tangential_x); any other is <name>_x.
bool is_body(std::string_view field) {
  return field == "first" || field == "second_particle" || field == "second_wall";
}

std::string axis_stem(std::string_view field) {
  if (field == "point") return "";
  if (field == "normal") return "n";
  if (field == "tangential_force") return "tangential_";
  return std::string(field) + "_";
}

std::string contact_columns() {
  std::string header = "first,second_kind,second";
  std::apply(
      [&](const auto&... f) {
        const auto columns = [&](const auto& field) {
          if (is_body(field.name)) return;
          using T = std::remove_cvref_t<decltype(dem::protocol::ContactEntry{}.*field.member)>;
          if constexpr (std::is_same_v<T, dem::protocol::Vector3>) {
            for (const char axis : {'x', 'y', 'z'}) {
              header += ',';
              header += axis_stem(field.name);
              header += axis;
            }
          } else {
            header += ",";
            header += field.name;
          }
        };
        (columns(f), ...);
      },
      dem::protocol::Fields<dem::protocol::ContactEntry>::list);
  return header;
}

void add_contact_cells(std::string& line, const dem::protocol::ContactEntry& c) {
  std::apply(
      [&](const auto&... f) {
        const auto cells = [&](const auto& field) {
          if (is_body(field.name)) return;
          const auto& value = c.*field.member;
          if constexpr (std::is_same_v<std::remove_cvref_t<decltype(value)>, dem::protocol::Vector3>) {
            for (const double v : {value.x, value.y, value.z}) CsvWriter::add(line, v);
          } else {
            CsvWriter::add(line, value);
          }
        };
        (cells(f), ...);
      },
      dem::protocol::Fields<dem::protocol::ContactEntry>::list);
}

}  // namespace

int contacts(const Global& global, const dem::protocol::ContactQueryArgs& query, const std::string& csv, int limit) {
  Client client = connect(global);
  const Reply reply = client.query_contacts(query);
  // Walls by name, as in the server's own tables.
  std::map<std::int32_t, std::string> wall_names;
  if (std::any_of(reply.contacts.begin(), reply.contacts.end(), [](const auto& c) { return c.second_wall >= 0; })) {
    for (const auto& wall : client.get_state().plates.walls) wall_names[wall.id] = wall.name;
  }
  const auto second = [&](const dem::protocol::ContactEntry& c) {
    return c.second_wall >= 0 ? wall_names[c.second_wall] : std::to_string(c.second_particle);
  };
  std::cout << reply.message << '\n';
  if (!csv.empty()) {
    CsvWriter out(csv, contact_columns());
    for (const auto& c : reply.contacts) {
      std::string line;
      CsvWriter::add(line, c.first);
      CsvWriter::add(line, c.second_wall >= 0 ? "wall" : "particle");
      CsvWriter::add(line, second(c));
      add_contact_cells(line, c);
      out.built_row(std::move(line));
    }
    std::cout << "wrote " << csv << '\n';
  }
  const int shown = std::min<int>(limit, static_cast<int>(reply.contacts.size()));
  if (shown > 0) {
    std::printf("%8s %10s %14s %14s %14s %14s %8s\n", "first", "second", "x", "y", "normal_force", "shear_force",
                "sliding");
    for (int i = 0; i < shown; ++i) {
      const auto& c = reply.contacts[static_cast<std::size_t>(i)];
      std::printf("%8d %10s %14.6g %14.6g %14.6g %14.6g %8s\n", c.first, second(c).c_str(), c.point.x, c.point.y,
                  c.normal_force, c.shear_force, c.sliding ? "yes" : "no");
    }
    if (shown < static_cast<int>(reply.contacts.size())) {
      std::cout << "... " << reply.contacts.size() - static_cast<std::size_t>(shown)
                << " more (--limit N to show more, --csv FILE for all)\n";
    }
  }
  return kOk;
}

int snapshot_save(const Global& global, const std::string& file, bool on_server) {
  Client client = connect(global);
  if (on_server) {
    print(client.save_snapshot(file, false));
    return kOk;
  }
  const Reply reply = client.save_snapshot({}, true);
  const std::string temporary = file + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reply.data.data(), static_cast<std::streamsize>(reply.data.size()));
    if (!out) throw std::runtime_error("cannot write " + file);
  }
  if (std::rename(temporary.c_str(), file.c_str()) != 0) throw std::runtime_error("cannot write " + file);
  std::cout << "saved snapshot at cycle " << reply.state.cycle << " to " << file << " (" << reply.data.size()
            << " bytes)\n";
  return kOk;
}

int snapshot_load(const Global& global, const std::string& file, bool on_server) {
  Client client = connect(global);
  print(on_server ? client.load_snapshot_on_server(file)
                  : client.load_snapshot_bytes(dem::client::read_local_file(file)));
  return kOk;
}

int set(const Global& global, const std::string& parameter, const std::string& value) {
  Client client = connect(global);
  if (parameter == "gravity") {
    std::vector<double> components;
    std::stringstream parts(value);
    for (std::string part; std::getline(parts, part, ',');) components.push_back(number(part, "gravity"));
    if (components.size() < 2 || components.size() > 3) throw BadArguments("gravity: give GX,GY or GX,GY,GZ");
    print(client.set_gravity({components[0], components[1], components.size() > 2 ? components[2] : 0.0}));
    return kOk;
  }
  std::string name = parameter;
  std::string material;
  if (const auto dot = parameter.find('.'); dot != std::string::npos) {
    name = parameter.substr(0, dot);
    material = parameter.substr(dot + 1);
  }
  if (name == "friction" && material.empty()) throw BadArguments("friction is set per material: friction.MATERIAL");
  print(client.set_parameter(name, number(value, parameter), material));
  return kOk;
}

int shutdown(const Global& global, bool wait, bool force) {
  Client client = connect(global);
  print(client.shutdown(force));
  if (!wait) return kOk;
  // The server is gone when its status writer is.
  const auto deadline = std::chrono::steady_clock::now() + std::max(milliseconds(global.timeout), 10000ms);
  while (client.server_alive()) {
    if (std::chrono::steady_clock::now() > deadline) {
      throw dem::client::ReplyTimeout("server \"" + global.server + "\" did not stop in time");
    }
    std::this_thread::sleep_for(20ms);
  }
  std::cout << "server " << global.server << " stopped\n";
  return kOk;
}

}  // namespace demctl
