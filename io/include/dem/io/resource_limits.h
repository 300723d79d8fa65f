// What one world may take of the machine: threads, particles, memory, and
// the work a random packing may do. A case or snapshot asking for more is
// refused at validation, naming the field and the limit, instead of
// crashing the process later (a thread count libgomp cannot start, a
// particle count that overflows, an allocation the machine cannot hold).
// The defaults are sized to the machine the process runs on; dem_server
// takes its own from its options (docs/RELIABILITY.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dem::io {

struct ResourceLimits {
  // Engine threads a case, a snapshot or an option may ask for: the cores
  // this process may run on (its CPU affinity, so a container's cpuset counts).
  int max_threads = 1;
  // Particles in one world, whatever their sources (lattices, packings, files).
  std::uint64_t max_particles = 0;
  // Bytes one world may need, estimated at kBytesPerParticle per particle.
  std::uint64_t memory_bytes = 0;
  // Where memory_bytes comes from, for messages: "half of the 24105 MiB
  // this machine has", "half of what the address-space limit (ulimit -v)
  // leaves this process", "set with --memory-budget".
  std::string memory_source;
  // Cells of a random packing's placement grid (one per largest diameter
  // of the box): a huge box of small particles would allocate them all.
  std::uint64_t max_packing_cells = 0;
  // A random packing's max_attempts (per particle): a packing that nearly
  // cannot fit costs up to its count times this many tries. The engine's
  // default is 100,000; the machine's limit allows 100 times that.
  std::uint64_t max_packing_attempts = 10'000'000;
  // Asked while a random packing is placed (RandomPackingDefT::stopped):
  // true ends the conversion with an error. dem_server sets it for a load
  // it may abandon (stop, --load-seconds), so the work ends with it.
  std::function<bool()> stop_packing;
};

// Measured on the shared 100,000-sphere benchmark packing (3D, Hertz laws,
// about 6 contacts per sphere): 224 MB resident for 100,000 spheres, 2.1 kB
// each; rounded up for denser packings and the case's own copies.
inline constexpr std::uint64_t kBytesPerParticle = 2560;

// The memory this process may use, and which limit says so: the smallest
// of the machine's memory, the memory limits of the cgroups it runs in
// (from its own up to the root: a container's, a systemd unit's, a batch
// job's) and what its address-space and data limits (RLIMIT_AS, ulimit -v;
// RLIMIT_DATA, ulimit -d) leave beside what it has mapped already.
struct MemoryLimit {
  std::uint64_t bytes = 0;
  std::string source;  // "this machine has", "the address-space limit (ulimit -v) leaves this process", ...
};

// What memory_limit() weighs, read from this process (memory_facts) or
// given (the tests).
struct MemoryFacts {
  std::uint64_t machine_bytes = 0;
  std::vector<std::pair<std::string, std::uint64_t>> cgroup_limits;  // the file that says so, its bytes
  std::optional<std::uint64_t> address_space_limit;                  // RLIMIT_AS when not unlimited
  std::uint64_t address_space_used = 0;                              // VmSize
  std::optional<std::uint64_t> data_limit;                           // RLIMIT_DATA when not unlimited
  std::uint64_t data_used = 0;                                       // VmData
};
MemoryFacts memory_facts();
MemoryLimit memory_limit(const MemoryFacts& facts);
MemoryLimit memory_limit();  // this process's, read afresh
// This process's as it started (read once): what the default budget is half of.
const MemoryLimit& starting_memory_limit();

// Why an allocation failed, for a reply or a log: memory ran out, and the
// limit the process started under ("... 631 MiB, what the address-space
// limit (ulimit -v 1150000) leaves this process").
std::string out_of_memory_reason();

// The memory limits of the cgroups that /proc/self/cgroup's text names,
// under a hierarchy mounted at `root` (/sys/fs/cgroup): cgroup v2's
// memory.max and memory.high (at root or root/unified) and v1's
// memory.limit_in_bytes (at root/memory), each directory from the
// hierarchy's root down to the process's own. "max" and missing files are
// no limit.
std::vector<std::pair<std::string, std::uint64_t>> cgroup_memory_limits(const std::filesystem::path& root,
                                                                        const std::string& proc_self_cgroup);

// Sized to this machine: every core it may use, half the memory it may use
// (memory_limit(): the machine's, a cgroup's, what ulimit -v leaves), as
// many particles as that memory holds (and particle ids can number), and
// packing grids of at most 64 cells per particle the budget allows.
ResourceLimits machine_limits();

// The same limits with a smaller particle or memory budget (each 0 keeps
// the machine's); the particle budget follows the memory one and the reverse.
ResourceLimits limits_with_budget(std::uint64_t max_particles, std::uint64_t memory_bytes);
// The same from a given memory limit (half of it is the budget when
// memory_bytes is 0).
ResourceLimits limits_with_budget(std::uint64_t max_particles, std::uint64_t memory_bytes, const MemoryLimit& memory);

// What is wrong with asking for `threads` engine threads, or nothing;
// `threads` 0 means every core and is always allowed.
std::optional<std::string> thread_count_problem(std::int64_t threads, const ResourceLimits& limits);

// What is wrong with a world of `particles` particles, or nothing: the
// particle budget, then the memory it would need.
std::optional<std::string> particle_count_problem(std::uint64_t particles, const ResourceLimits& limits);

// a * b and a + b saturating at the largest uint64: particle counts are
// products of uint32 fields that overflow 64 bits together.
std::uint64_t saturating_multiply(std::uint64_t a, std::uint64_t b);
std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b);

}  // namespace dem::io
