#include "dem/io/resource_limits.h"

#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>
#include <thread>
#include <vector>

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

std::string bytes_text(std::uint64_t bytes) { return std::to_string(bytes / (1024 * 1024)) + " MiB"; }

// A number in a file ("max", missing or unreadable: nothing).
std::optional<std::uint64_t> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::uint64_t value = 0;
  if (in >> value && value > 0) return value;
  return std::nullopt;
}

// The files of `names` in the hierarchy's root `top` and in each cgroup
// below it down to the process's own (`own`, as /proc/self/cgroup names it),
// with the limits they hold. A path that leads out of `top` (a cgroup
// namespace's "/..") counts as the root.
void add_limits_downwards(const std::filesystem::path& top, const std::string& own,
                          std::initializer_list<const char*> names,
                          std::vector<std::pair<std::string, std::uint64_t>>& limits) {
  std::error_code error;
  if (!std::filesystem::is_directory(top, error)) return;
  std::filesystem::path below = std::filesystem::path(own).relative_path().lexically_normal();
  if (!below.empty() && *below.begin() == "..") below.clear();
  std::filesystem::path at = top;
  const auto add = [&] {
    for (const char* name : names) {
      if (const std::optional<std::uint64_t> bytes = read_bytes(at / name)) {
        limits.emplace_back((at / name).string(), *bytes);
      }
    }
  };
  add();
  for (const std::filesystem::path& part : below) {
    if (part.empty() || part == ".") continue;
    at /= part;
    add();
  }
}

// A /proc/self/status field in kB ("VmSize:", "VmData:"), in bytes.
std::uint64_t status_bytes(const std::string& field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(field, 0) == 0) {
      std::istringstream value(line.substr(field.size()));
      std::uint64_t kilobytes = 0;
      value >> kilobytes;
      return kilobytes * 1024;
    }
  }
  return 0;
}

}  // namespace

std::uint64_t saturating_multiply(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) return std::numeric_limits<std::uint64_t>::max();
  return a * b;
}

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
  return b > std::numeric_limits<std::uint64_t>::max() - a ? std::numeric_limits<std::uint64_t>::max() : a + b;
}

std::vector<std::pair<std::string, std::uint64_t>> cgroup_memory_limits(const std::filesystem::path& root,
                                                                        const std::string& proc_self_cgroup) {
  std::vector<std::pair<std::string, std::uint64_t>> limits;
  std::istringstream lines(proc_self_cgroup);
  std::string line;
  while (std::getline(lines, line)) {
    // "hierarchy-id:controllers:path"; the unified (v2) one is "0::path".
    const std::size_t first = line.find(':');
    const std::size_t second = first == std::string::npos ? first : line.find(':', first + 1);
    if (second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string own = line.substr(second + 1);
    if (line.rfind("0::", 0) == 0) {
      const bool hybrid = std::filesystem::is_directory(root / "unified");
      add_limits_downwards(hybrid ? root / "unified" : root, own, {"memory.max", "memory.high"}, limits);
    } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
      add_limits_downwards(root / "memory", own, {"memory.limit_in_bytes"}, limits);
    }
  }
  return limits;
}

MemoryFacts memory_facts() {
  MemoryFacts facts;
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGESIZE);
  facts.machine_bytes = pages > 0 && page_size > 0
                            ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size)
                            : 1ull << 30;
  std::ifstream cgroup("/proc/self/cgroup");
  std::stringstream text;
  text << cgroup.rdbuf();
  facts.cgroup_limits = cgroup_memory_limits("/sys/fs/cgroup", text.str());
  const auto soft_limit = [](int resource) -> std::optional<std::uint64_t> {
    rlimit r{};
    if (getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return std::nullopt;
    return static_cast<std::uint64_t>(r.rlim_cur);
  };
  facts.address_space_limit = soft_limit(RLIMIT_AS);
  facts.address_space_used = status_bytes("VmSize:");
  facts.data_limit = soft_limit(RLIMIT_DATA);
  facts.data_used = status_bytes("VmData:");
  return facts;
}

MemoryLimit memory_limit(const MemoryFacts& facts) {
  MemoryLimit limit{facts.machine_bytes, "this machine has"};
  const auto lower = [&](std::uint64_t bytes, std::string source) {
    if (bytes < limit.bytes) limit = {bytes, std::move(source)};
  };
  for (const auto& [file, bytes] : facts.cgroup_limits) lower(bytes, "the cgroup limit " + file + " allows");
  // What the process's own limits leave beside what it has mapped (the
  // program, its libraries, DDS's buffers, the threads' stacks).
  const auto left = [](std::uint64_t cap, std::uint64_t used) { return cap > used ? cap - used : 0; };
  if (facts.address_space_limit) {
    lower(left(*facts.address_space_limit, facts.address_space_used),
          "the address-space limit (ulimit -v " + std::to_string(*facts.address_space_limit / 1024) +
              ") leaves this process");
  }
  if (facts.data_limit) {
    lower(left(*facts.data_limit, facts.data_used),
          "the data-segment limit (ulimit -d " + std::to_string(*facts.data_limit / 1024) + ") leaves this process");
  }
  return limit;
}

MemoryLimit memory_limit() { return memory_limit(memory_facts()); }

const MemoryLimit& starting_memory_limit() {
  static const MemoryLimit memory = memory_limit();
  return memory;
}

std::string out_of_memory_reason() {
  const MemoryLimit& memory = starting_memory_limit();
  return "memory ran out (std::bad_alloc; the process may have " + bytes_text(memory.bytes) + ", what " +
         memory.source + ")";
}

ResourceLimits limits_with_budget(std::uint64_t max_particles, std::uint64_t memory_bytes) {
  return limits_with_budget(max_particles, memory_bytes, starting_memory_limit());
}

ResourceLimits limits_with_budget(std::uint64_t max_particles, std::uint64_t memory_bytes, const MemoryLimit& memory) {
  static const int cores = usable_cores();
  ResourceLimits limits;
  limits.max_threads = cores;
  limits.memory_bytes = memory_bytes > 0 ? memory_bytes : memory.bytes / 2;
  limits.memory_source =
      memory_bytes > 0 ? "as set (--memory-budget)" : "half of the " + bytes_text(memory.bytes) + " " + memory.source;
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
    std::string why;
    if (limits.max_particles == kMaxIds) {
      why = " (what particle ids can number)";
    } else if (limits.max_particles == std::max<std::uint64_t>(1, limits.memory_bytes / kBytesPerParticle)) {
      // The memory budget sets it: say which limit that is.
      why = " (what the memory budget of " + bytes_text(limits.memory_bytes) + " holds" +
            (limits.memory_source.empty() ? std::string() : ", " + limits.memory_source) + ")";
    }
    return "define " + count + " particles, more than the particle budget of " + std::to_string(limits.max_particles) +
           why;
  }
  const std::uint64_t needed = saturating_multiply(particles, kBytesPerParticle);
  if (needed > limits.memory_bytes) {
    return "define " + count + " particles, which need about " + bytes_text(needed) +
           ", more than the memory budget of " + bytes_text(limits.memory_bytes) +
           (limits.memory_source.empty() ? std::string() : " (" + limits.memory_source + ")");
  }
  return std::nullopt;
}

}  // namespace dem::io
