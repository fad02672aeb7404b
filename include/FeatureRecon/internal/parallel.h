// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_INTERNAL_PARALLEL_H
#define FEATURERECON_INTERNAL_PARALLEL_H

// A static split of independent work over std::threads. Results never depend on the number of threads: every
// index is handled by exactly one call, and callers write per-index results that they combine in index order.

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace FeatureRecon {
namespace internal {

/// The number of threads to use: `requested`, or the hardware's concurrency for 0 (at least 1, at most 64).
inline unsigned thread_count(unsigned requested) {
  const unsigned n = requested != 0 ? requested : std::thread::hardware_concurrency();
  return std::min(64u, std::max(1u, n));
}

/// Calls body(begin, end) on consecutive blocks covering [0, n): one block per thread, the first on the
/// calling thread. Runs inline when n < min_per_thread * 2 or with one thread. After every thread has joined,
/// the exception of the lowest block that threw (by position, whatever the timing) is rethrown; the others
/// are dropped.
template <class Body>
void parallel_blocks(std::size_t n, unsigned threads, std::size_t min_per_thread, Body body) {
  const std::size_t t = std::min<std::size_t>(
      thread_count(threads), std::max<std::size_t>(1, n / std::max<std::size_t>(1, min_per_thread)));
  if (t <= 1) {
    body(std::size_t(0), n);
    return;
  }
  std::vector<std::exception_ptr> errors(t);
  std::vector<std::thread> pool;
  pool.reserve(t - 1);
  auto run = [&](std::size_t k) {
    try {
      body(n * k / t, n * (k + 1) / t);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  for (std::size_t k = 1; k < t; ++k) pool.emplace_back(run, k);
  run(0);
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace internal
}  // namespace FeatureRecon

#endif  // FEATURERECON_INTERNAL_PARALLEL_H
