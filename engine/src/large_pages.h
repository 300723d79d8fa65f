// Memory for the engine's long arrays (particles, contact rows, blocks) on
// the processor's large pages where the system offers them. On a 100k bed
// the force pass reads a row's second particle, its sums and the shares
// set aside anywhere in some 60 MB: about 15,000 small pages of 4 KiB,
// more than the core's address translation buffers hold (a few thousand
// entries), against 30 large pages of 2 MiB. Debian leaves large pages to
// the programs that ask for them (transparent_hugepage "madvise"), so the
// arrays ask.
//
// 100k plate benchmark, one thread, side by side against the arrays on
// small pages: 1.055 (8 rounds, 1.020-1.067); two threads, one at a time,
// interleaved: 1.026; 10k (only the shear column is long enough) 0.998;
// peak RSS 92 against 98 MiB, as the long arrays go back to the system
// when freed (docs/PERFORMANCE.md, item 24).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace dem {

inline constexpr std::size_t kLargePage = std::size_t{2} << 20;
// Under AddressSanitizer (the fuzzing builds) every array comes from the
// heap, whose bounds it checks.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kMapLongArrays = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kMapLongArrays = false;
#else
inline constexpr bool kMapLongArrays = true;
#endif
#else
inline constexpr bool kMapLongArrays = true;
#endif
// Arrays of at least this many bytes start on a large page; smaller ones
// come from the ordinary heap.
inline constexpr std::size_t kLargeArray = kLargePage / 2;

// Maps `bytes` (at least kLargeArray) starting on a large page and asks
// for large pages. Only whole aligned large pages can be large: an array's
// last part is mapped as a whole large page when it fills at least half of
// one, else on small pages, so that an array costs at most half a large
// page more than it needs (whole large pages for every array added 19 MiB
// to the 100k bed's peak). Throws std::bad_alloc when the system has no
// memory.
void* map_large_pages(std::size_t bytes);
void unmap_large_pages(void* memory, std::size_t bytes);

template <typename T>
struct LargePageAllocator {
  using value_type = T;

  LargePageAllocator() = default;
  template <typename U>
  LargePageAllocator(const LargePageAllocator<U>&) noexcept {}

  // Short arrays come from std::allocator, so that they lie as they would
  // in a plain vector. (The vector keeps n within max_size, so n * sizeof(T)
  // does not overflow.)
  T* allocate(std::size_t n) {
    if (!is_long(n)) return std::allocator<T>{}.allocate(n);
    return static_cast<T*>(map_large_pages(n * sizeof(T)));
  }
  void deallocate(T* memory, std::size_t n) noexcept {
    if (!is_long(n)) return std::allocator<T>{}.deallocate(memory, n);
    unmap_large_pages(memory, n * sizeof(T));
  }

  friend bool operator==(const LargePageAllocator&, const LargePageAllocator&) = default;

 private:
  static bool is_long(std::size_t n) { return kMapLongArrays && n * sizeof(T) >= kLargeArray; }
};

// One array of the engine's state, by particle slot or by contact row.
template <typename T>
using Column = std::vector<T, LargePageAllocator<T>>;

}  // namespace dem
