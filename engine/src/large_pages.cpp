#include "large_pages.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace dem {
namespace {

// What an array of `bytes` maps (large_pages.h).
std::size_t mapped_bytes(std::size_t bytes) {
  const std::size_t tail = bytes % kLargePage;
  if (tail >= kLargePage / 2) return bytes - tail + kLargePage;
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return (bytes + page - 1) / page * page;
}

}  // namespace

void* map_large_pages(std::size_t bytes) {
  // Mapped a large page over and trimmed to an aligned start.
  const std::size_t kept = mapped_bytes(bytes), mapped = kept + kLargePage;
  void* raw = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kLargePage - 1) / kLargePage * kLargePage;
  const std::size_t before = aligned - start, after = mapped - before - kept;
  if (before > 0) munmap(raw, before);
  if (after > 0) munmap(reinterpret_cast<void*>(aligned + kept), after);
  void* memory = reinterpret_cast<void*>(aligned);
#if defined(MADV_HUGEPAGE)
  // Advice only: where large pages are off or none is free, small pages serve.
  madvise(memory, kept, MADV_HUGEPAGE);
#endif
  return memory;
}

void unmap_large_pages(void* memory, std::size_t bytes) { munmap(memory, mapped_bytes(bytes)); }

}  // namespace dem
