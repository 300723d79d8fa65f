// The service under load (issue 12, docs/RELIABILITY.md): a dem_server
// process cycles a 4,900-disc lattice with one engine thread while
//   - client A sends get_state 250 times a second, each awaited: the
//     round trip a watching client sees, measured on its side;
//   - clients B, C and D each send 250 commands a second without waiting
//     (get_state, set_wall_velocity, a contact query on a wall), their
//     replies collected as they come;
//   - a telemetry subscriber (demctl monitor) is stopped with SIGSTOP and
//     acknowledges nothing;
// for 60 s (--seconds), after 15 s of the same run without commands.
// Printed: commands sent and answered (and busy), get_state's round trip
// (median, p99, max), each kind's time on the server, the engine's
// cycles per second without and with the load, and the server's resident
// memory every 10 s. Figures are printed, not asserted.
// With --flood, clients B, C and D instead query the contacts on a wall as
// fast as the client library lets them (each with its 64 requests in
// flight, client::ConnectOptions::max_outstanding): the load of issue 37,
// where get_state's p99 beside them was 35.7 ms.
// With --clients-apart, B, C and D are each a process of their own (this
// program again, --as-client), as three other users' tools would be; by
// default they are threads of this process beside A, sharing its DDS
// receive thread, so A's small replies queue behind their contact lists.
//   bench_responsiveness [--seconds 60] [--baseline 15] [--rate 1000] [--flood] [--clients-apart]
//                        [--domain 126]
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <deque>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "dem/client/client.h"
#include "lattice_case.h"

extern char** environ;

namespace {

using namespace std::chrono_literals;
using dem::bench::lattice_case;
using dem::bench::LatticeTop;
using Clock = std::chrono::steady_clock;
// The DDS domain, --domain (126 unless told).
std::uint32_t domain_id = 126;

pid_t spawn(std::vector<std::string> arguments) {
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) throw std::runtime_error("spawn");
  return pid;
}

double rss_mib(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return 0.0;
}

// The process's CPU time (user and system, all its threads), s.
double cpu_seconds(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  std::istringstream fields(text.substr(text.rfind(')') + 2));  // after "pid (comm) "
  std::string field;
  double ticks = 0.0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14 || i == 15) ticks += std::stod(field);  // utime, stime
  }
  return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

dem::client::ConnectOptions connect_options() {
  dem::client::ConnectOptions options;
  options.server = "responsive";
  options.domain = domain_id;
  options.timeout = 20s;
  options.reply_timeout = 60s;
  return options;
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(p * static_cast<double>(values.size())))];
}

// Cycles per second of wall time over `seconds`, from the status a watcher
// sees, and per second of the server's CPU time: on a machine the load
// generator shares, the first also counts the server waiting for a core.
struct Rate {
  double per_second = 0.0;
  double per_cpu_second = 0.0;
};
Rate engine_rate(dem::client::Client& watcher, pid_t server, std::chrono::seconds seconds) {
  const auto first = watcher.get_state();
  const double cpu = cpu_seconds(server);
  const auto start = Clock::now();
  std::this_thread::sleep_for(seconds);
  const auto last = watcher.get_state();
  const auto cycles = static_cast<double>(last.state.cycle - first.state.cycle);
  return {cycles / std::chrono::duration<double>(Clock::now() - start).count(), cycles / (cpu_seconds(server) - cpu)};
}

struct Results {
  std::mutex mutex;
  std::map<std::string, std::vector<double>> server_ms;  // by kind: reply.duration
  std::vector<double> round_trip_ms;                     // client A's get_state
  std::uint64_t sent = 0, answered = 0, busy = 0, errors = 0, lost = 0;
  std::vector<std::string> lost_requests;  // "request N from CLIENT", as the server's log names them
};

// One of clients B, C and D (c = 0, 1, 2) until `done`: pipelined commands at
// its share of the rate, or contact queries as fast as replies come (flood),
// the replies collected by a second thread as they arrive.
void load_client(int c, bool flood, std::chrono::duration<double> per_client, const std::atomic<bool>& done,
                 Results& results) {
  dem::client::Client client(connect_options());
  std::mutex mutex;
  std::deque<std::uint64_t> outstanding;
  std::atomic<bool> sending{true};
  std::thread collector([&] {
    for (;;) {
      std::uint64_t id = 0;
      {
        std::lock_guard lock(mutex);
        if (outstanding.empty()) {
          if (!sending) return;
          id = 0;
        } else {
          id = outstanding.front();
          outstanding.pop_front();
        }
      }
      if (id == 0) {
        std::this_thread::sleep_for(1ms);
        continue;
      }
      // A reply not here in 10 s is lost (2 s once the load is over: its stragglers).
      const std::optional<dem::protocol::Reply> reply = client.await(id, done ? 2s : 10s);
      std::lock_guard lock(results.mutex);
      if (!reply) {
        ++results.lost;
        results.lost_requests.push_back("request " + std::to_string(id) + " from " + client.client_id());
        continue;
      }
      ++results.answered;
      if (reply->status == dem::protocol::ReplyStatus::kBusy)
        ++results.busy;
      else if (!reply->ok())
        ++results.errors;
      const auto kind = dem::protocol::command_kind(reply->kind);
      results.server_ms[std::string(kind ? dem::protocol::to_string(*kind) : "unknown")].push_back(reply->duration *
                                                                                                   1e3);
    }
  });
  auto next = Clock::now();
  for (int i = 0; !done; ++i) {
    dem::protocol::Command command;
    if (flood) {  // as fast as replies come: send waits while 64 are unanswered
      command.kind = static_cast<std::uint8_t>(dem::protocol::CommandKind::kQueryContacts);
      command.query.wall_set = true;
      command.query.wall = "bottom";
      const std::uint64_t id = client.send(command);
      std::lock_guard lock(mutex);
      outstanding.push_back(id);
      std::lock_guard count(results.mutex);
      ++results.sent;
      continue;
    }
    next += std::chrono::duration_cast<Clock::duration>(per_client);
    std::this_thread::sleep_until(next);
    switch ((i + c) % 10) {
      case 0:
      case 1:
        command.kind = static_cast<std::uint8_t>(dem::protocol::CommandKind::kSetWallVelocity);
        command.wall_velocity.wall = "top";
        break;
      case 2:
        command.kind = static_cast<std::uint8_t>(dem::protocol::CommandKind::kQueryContacts);
        command.query.wall_set = true;
        command.query.wall = "bottom";
        break;
      default:
        command.kind = static_cast<std::uint8_t>(dem::protocol::CommandKind::kGetState);
    }
    const std::uint64_t id = client.send(command);
    std::lock_guard lock(mutex);
    outstanding.push_back(id);
    std::lock_guard count(results.mutex);
    ++results.sent;
  }
  sending = false;
  collector.join();
}

// A client's figures to the parent (--as-client): one line of counts, one
// line per request without reply, one per reply's time on the server.
void write_report(const std::string& path, const Results& results) {
  std::ofstream out(path);
  out << results.sent << ' ' << results.answered << ' ' << results.busy << ' ' << results.errors << ' ' << results.lost
      << '\n';
  for (const std::string& lost : results.lost_requests) out << "lost " << lost << '\n';
  for (const auto& [kind, ms] : results.server_ms) {
    for (const double value : ms) out << kind << ' ' << value << '\n';
  }
}

void add_report(const std::string& path, Results& results) {
  std::ifstream in(path);
  std::uint64_t sent = 0, answered = 0, busy = 0, errors = 0, lost = 0;
  if (!(in >> sent >> answered >> busy >> errors >> lost)) throw std::runtime_error("no report in " + path);
  results.sent += sent;
  results.answered += answered;
  results.busy += busy;
  results.errors += errors;
  results.lost += lost;
  std::string word;
  while (in >> word) {
    std::string rest;
    std::getline(in, rest);
    if (word == "lost") {
      results.lost_requests.push_back(rest.substr(1));
    } else {
      results.server_ms[word].push_back(std::stod(rest));
    }
  }
}

std::string self_path() {
  std::vector<char> path(4096);
  const ssize_t length = ::readlink("/proc/self/exe", path.data(), path.size() - 1);
  if (length <= 0) throw std::runtime_error("readlink /proc/self/exe");
  return std::string(path.data(), static_cast<std::size_t>(length));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The service's responsiveness under a load of commands (docs/RELIABILITY.md)."};
  int seconds = 60, baseline = 15, rate = 1000;
  app.add_option("--seconds", seconds, "how long the load lasts")->capture_default_str();
  app.add_option("--baseline", baseline, "seconds of the run without commands, first")->capture_default_str();
  app.add_option("--rate", rate, "commands a second, all clients together")->capture_default_str();
  app.add_option("--domain", domain_id, "the DDS domain id of the server and clients")->capture_default_str();
  bool flood = false, stalled = true;
  app.add_flag("!--no-stalled-monitor", stalled, "leave out the monitor stopped with SIGSTOP");
  app.add_flag("--flood", flood, "clients B, C and D query contacts without pause instead of at the rate");
  bool clients_apart = false;
  app.add_flag("--clients-apart", clients_apart, "clients B, C and D each in a process of their own");
  int as_client = -1;
  std::string report;
  app.add_option("--as-client", as_client, "run as client B, C or D (0-2) of a parent's run, for --seconds")
      ->check(CLI::Range(0, 2));
  app.add_option("--report", report, "with --as-client: the file the client's figures go to");
  std::string log_level = "warn";
  app.add_option("--server-log-level", log_level,
                 "the server's log level (info logs every reply: which of those without reply it sent)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  const auto per_client = std::chrono::duration<double>(4.0 / rate);
  if (as_client >= 0) {
    Results results;
    std::atomic<bool> done{false};
    std::thread client([&] { load_client(as_client, flood, per_client, done, results); });
    std::this_thread::sleep_for(std::chrono::seconds(seconds));
    done = true;
    client.join();
    write_report(report, results);
    return 0;
  }

  const pid_t server = spawn({DEM_SERVER_PROGRAM, "--name", "responsive", "--domain", std::to_string(domain_id),
                              "--threads", "1", "--log-level", log_level, "--no-csv", "--telemetry-cycles", "100",
                              "--out", std::string(DEM_BENCH_OUTPUT) + "/responsive"});
  dem::client::Client owner(connect_options());
  owner.load_case_text(lattice_case(70, 70, LatticeTop::kWall), "lattice_70x70");
  const std::uint64_t run = owner.start_cycle(1'000'000'000);
  const pid_t monitor = spawn({DEM_DEMCTL_PROGRAM, "--server", "responsive", "--domain", std::to_string(domain_id),
                               "monitor", "--csv", "/dev/null"});
  std::this_thread::sleep_for(2s);
  if (stalled) {
    ::kill(monitor, SIGSTOP);  // a subscriber that takes nothing from here on
  } else {
    ::kill(monitor, SIGKILL);
  }

  dem::client::Client watcher(connect_options());
  std::printf("server pid %d; RSS %.1f MiB after loading\n", server, rss_mib(server));
  const Rate quiet = engine_rate(watcher, server, std::chrono::seconds(baseline));
  std::printf("engine without commands: %.0f cycles/s, %.0f cycles per CPU second of the server\n", quiet.per_second,
              quiet.per_cpu_second);

  Results results;
  std::atomic<bool> done{false};
  std::vector<std::thread> threads;
  // A: synchronous get_state, its round trip.
  threads.emplace_back([&] {
    dem::client::Client client(connect_options());
    auto next = Clock::now();
    while (!done) {
      next += std::chrono::duration_cast<Clock::duration>(per_client);
      std::this_thread::sleep_until(next);
      const auto start = Clock::now();
      const dem::protocol::Reply reply = client.get_state();
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      std::lock_guard lock(results.mutex);
      ++results.sent;
      ++results.answered;
      results.round_trip_ms.push_back(ms);
      results.server_ms["get_state"].push_back(reply.duration * 1e3);
    }
  });
  // B, C, D: pipelined mixed commands, replies collected by a second thread each.
  std::vector<pid_t> apart;
  std::vector<std::string> reports;
  for (int c = 0; c < 3; ++c) {
    if (clients_apart) {
      reports.push_back(std::string(DEM_BENCH_OUTPUT) + "/responsive/client_" + std::to_string(c) + ".txt");
      std::vector<std::string> arguments{self_path(),          "--as-client", std::to_string(c),        "--report",
                                         reports.back(),       "--seconds",   std::to_string(seconds),  "--rate",
                                         std::to_string(rate), "--domain",    std::to_string(domain_id)};
      if (flood) arguments.emplace_back("--flood");
      apart.push_back(spawn(arguments));
    } else {
      threads.emplace_back([&, c] { load_client(c, flood, per_client, done, results); });
    }
  }
  const auto load_start = Clock::now();
  std::vector<Rate> rates;
  for (int t = 10; t <= seconds; t += 10) {
    rates.push_back(engine_rate(watcher, server, 10s));
    std::printf("  %3d s: engine %.0f cycles/s (%.0f per CPU second), server RSS %.1f MiB\n", t,
                rates.back().per_second, rates.back().per_cpu_second, rss_mib(server));
  }
  done = true;
  for (std::thread& thread : threads) thread.join();
  for (const pid_t client : apart) waitpid(client, nullptr, 0);
  for (const std::string& path : reports) add_report(path, results);
  const double load_seconds = std::chrono::duration<double>(Clock::now() - load_start).count();

  Rate loaded;
  for (const Rate& r : rates) {
    loaded.per_second += r.per_second / static_cast<double>(rates.size());
    loaded.per_cpu_second += r.per_cpu_second / static_cast<double>(rates.size());
  }
  std::printf("load: %.0f s, %llu commands sent (%.0f/s), %llu answered (%llu busy, %llu errors), %llu without reply\n",
              load_seconds, static_cast<unsigned long long>(results.sent),
              static_cast<double>(results.sent) / load_seconds, static_cast<unsigned long long>(results.answered),
              static_cast<unsigned long long>(results.busy), static_cast<unsigned long long>(results.errors),
              static_cast<unsigned long long>(results.lost));
  for (std::size_t i = 0; i < results.lost_requests.size() && i < 5; ++i) {
    std::printf("without reply: %s\n", results.lost_requests[i].c_str());
  }
  std::printf("get_state round trip (client A): median %.3f ms, p99 %.3f ms, max %.3f ms (%zu)\n",
              percentile(results.round_trip_ms, 0.5), percentile(results.round_trip_ms, 0.99),
              percentile(results.round_trip_ms, 1.0), results.round_trip_ms.size());
  for (const auto& [kind, ms] : results.server_ms) {
    std::printf("on the server, %-18s median %.3f ms, p99 %.3f ms, max %.3f ms (%zu)\n", kind.c_str(),
                percentile(ms, 0.5), percentile(ms, 0.99), percentile(ms, 1.0), ms.size());
  }
  std::printf("engine: %.0f cycles/s without commands, %.0f with (%.1f%% less)\n", quiet.per_second, loaded.per_second,
              100.0 * (quiet.per_second - loaded.per_second) / quiet.per_second);
  std::printf(
      "engine per CPU second of the server: %.0f without commands, %.0f with (%.1f%% less: the server's own "
      "cost of the commands)\n",
      quiet.per_cpu_second, loaded.per_cpu_second,
      100.0 * (quiet.per_cpu_second - loaded.per_cpu_second) / quiet.per_cpu_second);

  owner.stop();
  owner.await(run, 30s);
  ::kill(monitor, SIGKILL);
  waitpid(monitor, nullptr, 0);
  owner.shutdown();
  waitpid(server, nullptr, 0);
  return 0;
}
