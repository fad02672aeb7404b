// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_INTERNAL_RANDOM_H
#define FEATURERECON_INTERNAL_RANDOM_H

// Portable random numbers: the standard library's distributions differ between implementations, so seeded
// results are built from std::mt19937_64's bits (fixed by the standard) with these conversions only.

#include <cmath>
#include <cstdint>
#include <random>

namespace FeatureRecon {
namespace internal {

/// SplitMix64 finaliser: decorrelates seeds derived from one another (seed ^ constant, seed + index).
inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// Uniform doubles in [0, 1) from the top 53 bits of std::mt19937_64; normal deviates by Box-Muller.
struct Unit_random {
  explicit Unit_random(std::uint64_t seed) : rng(seed) {}
  double operator()() { return double(rng() >> 11) * 0x1.0p-53; }
  /// A standard normal deviate (two uniforms per call; no cached second value, so calls are independent of
  /// history).
  double normal() {
    const double u = 1.0 - (*this)(), v = (*this)();  // u in (0, 1]
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
  }
  std::mt19937_64 rng;
};

}  // namespace internal
}  // namespace FeatureRecon

#endif  // FEATURERECON_INTERNAL_RANDOM_H
