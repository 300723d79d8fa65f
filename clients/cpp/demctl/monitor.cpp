// demctl monitor: a live table of plate stress against settlement and the
// contact statistics, one row per telemetry sample (plate forces and
// contact statistics of the same cycle), until Ctrl-C or N rows.
#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <map>
#include <memory>
#include <mutex>

#include "commands.h"
#include "csv.h"
#include "dem/client/telemetry.h"
#include "exit_codes.h"
#include "interrupt.h"

namespace demctl {

using dem::protocol::ContactStats;
using dem::protocol::PlateForces;
using namespace std::chrono_literals;

namespace {

// Plate forces and contact statistics arrive on two topics; a row needs
// both of one cycle. Older halves whose partner never came are dropped.
class RowAssembler {
 public:
  void add(const PlateForces& plates) {
    std::lock_guard lock(mutex_);
    plates_[plates.cycle] = plates;
    match();
  }
  void add(const ContactStats& stats) {
    std::lock_guard lock(mutex_);
    stats_[stats.cycle] = stats;
    match();
  }
  // Waits a little for rows; returns those complete, oldest first.
  std::deque<std::pair<PlateForces, ContactStats>> take(std::chrono::milliseconds wait) {
    std::unique_lock lock(mutex_);
    ready_.wait_for(lock, wait, [this] { return !rows_.empty(); });
    return std::exchange(rows_, {});
  }

 private:
  void match() {
    for (auto it = plates_.begin(); it != plates_.end();) {
      const auto stats = stats_.find(it->first);
      if (stats == stats_.end()) {
        ++it;
        continue;
      }
      rows_.emplace_back(std::move(it->second), std::move(stats->second));
      stats_.erase(stats_.begin(), std::next(stats));
      it = plates_.erase(plates_.begin(), std::next(it));
      ready_.notify_one();
    }
  }

  std::mutex mutex_;
  std::condition_variable ready_;
  std::map<std::uint64_t, PlateForces> plates_;
  std::map<std::uint64_t, ContactStats> stats_;
  std::deque<std::pair<PlateForces, ContactStats>> rows_;
};

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
  return wanted;
}

const dem::protocol::WallForce* find(const PlateForces& plates, const std::string& name) {
  for (const auto& wall : plates.walls) {
    if (wall.name == name) return &wall;
  }
  return nullptr;
}

}  // namespace

int monitor(const Global& global, const MonitorOptions& options) {
  dem::client::Client client(connect_options(global));
  RowAssembler rows;
  dem::client::TelemetrySubscription subscription(
      client, {.plate_forces = [&](const PlateForces& p) { rows.add(p); },
               .contact_stats = [&](const ContactStats& s) { rows.add(s); },
               .status = {}});
  std::vector<std::string> walls;
  std::unique_ptr<CsvWriter> csv;
  std::uint64_t printed = 0;
  std::fprintf(stderr, "monitoring server %s (Ctrl-C to stop)\n", global.server.c_str());
  while (!interrupted() && (!options.samples || printed < *options.samples)) {
    for (const auto& [plates, stats] : rows.take(100ms)) {
      if (walls.empty()) {
        walls = plate_names(plates, options.walls);
        // Two header lines: each plate's name over its stress and settlement columns.
        std::printf("%23s", "");
        for (const auto& name : walls) std::printf(" %29.29s", name.c_str());
        std::printf("\n%10s %12s", "cycle", "time [s]");
        for (std::size_t i = 0; i < walls.size(); ++i) std::printf(" %14s %14s", "stress [Pa]", "settlement [m]");
        std::printf(" %9s %6s %8s %12s\n", "contacts", "Z", "sliding", "KE [J]");
        if (!options.csv.empty()) {
          std::string header = "cycle,time";
          for (const auto& name : walls) header += "," + name + "_stress," + name + "_settlement";
          header += ",contacts,coordination_number,sliding_fraction,mean_normal_force,max_normal_force,"
                    "kinetic_energy,out_of_balance";
          csv = std::make_unique<CsvWriter>(options.csv, header);
        }
      }
      // Stress and settlement of each plate shown, in order.
      std::vector<double> plate_values;
      for (const auto& name : walls) {
        const auto* wall = find(plates, name);
        plate_values.push_back(wall ? wall->normal_stress : 0.0);
        plate_values.push_back(wall ? wall->settlement : 0.0);
      }
      std::printf("%10llu %12.6g", static_cast<unsigned long long>(plates.cycle), plates.time);
      for (const double value : plate_values) std::printf(" %14.6g", value);
      std::printf(" %9d %6.3f %7.1f%% %12.5g\n", stats.contacts, stats.coordination_number,
                  100.0 * stats.sliding_fraction, stats.kinetic_energy);
      std::fflush(stdout);
      if (csv) {
        csv->row(plates.cycle, plates.time, plate_values, stats.contacts, stats.coordination_number,
                 stats.sliding_fraction, stats.mean_normal_force, stats.max_normal_force, stats.kinetic_energy,
                 stats.out_of_balance);
        csv->flush();
      }
      ++printed;
      if (options.samples && printed >= *options.samples) break;
    }
    if (!client.server_alive()) {
      std::fprintf(stderr, "server %s stopped\n", global.server.c_str());
      break;
    }
  }
  if (csv) std::fprintf(stderr, "wrote %s (%llu rows)\n", options.csv.c_str(), static_cast<unsigned long long>(printed));
  return kOk;
}

}  // namespace demctl
