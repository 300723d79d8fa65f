// The service over loopback DDS, measured against dem_server processes:
//   RoundTrip       one command and its reply (get_state): median and p99
//   Throughput/N    cycles per second of a 4,900-disc loading test with
//                   telemetry every N cycles (0: none) and a subscriber
//                   taking it, as the server reports it (reply duration)
//   QueryContacts   one query returning 100,000 contacts in chunks
// Figures are printed, not asserted. The servers run on DDS domain 125
// with the repository's loopback configuration and one engine thread.
//   bench_service [--benchmark_filter=RoundTrip]
#include <benchmark/benchmark.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "dem/client/client.h"
#include "dem/client/telemetry.h"
#include "lattice_case.h"

extern char** environ;

namespace {

using dem::bench::lattice_case;
using dem::bench::LatticeTop;
using namespace std::chrono_literals;
constexpr std::uint32_t kDomain = 125;

// A dem_server process and a client connected to it, shut down at exit.
class Server {
 public:
  Server(const std::string& name, const std::vector<std::string>& options) {
    std::vector<std::string> arguments{DEM_SERVER_PROGRAM,
                                       "--name",
                                       name,
                                       "--domain",
                                       std::to_string(kDomain),
                                       "--threads",
                                       "1",
                                       "--log-level",
                                       "warn",
                                       "--no-csv",
                                       "--out",
                                       std::string(DEM_BENCH_OUTPUT) + "/" + name};
    arguments.insert(arguments.end(), options.begin(), options.end());
    std::vector<char*> argv;
    for (std::string& argument : arguments) argv.push_back(argument.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0], nullptr, nullptr, argv.data(), environ) != 0) throw std::runtime_error("spawn");
    dem::client::ConnectOptions connect;
    connect.server = name;
    connect.domain = kDomain;
    connect.timeout = 20s;
    connect.reply_timeout = 300s;
    client_ = std::make_unique<dem::client::Client>(connect);
  }
  ~Server() {
    try {
      client_->shutdown();
    } catch (const std::exception&) {
      ::kill(pid_, SIGKILL);
    }
    client_.reset();
    waitpid(pid_, nullptr, 0);
  }
  dem::client::Client& client() { return *client_; }

 private:
  pid_t pid_ = -1;
  std::unique_ptr<dem::client::Client> client_;
};

void RoundTrip(benchmark::State& state) {
  static Server server("bench_rtt", {"--case", std::string(DEM_CASES_DIR) + "/ball/nine_disc_damped.case.txtpb"});
  dem::client::Client& client = server.client();
  std::vector<double> microseconds;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(client.get_state());
    microseconds.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(microseconds.begin(), microseconds.end());
  state.counters["median_us"] = microseconds[microseconds.size() / 2];
  state.counters["p99_us"] = microseconds[microseconds.size() * 99 / 100];
}
BENCHMARK(RoundTrip)->Iterations(3000)->Unit(benchmark::kMicrosecond);

void Throughput(benchmark::State& state) {
  const auto every = state.range(0);
  Server server("bench_tp_" + std::to_string(every), {"--telemetry-cycles", std::to_string(every)});
  dem::client::Client& client = server.client();
  client.load_case_text(lattice_case(70, 70, LatticeTop::kPlate), "lattice_70x70");
  std::atomic<std::uint64_t> samples{0};
  dem::client::TelemetrySubscription monitor(client, {.plate_forces = [&](const auto&) { ++samples; },
                                                      .contact_stats = [&](const auto&) { ++samples; },
                                                      .status = {}});
  while (monitor.matched_publishers() == 0) std::this_thread::sleep_for(10ms);
  client.cycle(200);  // settle in
  constexpr std::int64_t kCycles = 2000;
  double seconds = 0.0;
  std::int64_t contacts = 0;
  for (auto _ : state) {
    const dem::protocol::Reply reply = client.cycle(kCycles);
    seconds += reply.duration;
    state.SetIterationTime(reply.duration);
    contacts = client.get_state().stats.contacts;
  }
  state.counters["cycles_per_s"] = static_cast<double>(kCycles * state.iterations()) / seconds;
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["telemetry_samples"] = static_cast<double>(samples.load());
}
BENCHMARK(Throughput)->Arg(10)->Arg(0)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);

void QueryContacts(benchmark::State& state) {
  static Server server("bench_query", {});
  dem::client::Client& client = server.client();
  static const bool loaded = [&] {
    client.load_case_text(lattice_case(224, 224, LatticeTop::kOpen), "lattice_224x224");
    client.cycle(1);
    return true;
  }();
  (void)loaded;
  std::size_t received = 0;
  for (auto _ : state) received = client.query_contacts().contacts.size();
  state.counters["contacts"] = static_cast<double>(received);
}
BENCHMARK(QueryContacts)->Iterations(5)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
