// The engine's long arrays (large_pages.h): past a large page they start on
// one and ask the kernel for large pages; they behave as any vector.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>

#include "large_pages.h"

namespace dem {
namespace {

constexpr std::size_t kDoublesPerLargePage = kLargePage / sizeof(double);

// The kernel's transparent large pages setting: "always", "madvise" or
// "never" (empty where the kernel has none).
std::string transparent_large_pages() {
  std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(file, line);
  const auto open = line.find('['), close = line.find(']');
  return open == std::string::npos || close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

// The kilobytes of large pages backing the mapping that holds `address`
// (/proc/self/smaps), or -1 where there is no such mapping.
long large_page_kilobytes(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("AnonHugePages:", 0) == 0) {
      return std::stol(line.substr(line.find(':') + 1));
    }
  }
  return -1;
}

TEST(LargePages, LongColumnsStartOnALargePage) {
  if (!kMapLongArrays) GTEST_SKIP() << "AddressSanitizer build: every array on the heap";
  const Column<double> column(kDoublesPerLargePage + 1000, 1.0);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(column.data()) % kLargePage, 0u);
}

TEST(LargePages, ColumnsKeepTheirValuesAsTheyGrowPastALargePage) {
  Column<std::int64_t> column;
  const std::int64_t n = 3 * static_cast<std::int64_t>(kDoublesPerLargePage) + 17;
  for (std::int64_t k = 0; k < n; ++k) column.push_back(k);
  Column<std::int64_t> copy = column;
  column.resize(10);
  column.shrink_to_fit();
  ASSERT_EQ(copy.size(), static_cast<std::size_t>(n));
  std::int64_t expected = 0;
  for (const std::int64_t value : copy) EXPECT_EQ(value, expected++) << "at " << expected;
  EXPECT_EQ(std::accumulate(column.begin(), column.end(), std::int64_t{0}), 45);
}

// Where the kernel gives large pages to programs that ask (Debian's
// default), a touched long column is backed by them.
TEST(LargePages, LongColumnsAreBackedByLargePages) {
  if (!kMapLongArrays) GTEST_SKIP() << "AddressSanitizer build: every array on the heap";
  const std::string setting = transparent_large_pages();
  if (setting != "always" && setting != "madvise") GTEST_SKIP() << "transparent large pages: '" << setting << "'";
  const Column<double> column(4 * kDoublesPerLargePage, 1.0);
  const long kilobytes = large_page_kilobytes(column.data());
  std::printf("a 8 MiB column: %ld KiB on large pages (transparent large pages: %s)\n", kilobytes, setting.c_str());
  EXPECT_GE(kilobytes, 2048);
}

}  // namespace
}  // namespace dem
