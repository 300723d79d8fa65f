// demctl monitor: a live table of plate stress against settlement and the
// contact statistics, one row per telemetry sample (plate forces and
// contact statistics of the same cycle), until Ctrl-C or N rows - of one
// server, or of every server of a sweep (or of the domain) at once, each
// row naming its server, as they come and go.
#include "monitor.h"

#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string_view>

#include "csv.h"
#include "dem/cli/interrupt.h"
#include "dem/client/telemetry.h"
#include "dem/dds/discovery.h"
#include "exit_codes.h"
#include "monitor_columns.h"

namespace demctl {

using dem::protocol::ContactStats;
using dem::protocol::PlateForces;
using dem::protocol::Status;
using namespace std::chrono_literals;

namespace {

struct Row {
  std::string server;
  PlateForces plates;
  ContactStats stats;
};

// Plate forces and contact statistics arrive on two topics per server; a
// row needs both of one cycle of one server. Older halves whose partner
// never came are dropped. Also keeps each server's latest status.
class Inbox {
 public:
  void add(const std::string& server, const PlateForces& plates) {
    std::lock_guard lock(mutex_);
    auto& halves = servers_[server];
    halves.plates[plates.cycle] = plates;
    match(server, halves);
  }
  void add(const std::string& server, const ContactStats& stats) {
    std::lock_guard lock(mutex_);
    auto& halves = servers_[server];
    halves.stats[stats.cycle] = stats;
    match(server, halves);
  }
  void add(const std::string& server, const Status& status) {
    std::lock_guard lock(mutex_);
    statuses_[server] = status;
  }
  // Waits a little for rows; returns those complete, oldest first (per server).
  std::deque<Row> take(std::chrono::milliseconds wait) {
    std::unique_lock lock(mutex_);
    ready_.wait_for(lock, wait, [this] { return !rows_.empty(); });
    return std::exchange(rows_, {});
  }
  std::optional<Status> status(const std::string& server) const {
    std::lock_guard lock(mutex_);
    const auto found = statuses_.find(server);
    return found == statuses_.end() ? std::nullopt : std::optional<Status>(found->second);
  }

 private:
  struct Halves {
    std::map<std::uint64_t, PlateForces> plates;
    std::map<std::uint64_t, ContactStats> stats;
  };
  void match(const std::string& server, Halves& halves) {
    for (auto it = halves.plates.begin(); it != halves.plates.end();) {
      const auto stats = halves.stats.find(it->first);
      if (stats == halves.stats.end()) {
        ++it;
        continue;
      }
      rows_.push_back({server, std::move(it->second), std::move(stats->second)});
      halves.stats.erase(halves.stats.begin(), std::next(stats));
      it = halves.plates.erase(halves.plates.begin(), std::next(it));
      ready_.notify_one();
    }
  }

  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::map<std::string, Halves> servers_;
  std::map<std::string, Status> statuses_;
  std::deque<Row> rows_;
};

// The plates shown: those --wall names (every wall without it), in the
// server's order of its walls, so the columns are the case's whatever
// order --wall gives.
std::vector<std::string> plate_names(const PlateForces& plates, const std::vector<std::string>& wanted) {
  std::vector<std::string> names;
  for (const auto& wall : plates.walls) names.push_back(wall.name);
  if (wanted.empty()) return names;
  for (const auto& name : wanted) {
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      throw BadArguments("monitor: no wall \"" + name + "\" (walls: " + known + ")");
    }
  }
  std::erase_if(names,
                [&](const std::string& name) { return std::find(wanted.begin(), wanted.end(), name) == wanted.end(); });
  return names;
}

const dem::protocol::WallForce* find(const PlateForces& plates, const std::string& name) {
  for (const auto& wall : plates.walls) {
    if (wall.name == name) return &wall;
  }
  return nullptr;
}

// The table on stdout and, with --csv, the same rows in a file. The plates
// shown are those of the first row (every server of a sweep has the same
// walls); with a server column when following several servers.
class RowWriter {
 public:
  RowWriter(const MonitorOptions& options, int server_width) : options_(options), server_width_(server_width) {}

  void write(const Row& row) {
    if (walls_.empty()) header(row.plates);
    const auto& [server, plates, stats] = row;
    // Stress and settlement of each plate shown, in order.
    std::vector<double> plate_values;
    for (const auto& name : walls_) {
      const auto* wall = find(plates, name);
      plate_values.push_back(wall ? wall->normal_stress : 0.0);
      plate_values.push_back(wall ? wall->settlement : 0.0);
    }
    if (server_width_ > 0) std::printf("%-*s ", server_width_, server.c_str());
    std::printf("%10llu %12.6g", static_cast<unsigned long long>(plates.cycle), plates.time);
    for (const double value : plate_values) std::printf(" %14.6g", value);
    std::vector<double> statistics;
    for (const StatisticsColumn& column : kStatisticsColumns) {
      const double value = column.value(stats);
      statistics.push_back(value);
      if (column.heading) {
        std::printf(" ");
        std::printf(column.format, column.width, value * column.scale);
      }
    }
    std::printf("\n");
    std::fflush(stdout);
    if (csv_) {
      if (server_width_ > 0) {
        csv_->row(server, plates.cycle, plates.time, plate_values, statistics);
      } else {
        csv_->row(plates.cycle, plates.time, plate_values, statistics);
      }
      csv_->flush();
    }
    ++rows_;
  }
  std::uint64_t rows() const { return rows_; }

 private:
  void header(const PlateForces& plates) {
    walls_ = plate_names(plates, options_.walls);
    const int lead = server_width_ > 0 ? server_width_ + 1 : 0;
    // Two header lines: each plate's name over its stress and settlement columns.
    std::printf("%*s", 23 + lead, "");
    for (const auto& name : walls_) std::printf(" %29.29s", name.c_str());
    std::printf("\n");
    if (server_width_ > 0) std::printf("%-*s ", server_width_, "server");
    std::printf("%10s %12s", "cycle", "time [s]");
    for (std::size_t i = 0; i < walls_.size(); ++i) std::printf(" %14s %14s", "stress [Pa]", "settlement [m]");
    for (const StatisticsColumn& column : kStatisticsColumns) {
      // A percentage's sign takes a place of its own.
      const bool percent = std::string_view(column.format ? column.format : "").ends_with("%%");
      if (column.heading) std::printf(" %*s", column.width + (percent ? 1 : 0), column.heading);
    }
    std::printf("\n");
    if (!options_.csv.empty()) {
      std::string header = server_width_ > 0 ? "server,cycle,time" : "cycle,time";
      for (const auto& name : walls_) header += "," + name + "_stress," + name + "_settlement";
      for (const StatisticsColumn& column : kStatisticsColumns) header += std::string(",") + column.csv;
      csv_ = std::make_unique<CsvWriter>(options_.csv, header);
    }
  }

  const MonitorOptions& options_;
  int server_width_;
  std::vector<std::string> walls_;
  std::unique_ptr<CsvWriter> csv_;
  std::uint64_t rows_ = 0;
};

bool enough(const MonitorOptions& options, const RowWriter& writer) {
  return options.samples && writer.rows() >= *options.samples;
}

int monitor_one(const Global& global, const MonitorOptions& options) {
  dem::client::Client client(connect_options(global));
  Inbox inbox;
  const std::string& name = global.server;
  dem::client::TelemetrySubscription subscription(client,
                                                  {.plate_forces = [&](const PlateForces& p) { inbox.add(name, p); },
                                                   .contact_stats = [&](const ContactStats& s) { inbox.add(name, s); },
                                                   .status = {}});
  RowWriter writer(options, 0);
  std::fprintf(stderr, "monitoring server %s (Ctrl-C to stop)\n", name.c_str());
  while (!dem::cli::interrupted() && !enough(options, writer)) {
    for (const Row& row : inbox.take(100ms)) {
      writer.write(row);
      if (enough(options, writer)) break;
    }
    if (!client.server_alive()) {
      std::fprintf(stderr, "server %s stopped\n", name.c_str());
      break;
    }
  }
  if (!options.csv.empty()) {
    std::fprintf(stderr, "wrote %s (%llu rows)\n", options.csv.c_str(), static_cast<unsigned long long>(writer.rows()));
  }
  return kOk;
}

// Every server of a sweep (or of the domain), followed as discovery finds
// them and let go when they leave; ends on Ctrl-C, after N rows, or - with
// --idle-exit S - once none has been there for S seconds.
int monitor_fleet(const Global& global, const MonitorOptions& options) {
  struct Followed {
    std::unique_ptr<dem::client::TelemetrySubscription> subscription;
    std::optional<std::chrono::steady_clock::time_point> gone_since;
  };
  dem::dds::Participant participant(global.domain, global.dds_config);
  dem::dds::PublicationMonitor publications(participant);
  Inbox inbox;
  std::map<std::string, Followed> followed;
  const std::string what = options.all ? "every server" : "the servers of sweep " + options.sweep;
  const std::string none = options.all ? "no server on the domain" : "no server of sweep " + options.sweep;
  RowWriter writer(options, options.all ? 20 : std::max(12, static_cast<int>(options.sweep.size()) + 5));
  std::fprintf(stderr, "monitoring %s on DDS domain %u (Ctrl-C to stop)\n", what.c_str(), global.domain);
  auto seen = std::chrono::steady_clock::now();  // when a server of the fleet was last there
  auto refreshed = seen - 1s;
  while (!dem::cli::interrupted() && !enough(options, writer)) {
    const auto now = std::chrono::steady_clock::now();
    if (now - refreshed >= 500ms) {
      refreshed = now;
      std::set<std::string> alive;
      for (const std::string& name : dem::client::server_names(publications.alive())) {
        if (options.all || in_sweep(name, options.sweep)) alive.insert(name);
      }
      for (const std::string& name : alive) {
        auto [entry, added] = followed.try_emplace(name);
        entry->second.gone_since.reset();
        if (!added) continue;
        entry->second.subscription = std::make_unique<dem::client::TelemetrySubscription>(
            participant, name,
            dem::client::TelemetryCallbacks{
                .plate_forces = [&inbox, name](const PlateForces& p) { inbox.add(name, p); },
                .contact_stats = [&inbox, name](const ContactStats& s) { inbox.add(name, s); },
                .status = [&inbox, name](const Status& s) { inbox.add(name, s); }});
        std::fprintf(stderr, "following server %s\n", name.c_str());
      }
      // A server that left is let go a second later, so its last samples are read.
      for (auto it = followed.begin(); it != followed.end();) {
        if (alive.count(it->first)) {
          ++it;
          continue;
        }
        if (!it->second.gone_since) it->second.gone_since = now;
        if (now - *it->second.gone_since < 1s) {
          ++it;
          continue;
        }
        const auto status = inbox.status(it->first);
        std::fprintf(stderr, "server %s left%s%s\n", it->first.c_str(), status ? ": " : "",
                     status ? (std::string(dem::protocol::to_string(status->state)) + ", cycle " +
                               std::to_string(status->cycle) + (status->message.empty() ? "" : ", " + status->message))
                                  .c_str()
                            : "");
        it = followed.erase(it);
      }
      if (!followed.empty()) seen = now;
      if (options.idle_exit > 0.0 && now - seen >= std::chrono::duration<double>(options.idle_exit)) {
        std::fprintf(stderr, "%s for %g s\n", none.c_str(), options.idle_exit);
        break;
      }
    }
    for (const Row& row : inbox.take(100ms)) {
      writer.write(row);
      if (enough(options, writer)) break;
    }
  }
  if (!options.csv.empty()) {
    std::fprintf(stderr, "wrote %s (%llu rows)\n", options.csv.c_str(), static_cast<unsigned long long>(writer.rows()));
  }
  return kOk;
}

}  // namespace

int monitor(const Global& global, const MonitorOptions& options) {
  if (options.all || !options.sweep.empty()) return monitor_fleet(global, options);
  if (options.idle_exit > 0.0) throw BadArguments("monitor: --idle-exit goes with --sweep or --all");
  return monitor_one(global, options);
}

}  // namespace demctl
