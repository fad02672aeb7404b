// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_INTERNAL_LARGE_ARRAY_ALLOCATOR_H
#define FEATURERECON_INTERNAL_LARGE_ARRAY_ALLOCATOR_H

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace FeatureRecon {
namespace internal {

/// \cond
/// Allocator for the large scratch arrays of the sweeps: blocks of 4 MiB or more are 2 MiB-aligned and
/// advised as transparent huge pages on Linux, which makes first-touch page faults (the dominant cost of
/// fresh memory on virtual machines) about 500 times rarer. Smaller blocks use malloc (aligned_alloc for
/// over-aligned types).
template <class T>
struct Large_array_allocator {
  using value_type = T;
  static constexpr std::size_t huge_page = std::size_t(2) << 20;
  static constexpr std::size_t threshold = std::size_t(4) << 20;

  Large_array_allocator() noexcept = default;
  template <class U>
  Large_array_allocator(const Large_array_allocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    void* p = nullptr;
    if (bytes >= threshold) {
      const std::size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;
      p = std::aligned_alloc(huge_page, rounded);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
      if (p != nullptr) (void)madvise(p, rounded, MADV_HUGEPAGE);
#endif
    } else if (alignof(T) > alignof(std::max_align_t)) {  // the link-cut tree's nodes are aligned to 32 bytes
      p = std::aligned_alloc(alignof(T),
                             (std::max<std::size_t>(bytes, 1) + alignof(T) - 1) / alignof(T) * alignof(T));
    } else {
      p = std::malloc(bytes == 0 ? 1 : bytes);
    }
    if (p == nullptr) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) noexcept { std::free(p); }
};

template <class T, class U>
bool operator==(const Large_array_allocator<T>&, const Large_array_allocator<U>&) noexcept {
  return true;
}
template <class T, class U>
bool operator!=(const Large_array_allocator<T>&, const Large_array_allocator<U>&) noexcept {
  return false;
}

template <class T>
using Large_vector = std::vector<T, Large_array_allocator<T>>;

/// Reserves exactly n elements in a std::vector and advises the 2 MiB-aligned part of the new buffer as huge
/// pages before anything touches it (for public result arrays that must stay std::vector).
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::size_t huge_page = std::size_t(2) << 20;
  const std::size_t bytes = v.capacity() * sizeof(T);
  if (bytes < 2 * huge_page) return;
  const std::size_t begin = (reinterpret_cast<std::size_t>(v.data()) + huge_page - 1) / huge_page * huge_page;
  const std::size_t end = (reinterpret_cast<std::size_t>(v.data()) + bytes) / huge_page * huge_page;
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
}
/// \endcond

}  // namespace internal
}  // namespace FeatureRecon

#endif  // FEATURERECON_INTERNAL_LARGE_ARRAY_ALLOCATOR_H
