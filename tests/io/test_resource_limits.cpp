#include <gmock/gmock.h>
#include <gtest/gtest.h>

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
