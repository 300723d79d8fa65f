#include "dem/io/resource_limits.h"

#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <thread>

namespace dem::io {
namespace {

constexpr std::uint64_t kMaxIds = static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max());
constexpr std::uint64_t kCellsPerParticle = 64;

int usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

// The smaller of the machine's memory and a cgroup v2 limit ("max" when none).
std::uint64_t usable_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGESIZE);
  std::uint64_t memory = pages > 0 && page_size > 0 ? static_cast<std::uint64_t>(pages) * page_size : 1ull << 30;
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  std::uint64_t limit = 0;
  if (cgroup >> limit && limit > 0) memory = std::min(memory, limit);
  return memory;
}

std::string bytes_text(std::uint64_t bytes) { return std::to_string(bytes / (1024 * 1024)) + " MiB"; }

}  // namespace

std::uint64_t saturating_multiply(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) return std::numeric_limits<std::uint64_t>::max();
  return a * b;
}

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
  return b > std::numeric_limits<std::uint64_t>::max() - a ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

ResourceLimits limits_with_budget(std::uint64_t max_particles, std::uint64_t memory_bytes) {
  static const int cores = usable_cores();
  static const std::uint64_t memory = usable_memory();
  ResourceLimits limits;
  limits.max_threads = cores;
  limits.memory_bytes = memory_bytes > 0 ? memory_bytes : memory / 2;
  const std::uint64_t by_memory = std::max<std::uint64_t>(1, limits.memory_bytes / kBytesPerParticle);
  limits.max_particles = std::min({max_particles > 0 ? max_particles : by_memory, by_memory, kMaxIds});
  limits.max_packing_cells = saturating_multiply(limits.max_particles, kCellsPerParticle);
  return limits;
}

ResourceLimits machine_limits() { return limits_with_budget(0, 0); }

std::optional<std::string> thread_count_problem(std::int64_t threads, const ResourceLimits& limits) {
  if (threads < 0) return "must be >= 0 (0 = every core), got " + std::to_string(threads);
  if (threads > limits.max_threads) {
    return "asks for " + std::to_string(threads) + " threads; this machine gives the process " +
           std::to_string(limits.max_threads) + " cores, so at most " + std::to_string(limits.max_threads) +
           " (0 = every core)";
  }
  return std::nullopt;
}

std::optional<std::string> particle_count_problem(std::uint64_t particles, const ResourceLimits& limits) {
  const std::string count =
      particles == std::numeric_limits<std::uint64_t>::max() ? "more than 2^64" : std::to_string(particles);
  if (particles > limits.max_particles) {
    return "define " + count + " particles, more than the particle budget of " + std::to_string(limits.max_particles) +
           (limits.max_particles == kMaxIds ? " (what particle ids can number)" : "");
  }
  const std::uint64_t needed = saturating_multiply(particles, kBytesPerParticle);
  if (needed > limits.memory_bytes) {
    return "define " + count + " particles, which need about " + bytes_text(needed) +
           ", more than the memory budget of " + bytes_text(limits.memory_bytes);
  }
  return std::nullopt;
}

}  // namespace dem::io
