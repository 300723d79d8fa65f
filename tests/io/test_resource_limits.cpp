#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <thread>

#include "dem/io/resource_limits.h"

namespace dem::io {
namespace {

using ::testing::HasSubstr;

constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();

TEST(ResourceLimits, MachineLimitsFollowTheMachine) {
  const ResourceLimits limits = machine_limits();
  EXPECT_GE(limits.max_threads, 1);
  EXPECT_LE(limits.max_threads, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  EXPECT_GT(limits.memory_bytes, 0u);
  // The particle budget is what the memory budget holds, and ids can number.
  EXPECT_EQ(limits.max_particles,
            std::min<std::uint64_t>(limits.memory_bytes / kBytesPerParticle, std::numeric_limits<std::int32_t>::max()));
  EXPECT_EQ(limits.max_packing_cells, limits.max_particles * 64);
}

TEST(ResourceLimits, ABudgetLowersTheParticleCountAndTheMemoryTogether) {
  const ResourceLimits by_count = limits_with_budget(1000, 0);
  EXPECT_EQ(by_count.max_particles, 1000u);
  const ResourceLimits by_memory = limits_with_budget(0, 100 * kBytesPerParticle);
  EXPECT_EQ(by_memory.max_particles, 100u);
  EXPECT_EQ(by_memory.memory_bytes, 100 * kBytesPerParticle);
  // The smaller of the two wins.
  EXPECT_EQ(limits_with_budget(1000, 100 * kBytesPerParticle).max_particles, 100u);
}

constexpr std::uint64_t kMiB = 1024 * 1024;
constexpr std::uint64_t kGiB = 1024 * kMiB;

// The server of issue 37 under `ulimit -v 4194304` (4 GiB) on a 24 GiB
// machine: the budget was half the machine's memory, 4,936,731 spheres, so
// 4,096,000 loaded and the first cycle ran out of memory. Now the budget is
// half of what the address-space limit leaves beside what the process has
// mapped (300 MiB here): (4096 - 300) / 2 = 1898 MiB, 777,420 spheres.
TEST(ResourceLimits, TheBudgetIsHalfOfWhatTheAddressSpaceLimitLeaves) {
  MemoryFacts facts;
  facts.machine_bytes = 24 * kGiB;
  EXPECT_EQ(memory_limit(facts).bytes, 24 * kGiB);
  EXPECT_EQ(memory_limit(facts).source, "this machine has");
  facts.address_space_limit = 4 * kGiB;
  facts.address_space_used = 300 * kMiB;
  const MemoryLimit limit = memory_limit(facts);
  EXPECT_EQ(limit.bytes, 3796 * kMiB);
  EXPECT_EQ(limit.source, "the address-space limit (ulimit -v 4194304) leaves this process");
  const ResourceLimits limits = limits_with_budget(0, 0, limit);
  EXPECT_EQ(limits.memory_bytes, 1898 * kMiB);
  EXPECT_EQ(limits.max_particles, 1898 * kMiB / kBytesPerParticle);
  EXPECT_EQ(limits.max_particles, 777'420u);
  ASSERT_TRUE(particle_count_problem(4'096'000, limits));
  EXPECT_EQ(*particle_count_problem(4'096'000, limits),
            "define 4096000 particles, more than the particle budget of 777420 (what the memory budget of 1898 MiB "
            "holds, half of the 3796 MiB the address-space limit (ulimit -v 4194304) leaves this process)");
  EXPECT_FALSE(particle_count_problem(777'420, limits));
  // A limit the process has already used up leaves it nothing: every world is refused.
  facts.address_space_used = 5 * kGiB;
  EXPECT_EQ(memory_limit(facts).bytes, 0u);
  EXPECT_TRUE(particle_count_problem(1, limits_with_budget(0, 0, memory_limit(facts))));
}

TEST(ResourceLimits, TheSmallestOfTheMachineTheCgroupsAndTheProcessLimitsWins) {
  MemoryFacts facts;
  facts.machine_bytes = 24 * kGiB;
  facts.cgroup_limits = {{"/sys/fs/cgroup/memory.max", 16 * kGiB}, {"/sys/fs/cgroup/job/memory.high", 6 * kGiB}};
  facts.address_space_limit = 8 * kGiB;
  facts.address_space_used = 1 * kGiB;  // leaves 7 GiB
  facts.data_limit = 10 * kGiB;
  EXPECT_EQ(memory_limit(facts).bytes, 6 * kGiB);
  EXPECT_EQ(memory_limit(facts).source, "the cgroup limit /sys/fs/cgroup/job/memory.high allows");
  const ResourceLimits limits = limits_with_budget(0, 0, memory_limit(facts));
  EXPECT_EQ(limits.memory_bytes, 3 * kGiB);
  EXPECT_EQ(limits.memory_source, "half of the 6144 MiB the cgroup limit /sys/fs/cgroup/job/memory.high allows");
  facts.data_used = 5 * kGiB;  // the data limit leaves 5 GiB
  EXPECT_EQ(memory_limit(facts).bytes, 5 * kGiB);
  EXPECT_EQ(memory_limit(facts).source, "the data-segment limit (ulimit -d 10485760) leaves this process");
  // A limit larger than the machine (cgroup v1's "no limit" is 2^63 - 4096) is no limit.
  facts = MemoryFacts{};
  facts.machine_bytes = 24 * kGiB;
  facts.cgroup_limits = {{"/sys/fs/cgroup/memory/memory.limit_in_bytes", 9'223'372'036'854'771'712u}};
  EXPECT_EQ(memory_limit(facts).source, "this machine has");
  // A budget given outright is kept, whatever the limits.
  EXPECT_EQ(limits_with_budget(0, 100 * kBytesPerParticle, memory_limit(facts)).max_particles, 100u);
}

// A fake /sys/fs/cgroup of a hybrid host (v1 controllers, v2 at unified/)
// and the /proc/self/cgroup text of a process two levels down.
TEST(ResourceLimits, CgroupLimitsAreReadFromTheRootDownToTheProcesssOwn) {
  const std::filesystem::path root = std::filesystem::temp_directory_path() / "dem_cgroup_test";
  std::filesystem::remove_all(root);
  const auto write = [&](const std::filesystem::path& file, const std::string& text) {
    std::filesystem::create_directories((root / file).parent_path());
    std::ofstream(root / file) << text << "\n";
  };
  write("memory/memory.limit_in_bytes", "9223372036854771712");
  write("memory/batch/memory.limit_in_bytes", "8589934592");
  write("memory/batch/job7/memory.limit_in_bytes", "2147483648");
  write("memory/other/memory.limit_in_bytes", "1024");  // not the process's
  write("unified/user.slice/memory.max", "max");
  write("unified/user.slice/memory.high", "3221225472");
  const auto limits =
      cgroup_memory_limits(root, "9:pids:/\n4:memory:/batch/job7\n1:cpu:/\n0::/user.slice/session-1.scope\n");
  const std::vector<std::pair<std::string, std::uint64_t>> expected = {
      {(root / "unified/user.slice/memory.high").string(), 3'221'225'472u},
      {(root / "memory/memory.limit_in_bytes").string(), 9'223'372'036'854'771'712u},
      {(root / "memory/batch/memory.limit_in_bytes").string(), 8'589'934'592u},
      {(root / "memory/batch/job7/memory.limit_in_bytes").string(), 2'147'483'648u},
  };
  auto sorted = [](auto list) {
    std::sort(list.begin(), list.end());
    return list;
  };
  EXPECT_EQ(sorted(limits), sorted(expected));
  // A cgroup namespace's path that leads out of the hierarchy counts as its root.
  EXPECT_EQ(cgroup_memory_limits(root, "4:memory:/../..\n"),
            (std::vector<std::pair<std::string, std::uint64_t>>{
                {(root / "memory/memory.limit_in_bytes").string(), 9'223'372'036'854'771'712u}}));
  MemoryFacts facts;
  facts.machine_bytes = 24 * kGiB;
  facts.cgroup_limits = limits;
  EXPECT_EQ(memory_limit(facts).bytes, 2 * kGiB);
  std::filesystem::remove_all(root);
}

TEST(ResourceLimits, ThreadCountsBeyondTheCoresAreRefused) {
  ResourceLimits limits;
  limits.max_threads = 2;
  EXPECT_FALSE(thread_count_problem(0, limits));
  EXPECT_FALSE(thread_count_problem(2, limits));
  ASSERT_TRUE(thread_count_problem(3, limits));
  EXPECT_EQ(*thread_count_problem(100000, limits),
            "asks for 100000 threads; this machine gives the process 2 cores, so at most 2 (0 = every core)");
  EXPECT_THAT(*thread_count_problem(-1, limits), HasSubstr("must be >= 0"));
}

TEST(ResourceLimits, ParticleCountsBeyondTheBudgetOrTheMemoryAreRefused) {
  ResourceLimits limits;
  limits.max_particles = 1000;
  limits.memory_bytes = 500 * kBytesPerParticle;
  EXPECT_FALSE(particle_count_problem(500, limits));
  EXPECT_THAT(*particle_count_problem(501, limits), HasSubstr("more than the memory budget of"));
  EXPECT_EQ(*particle_count_problem(1001, limits), "define 1001 particles, more than the particle budget of 1000");
  EXPECT_THAT(*particle_count_problem(kMax, limits), HasSubstr("define more than 2^64 particles"));
}

TEST(ResourceLimits, CountsSaturateInsteadOfWrapping) {
  EXPECT_EQ(saturating_multiply(4'000'000'000u, 4'000'000'000u), 16'000'000'000'000'000'000u);
  EXPECT_EQ(saturating_multiply(saturating_multiply(4'000'000'000u, 4'000'000'000u), 4'000'000'000u), kMax);
  EXPECT_EQ(saturating_multiply(0, kMax), 0u);
  EXPECT_EQ(saturating_add(kMax - 1, 1), kMax);
  EXPECT_EQ(saturating_add(kMax, kMax), kMax);
}

}  // namespace
}  // namespace dem::io
