// The time a cache line takes to go from one core to another and back,
// measured by two threads pinned to two cores handing a counter back and
// forth. Two threads of the engine share force sums and particle data every
// step, so their speed-up follows this figure: on this machine's virtual
// cores it has been seen at about 100 ns (two threads 1.9x one at 10k
// spheres) and at about 370 ns (1.1x), with the same binary, hours apart
// (docs/PERFORMANCE.md). bench/peer_comparison.py prints it with its table.
//
//   bench/core_round_trip [--cores A,B] [--round-trips N]
#include <pthread.h>
#include <sched.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

void pin_to(int core) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(core, &set);
  if (pthread_setaffinity_np(pthread_self(), sizeof set, &set) != 0) {
    throw std::runtime_error("cannot pin a thread to core " + std::to_string(core));
  }
}

// One round trip: this thread writes an odd value, the other answers with
// the next even one. The counter sits alone on its cache line.
double round_trip_ns(int first, int second, int round_trips) {
  struct alignas(64) Line {
    std::atomic<int> counter{0};
  } line;
  std::thread answerer([&] {
    pin_to(second);
    for (int i = 0; i < round_trips; ++i) {
      while (line.counter.load(std::memory_order_acquire) != 2 * i + 1) {
      }
      line.counter.store(2 * i + 2, std::memory_order_release);
    }
  });
  pin_to(first);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < round_trips; ++i) {
    line.counter.store(2 * i + 1, std::memory_order_release);
    while (line.counter.load(std::memory_order_acquire) != 2 * i + 2) {
    }
  }
  const auto end = std::chrono::steady_clock::now();
  answerer.join();
  return std::chrono::duration<double, std::nano>(end - start).count() / round_trips;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The round trip of a cache line between two cores"};
  std::vector<int> cores{0, 1};
  int round_trips = 200000;
  app.add_option("--cores", cores, "the two cores")->delimiter(',')->expected(2);
  app.add_option("--round-trips", round_trips, "how many")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  if (std::thread::hardware_concurrency() < 2) {
    std::printf("core round trip: one core only\n");
    return 0;
  }
  try {
    std::printf("core round trip %d-%d: %.0f ns\n", cores[0], cores[1], round_trip_ns(cores[0], cores[1], round_trips));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "core_round_trip: %s\n", e.what());
    return 1;
  }
  return 0;
}
