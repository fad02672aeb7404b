// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_INTERNAL_COMPRESSED_LISTS_H
#define FEATURERECON_INTERNAL_COMPRESSED_LISTS_H

#include <FeatureRecon/assertions.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace FeatureRecon {
namespace internal {

/// \cond
/// Lists 0..n-1 in two flat arrays (two allocations for all the lists, where a vector per list costs one
/// each): list k is items[offset[k], offset[k + 1]), holding the values emitted with key k in the order
/// emitted. build(n, each) calls each(emit) twice, to count and then to fill; each must emit the same (key <
/// n, value) pairs both times (with FEATURERECON_DEBUG, keys >= n and writes beyond the items are caught).
template <class T, class Allocator = std::allocator<T>>
struct Compressed_lists {
  using Offset_allocator = typename std::allocator_traits<Allocator>::template rebind_alloc<std::size_t>;
  std::vector<std::size_t, Offset_allocator> offset;
  std::vector<T, Allocator> items;

  template <class Each>
  void build(std::size_t n, Each each) {
    offset.assign(n + 2, 0);
    each([&](std::size_t k, const T&) {
      FEATURERECON_assertion(k < n);
      ++offset[k + 2];
    });
    for (std::size_t k = 2; k < offset.size(); ++k) offset[k] += offset[k - 1];
    items.resize(offset.back());
    each([&](std::size_t k, const T& value) {
      FEATURERECON_assertion(k < n && offset[k + 1] < items.size());
      items[offset[k + 1]++] = value;
    });
    offset.pop_back();  // offset[k + 1] went from the start of list k to its end, the start of list k + 1
  }
  std::size_t size(std::size_t k) const { return offset[k + 1] - offset[k]; }
  const T* begin(std::size_t k) const { return items.data() + offset[k]; }
  const T* end(std::size_t k) const { return items.data() + offset[k + 1]; }

  struct List {  // list k as a range
    const T *first, *last;
    const T* begin() const { return first; }
    const T* end() const { return last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
    bool empty() const { return first == last; }
    const T& front() const { return *first; }
  };
  List operator[](std::size_t k) const { return List{begin(k), end(k)}; }
};

/// Frees the memory of a container now, not at the end of its scope.
template <class T>
void release(T& x) {
  x = T();
}
/// \endcond

}  // namespace internal
}  // namespace FeatureRecon

#endif  // FEATURERECON_INTERNAL_COMPRESSED_LISTS_H
