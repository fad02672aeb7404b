// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// The small core headers against their documented contracts: the exact distance predicates of the Rips graph
// against a rational oracle at ties and near-ties, the portable random numbers against the standard's
// std::mt19937_64 bits, the compressed lists against a brute force, the large-array allocator's sizes and
// alignments, the static parallel split, and the ready-made traits.
#include <FeatureRecon/internal/Compressed_lists.h>
#include <FeatureRecon/internal/Large_array_allocator.h>
#include <FeatureRecon/internal/Union_find.h>
#include <FeatureRecon/internal/parallel.h>
#include <FeatureRecon/internal/random.h>
#include <FeatureRecon/point_traits.h>
#include <FeatureRecon/skeleton/internal/exact_distance.h>
#include <FeatureRecon/traits.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bitset>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "test_utilities.h"

namespace {

namespace fi = FeatureRecon::internal;
namespace si = FeatureRecon::skeleton::internal;

// ---- exact_distance.h -----------------------------------------------------------------------------------

mpq_class squared_distance_q(const double* p, const double* q, std::size_t d) {
  mpq_class s = 0;
  for (std::size_t i = 0; i < d; ++i) {
    const mpq_class u = mpq_class(p[i]) - mpq_class(q[i]);
    s += u * u;
  }
  return s;
}

int oracle_compare(const double* p, const double* q, const double* s, std::size_t d) {
  const mpq_class a = squared_distance_q(p, q, d), b = squared_distance_q(p, s, d);
  return a < b ? -1 : (b < a ? 1 : 0);
}

double double_squared_distance(const double* p, const double* q, std::size_t d) {
  double s = 0;
  for (std::size_t i = 0; i < d; ++i) s += (p[i] - q[i]) * (p[i] - q[i]);
  return s;
}

// Triples at exact ties (s is q with two coordinates' offsets from p swapped) and one or two units in the
// last place away from them, in 2 to 4 dimensions, against the rational oracle.
TEST(CoreInternals, CompareSquaredDistancesIsExactAtTiesAndNearTies) {
  std::mt19937_64 rng(20260601);
  std::uniform_real_distribution<double> coordinate(-1e3, 1e3), offset(-1.0, 1.0);
  int ties = 0, near_ties = 0, double_wrong = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::size_t d = 2 + trial % 3;
    std::array<double, 4> p{}, q{}, s{};
    for (std::size_t i = 0; i < d; ++i) p[i] = coordinate(rng);
    for (std::size_t i = 0; i < d; ++i) q[i] = p[i] + offset(rng) * std::ldexp(1.0, int(trial % 40) - 20);
    // s: the offsets of q from p with coordinates 0 and d - 1 swapped: an exact tie (the differences are
    // exact by Sterbenz only near p, so the tie is not always exact; the oracle decides).
    s = q;
    s[0] = p[0] + (q[d - 1] - p[d - 1]);
    s[d - 1] = p[d - 1] + (q[0] - p[0]);
    const int nudge = trial % 5;  // 0: as is; 1..4: one or two ulps either way in the last coordinate
    if (nudge == 1) s[d - 1] = std::nextafter(s[d - 1], 1e300);
    if (nudge == 2) s[d - 1] = std::nextafter(s[d - 1], -1e300);
    if (nudge == 3) s[d - 1] = std::nextafter(std::nextafter(s[d - 1], 1e300), 1e300);
    if (nudge == 4) s[0] = std::nextafter(s[0], -1e300);
    const int expected = oracle_compare(p.data(), q.data(), s.data(), d);
    ASSERT_EQ(si::compare_squared_distances(p.data(), q.data(), s.data(), d), expected) << "trial " << trial;
    ASSERT_EQ(si::compare_squared_distances(p.data(), s.data(), q.data(), d), -expected) << "trial " << trial;
    ASSERT_EQ(si::compare_squared_distances(p.data(), q.data(), q.data(), d), 0);
    (expected == 0 ? ties : near_ties) += 1;
    const double a = double_squared_distance(p.data(), q.data(), d),
                 b = double_squared_distance(p.data(), s.data(), d);
    if ((a < b ? -1 : (b < a ? 1 : 0)) != expected) ++double_wrong;
  }
  // Near-ties closer than the interval filter resolves: |p - q|^2 = A^2 + B^2 with B about 2^-25 in the
  // last coordinate, against |p - s|^2 = A'^2, A' = A or one ulp more.
  std::uniform_real_distribution<double> unit(-1, 1), scale(0.5, 2);
  for (int trial = 0; trial < 20000; ++trial) {
    const std::size_t d = 2 + trial % 3;
    std::array<double, 4> p{}, q{}, s{};
    for (std::size_t i = 0; i < d; ++i) p[i] = unit(rng);
    q[0] = p[0] + 1 + (unit(rng) + 1) / 2;
    s[0] = trial % 2 == 0 ? q[0] : std::nextafter(q[0], 1e300);
    for (std::size_t i = 1; i + 1 < d; ++i) q[i] = s[i] = p[i] + unit(rng);  // equal terms
    q[d - 1] = p[d - 1] + std::ldexp(scale(rng), -25);
    s[d - 1] = p[d - 1];
    const int expected = oracle_compare(p.data(), q.data(), s.data(), d);
    ASSERT_EQ(si::compare_squared_distances(p.data(), q.data(), s.data(), d), expected) << "trial " << trial;
    ASSERT_EQ(si::compare_squared_distances(p.data(), s.data(), q.data(), d), -expected) << "trial " << trial;
    (expected == 0 ? ties : near_ties) += 1;
    const double a = double_squared_distance(p.data(), q.data(), d),
                 b = double_squared_distance(p.data(), s.data(), d);
    if ((a < b ? -1 : (b < a ? 1 : 0)) != expected) ++double_wrong;
  }
  // The set is hard: many exact ties, and many triples that plain double arithmetic orders wrongly.
  EXPECT_GT(ties, 1000);
  EXPECT_GT(near_ties, 1000);
  EXPECT_GT(double_wrong, 1000);
}

TEST(CoreInternals, CompareSquaredDistancesHandPickedNearTies) {
  // |p - q|^2 = 1 + 2^-54 exactly, |p - s|^2 = 1: doubles round the first to 1 (a false tie).
  const double p[2] = {0, 0}, q[2] = {1, std::ldexp(1.0, -27)}, s[2] = {1, 0};
  EXPECT_EQ(si::compare_squared_distances(p, q, s, 2), 1);
  EXPECT_EQ(si::compare_squared_distances(p, s, q, 2), -1);
  // The last coordinate decides.
  const double p3[3] = {5, 5, 5}, q3[3] = {6, 5, 5 + std::ldexp(1.0, -20)}, s3[3] = {6, 5, 5};
  EXPECT_EQ(si::compare_squared_distances(p3, q3, s3, 3), 1);
  EXPECT_EQ(si::compare_squared_distances(p3, s3, q3, 3), -1);
}

TEST(CoreInternals, DistanceAtMostIsExactAtTiesAndNearTies) {
  // |p - q| = r exactly, with r^2 not a double (the interval filter cannot decide): true; r one ulp below:
  // false; one ulp above: true.
  const double r = 1 + std::ldexp(1.0, -52);
  const double p1[1] = {0}, q1[1] = {r};
  EXPECT_TRUE(si::distance_at_most(p1, q1, 1, r));
  EXPECT_FALSE(si::distance_at_most(p1, q1, 1, std::nextafter(r, 0.0)));
  EXPECT_TRUE(si::distance_at_most(p1, q1, 1, std::nextafter(r, 2.0)));
  // |p - q|^2 = 1 + 2^-54, which doubles round to 1: not within 1.
  const double p2[2] = {0, 0}, q2[2] = {1, std::ldexp(1.0, -27)};
  EXPECT_FALSE(si::distance_at_most(p2, q2, 2, 1.0));
  EXPECT_TRUE(si::distance_at_most(p2, q2, 2, std::nextafter(1.0, 2.0)));
  // 3-4-5 scaled and shifted: exact ties on every coordinate count, the last included.
  const double p3[3] = {0.25, -7, 1e3}, q3[3] = {0.25, -7 + 3 * 0.125, 1e3 + 4 * 0.125};
  EXPECT_TRUE(si::distance_at_most(p3, q3, 3, 5 * 0.125));
  EXPECT_FALSE(si::distance_at_most(p3, q3, 3, std::nextafter(5 * 0.125, 0.0)));
  // Random near-ties against the oracle: r = the double nearest |p - q| and its neighbours.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-10, 10);
  int trues = 0, falses = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const std::size_t d = 1 + trial % 4;
    std::array<double, 4> p{}, q{};
    for (std::size_t i = 0; i < d; ++i) p[i] = coordinate(rng);
    for (std::size_t i = 0; i < d; ++i) q[i] = p[i] + coordinate(rng) * std::ldexp(1.0, -(trial % 30));
    double radius = std::sqrt(double_squared_distance(p.data(), q.data(), d));
    if (trial % 3 == 1) radius = std::nextafter(radius, 0.0);
    if (trial % 3 == 2) radius = std::nextafter(radius, 1e300);
    const mpq_class rr = mpq_class(radius) * mpq_class(radius);
    const bool expected = !(rr < squared_distance_q(p.data(), q.data(), d));
    ASSERT_EQ(si::distance_at_most(p.data(), q.data(), d, radius), expected) << "trial " << trial;
    ASSERT_EQ(si::distance_at_most(q.data(), p.data(), d, radius), expected) << "trial " << trial;
    (expected ? trues : falses) += 1;
  }
  EXPECT_GT(trues, 1000);
  EXPECT_GT(falses, 1000);
}

// ---- random.h -------------------------------------------------------------------------------------------

TEST(CoreInternals, Splitmix64IsTheReferenceFinaliser) {
  // The reference SplitMix64 outputs from state 0 (Steele, Lea and Flood; Vigna's splitmix64.c): the state
  // advances by the golden gamma and each output is the finaliser of the new state.
  EXPECT_EQ(fi::splitmix64(0), 0xe220a8397b1dcdafULL);
  EXPECT_EQ(fi::splitmix64(0x9e3779b97f4a7c15ULL), 0x6e789e6aa1b965f4ULL);
  EXPECT_EQ(fi::splitmix64(0x3c6ef372fe94f82aULL), 0x06c45d188009454fULL);
  // Seeds derived from one another (seed + index) are decorrelated: about half of the bits change.
  double changed = 0;
  for (std::uint64_t seed = 0; seed < 4096; ++seed)
    changed += double(std::bitset<64>(fi::splitmix64(seed) ^ fi::splitmix64(seed + 1)).count());
  EXPECT_NEAR(changed / 4096, 32.0, 1.0);
}

TEST(CoreInternals, UnitRandomIsTheTop53BitsOfMt19937_64) {
  for (const std::uint64_t seed :
       {std::uint64_t(0), std::uint64_t(1), std::uint64_t(42), ~std::uint64_t(0)}) {
    fi::Unit_random random(seed);
    std::mt19937_64 reference(seed);
    for (int i = 0; i < 1000; ++i) {
      const std::uint64_t bits = reference();
      const double u = random();
      ASSERT_EQ(u, double(bits >> 11) / 9007199254740992.0) << "seed " << seed << ", draw " << i;
      ASSERT_GE(u, 0.0);
      ASSERT_LT(u, 1.0);
    }
  }
  // The same seed gives bit-identical streams, another seed another stream.
  fi::Unit_random a(12345), b(12345), c(12346);
  int equal_to_other = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = a();
    EXPECT_EQ(x, b());
    if (x == c()) ++equal_to_other;
  }
  EXPECT_EQ(equal_to_other, 0);
  // The standard fixes the 10000th output of a default-seeded std::mt19937_64; Unit_random(5489) is that one.
  fi::Unit_random d(5489);
  for (int i = 0; i < 9999; ++i) d();
  EXPECT_EQ(d(), double(9981545732273789042ULL >> 11) / 9007199254740992.0);
  // The uniforms fill [0, 1): their mean is 1/2, and values above 1/2 occur.
  fi::Unit_random e(3);
  double sum = 0, largest = 0;
  for (int i = 0; i < 100000; ++i) {
    const double x = e();
    sum += x;
    largest = std::max(largest, x);
  }
  EXPECT_NEAR(sum / 100000, 0.5, 0.01);
  EXPECT_GT(largest, 0.99);
}

TEST(CoreInternals, UnitRandomNormalIsBoxMullerOfTwoUniforms) {
  fi::Unit_random random(99);
  std::mt19937_64 reference(99);
  for (int i = 0; i < 1000; ++i) {
    const double u = 1.0 - double(reference() >> 11) / 9007199254740992.0;
    const double v = double(reference() >> 11) / 9007199254740992.0;
    const double expected = std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
    ASSERT_EQ(random.normal(), expected) << "draw " << i;
  }
  // A standard normal: mean 0, variance 1, about 68.3% within one standard deviation.
  fi::Unit_random g(5);
  const int n = 200000;
  double sum = 0, sum2 = 0;
  int within = 0;
  for (int i = 0; i < n; ++i) {
    const double x = g.normal();
    ASSERT_TRUE(std::isfinite(x));
    sum += x;
    sum2 += x * x;
    if (std::fabs(x) < 1) ++within;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.02);
  EXPECT_NEAR(sum2 / n, 1.0, 0.02);
  EXPECT_NEAR(double(within) / n, 0.6827, 0.01);
}

// ---- Compressed_lists.h ---------------------------------------------------------------------------------

template <class Lists>
void expect_lists(const Lists& lists, const std::vector<std::vector<int>>& expected) {
  const std::size_t n = expected.size();
  ASSERT_GE(lists.offset.size(), n + 1);
  EXPECT_EQ(lists.offset[0], 0u);
  std::size_t total = 0;
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_EQ(lists.offset[k], total);
    total += expected[k].size();
    ASSERT_EQ(lists.size(k), expected[k].size()) << "list " << k;
    EXPECT_EQ(std::vector<int>(lists.begin(k), lists.end(k)), expected[k]) << "list " << k;
    const auto list = lists[k];
    EXPECT_EQ(list.size(), expected[k].size());
    EXPECT_EQ(list.empty(), expected[k].empty());
    EXPECT_EQ(std::vector<int>(list.begin(), list.end()), expected[k]);
    if (!expected[k].empty()) {
      EXPECT_EQ(list.front(), expected[k].front());
    }
  }
  EXPECT_EQ(lists.offset[n], total);
  EXPECT_EQ(lists.items.size(), total);
}

TEST(CoreInternals, CompressedListsAgainstBruteForce) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = std::size_t(trial % 17);
    std::vector<std::pair<std::size_t, int>> pairs;
    if (n > 0) {
      const int count = int(rng() % 60);
      for (int i = 0; i < count; ++i) pairs.emplace_back(std::size_t(rng() % n), int(rng() % 1000) - 500);
      if (trial % 4 == 0)  // long single-key runs
        for (int i = 0; i < 5; ++i) pairs.emplace_back(n - 1, i);
    }
    std::vector<std::vector<int>> expected(n);
    for (const auto& [k, v] : pairs) expected[k].push_back(v);
    auto each = [&](auto emit) {
      for (const auto& [k, v] : pairs) emit(k, v);
    };
    fi::Compressed_lists<int> lists;
    lists.build(n, each);
    expect_lists(lists, expected);
    fi::Compressed_lists<int, fi::Large_array_allocator<int>> large;
    large.build(n, each);
    expect_lists(large, expected);
    // Rebuilding replaces the old lists.
    lists.build(n, [](auto) {});
    expect_lists(lists, std::vector<std::vector<int>>(n));
  }
}

TEST(CoreInternals, ReleaseFreesTheMemory) {
  std::vector<int> v(1000, 1);
  fi::release(v);
  EXPECT_TRUE(v.empty());
  EXPECT_EQ(v.capacity(), 0u);
}

// ---- Large_array_allocator.h ----------------------------------------------------------------------------

struct alignas(64) Wide {
  double x[3];
};

TEST(CoreInternals, LargeArrayAllocatorSizesAndAlignments) {
  fi::Large_array_allocator<double> doubles;
  constexpr std::size_t huge_page = std::size_t(2) << 20, threshold = std::size_t(4) << 20;
  // A size whose byte count overflows is refused, not allocated short.
  EXPECT_THROW(
      {
        const std::size_t n = std::size_t(-1) / sizeof(double) + 1;
        double* p = doubles.allocate(n);
        doubles.deallocate(p, n);
      },
      std::bad_array_new_length);
  // Blocks of 4 MiB or more are 2 MiB-aligned and hold all their bytes.
  for (const std::size_t bytes : {threshold, threshold + 8, threshold + huge_page / 2, 3 * threshold + 8}) {
    const std::size_t n = bytes / sizeof(double);
    double* p = doubles.allocate(n);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % huge_page, 0u) << bytes << " bytes";
#if defined(__GLIBC__)
    EXPECT_GE(malloc_usable_size(p), bytes) << bytes << " bytes";
#endif
    p[0] = 1;
    p[n - 1] = 2;
    doubles.deallocate(p, n);
  }
  // Small blocks hold all their bytes (zero elements included).
  fi::Large_array_allocator<char> chars;
  for (std::size_t n = 0; n <= 300; ++n) {
    char* p = chars.allocate(n);
    ASSERT_NE(p, nullptr);
#if defined(__GLIBC__)
    EXPECT_GE(malloc_usable_size(p), n) << n << " bytes";
#endif
    chars.deallocate(p, n);
  }
  // Over-aligned types get their alignment.
  fi::Large_array_allocator<Wide> wides;
  std::vector<std::pair<Wide*, std::size_t>> blocks;
  for (std::size_t n = 0; n < 40; ++n) {
    Wide* p = wides.allocate(n);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % alignof(Wide), 0u) << n << " elements";
    blocks.emplace_back(p, n);
  }
  for (const auto& [p, n] : blocks) wides.deallocate(p, n);
  // Stateless: any two allocators can free each other's memory.
  EXPECT_TRUE(fi::Large_array_allocator<int>() == fi::Large_array_allocator<double>());
  EXPECT_FALSE(fi::Large_array_allocator<int>() != fi::Large_array_allocator<double>());
  fi::Large_vector<int> v(1000, 7);
  fi::Large_vector<int> w(std::move(v));
  EXPECT_EQ(w.size(), 1000u);
  EXPECT_EQ(w[999], 7);
}

TEST(CoreInternals, ReserveHugeReservesExactly) {
  for (const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(1000), std::size_t(3) << 20}) {
    std::vector<double> v;
    fi::reserve_huge(v, n);
    EXPECT_EQ(v.capacity(), n);
    EXPECT_TRUE(v.empty());
  }
}

// ---- parallel.h -----------------------------------------------------------------------------------------

TEST(CoreInternals, ThreadCount) {
  EXPECT_EQ(fi::thread_count(1), 1u);
  EXPECT_EQ(fi::thread_count(33), 33u);
  EXPECT_EQ(fi::thread_count(64), 64u);
  EXPECT_EQ(fi::thread_count(65), 64u);
  EXPECT_EQ(fi::thread_count(1000), 64u);
  EXPECT_EQ(fi::thread_count(0), std::min(64u, std::max(1u, std::thread::hardware_concurrency())));
}

TEST(CoreInternals, ParallelBlocksCoverEachIndexOnce) {
  for (std::size_t n = 0; n <= 40; ++n)
    for (unsigned threads = 1; threads <= 6; ++threads)
      for (std::size_t min_per_thread = 0; min_per_thread <= 5; ++min_per_thread) {
        std::mutex mutex;
        std::vector<std::pair<std::size_t, std::size_t>> blocks;
        std::vector<int> seen(n, 0);
        std::thread::id first_block_thread;
        fi::parallel_blocks(n, threads, min_per_thread, [&](std::size_t begin, std::size_t end) {
          std::lock_guard<std::mutex> lock(mutex);
          blocks.emplace_back(begin, end);
          for (std::size_t i = begin; i < end; ++i) ++seen[i];
          if (begin == 0) first_block_thread = std::this_thread::get_id();
        });
        const std::string where = "n " + std::to_string(n) + ", threads " + std::to_string(threads) +
                                  ", min_per_thread " + std::to_string(min_per_thread);
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i], 1) << where << ", index " << i;
        std::sort(blocks.begin(), blocks.end());
        ASSERT_FALSE(blocks.empty());
        EXPECT_EQ(blocks.front().first, 0u);
        EXPECT_EQ(blocks.back().second, n);
        for (std::size_t b = 1; b < blocks.size(); ++b) EXPECT_EQ(blocks[b].first, blocks[b - 1].second);
        // One block per thread; inline (a single block) when n < 2 min_per_thread.
        const std::size_t expected_blocks = std::min<std::size_t>(
            threads, std::max<std::size_t>(1, n / std::max<std::size_t>(1, min_per_thread)));
        EXPECT_EQ(blocks.size(), expected_blocks) << where;
        if (min_per_thread > 0 && n < 2 * min_per_thread) {
          EXPECT_EQ(blocks.size(), 1u) << where;
        }
        // The first block runs on the calling thread.
        EXPECT_EQ(first_block_thread, std::this_thread::get_id()) << where;
      }
}

TEST(CoreInternals, ParallelBlocksRethrowAfterJoining) {
  for (std::size_t thrower = 0; thrower < 4; ++thrower) {
    std::atomic<int> finished{0};
    try {
      fi::parallel_blocks(400, 4, 100, [&](std::size_t begin, std::size_t) {
        if (begin / 100 == thrower) throw std::runtime_error("block " + std::to_string(thrower));
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        ++finished;
      });
      ADD_FAILURE() << "no exception from block " << thrower;
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "block " + std::to_string(thrower));
    }
    EXPECT_EQ(finished.load(), 3);  // every other block ran to its end before the rethrow
  }
  // Several blocks throw: the lowest one's exception, even when it is thrown last (the others at once).
  for (std::size_t lowest = 0; lowest < 3; ++lowest) try {
      fi::parallel_blocks(400, 4, 100, [&](std::size_t begin, std::size_t) {
        const std::size_t block = begin / 100;
        if (block < lowest) return;
        if (block == lowest) std::this_thread::sleep_for(std::chrono::milliseconds(20));
        throw std::runtime_error("block " + std::to_string(block));
      });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "block " + std::to_string(lowest));
    }
}

// ---- traits.h and point_traits.h ------------------------------------------------------------------------

using K = CGAL::Epick;

TEST(CoreInternals, PointWithNormalDistance) {
  using Traits = FeatureRecon::Point_with_normal_traits<K>;
  using V = K::Vector_3;
  Traits traits;
  const auto oriented = traits.compute_feature_distance_object();
  traits.orientation = FeatureRecon::Normal_orientation::unoriented;
  const auto unoriented = traits.compute_feature_distance_object();
  // In [0, 4] (oriented) and [0, 2] (unoriented), also where rounding puts the cosine beyond +-1.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> c(-1, 1);
  for (int i = 0; i < 20000; ++i) {
    const V a(c(rng), c(rng), c(rng));
    for (const V& b : {a, -a, V(c(rng), c(rng), c(rng)), a * 3.0, -a * 0.7}) {
      const double d = oriented(a, b), e = unoriented(a, b);
      ASSERT_GE(d, 0.0);
      ASSERT_LE(d, 4.0);
      ASSERT_GE(e, 0.0);
      ASSERT_LE(e, 2.0);
      ASSERT_LE(e, d);
    }
    EXPECT_LE(oriented(a, a), 1e-15);
    EXPECT_NEAR(oriented(a, -a), 4.0, 1e-15);
    EXPECT_LE(unoriented(a, -a), 1e-15);
    EXPECT_LE(unoriented(a, -a * 0.7), 1e-15);
  }
  EXPECT_NEAR(oriented(V(1, 0, 0), V(0, 1, 0)), 2.0, 1e-15);
  EXPECT_NEAR(unoriented(V(1, 0, 0), V(-1, 1, 0)), 2 - std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(oriented(V(1, 0, 0), V(-1, 1, 0)), 2 + std::sqrt(2.0), 1e-15);
  // Tiny and huge normals neither underflow nor overflow.
  EXPECT_NEAR(oriented(V(1e-170, 0, 0), V(0, 1e-170, 0)), 2.0, 1e-15);
  EXPECT_NEAR(oriented(V(1e-170, 0, 0), V(1e-170, 1e-170, 0)), 2 - std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(oriented(V(1e160, 0, 0), V(1e160, 1e160, 0)), 2 - std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(oriented(V(1e-300, 0, 0), V(0, 0, 1e300)), 2.0, 1e-15);
  // -1 when a normal is zero or not finite, in any component.
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const V& bad : {V(0, 0, 0), V(inf, 0, 0), V(0, -inf, 1), V(nan, 0, 0), V(1, nan, 0), V(1, 0, nan)}) {
    EXPECT_EQ(oriented(bad, V(1, 0, 0)), -1.0) << bad;
    EXPECT_EQ(oriented(V(1, 0, 0), bad), -1.0) << bad;
    EXPECT_EQ(unoriented(bad, bad), -1.0) << bad;
  }
  const std::pair<K::Point_3, V> item(K::Point_3(1, 2, 3), V(0, 0, 1));
  EXPECT_EQ(traits.construct_point_object()(item), item.first);
  EXPECT_EQ(traits.construct_feature_object()(item), item.second);
}

TEST(CoreInternals, PixelTraits) {
  FeatureRecon::Grey_pixel grey;
  grey.column = 3;
  grey.row = 7;
  grey.value = 200;
  const FeatureRecon::Grey_pixel_traits gt;
  EXPECT_EQ(gt.construct_point_object()(grey), K::Point_2(3.5, 7.5));
  const auto g = gt.construct_feature_object()(grey);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0], 200);
  const auto gd = gt.compute_feature_distance_object();
  EXPECT_EQ(gd({0}, {255}), 1.0);
  EXPECT_EQ(gd({200}, {200}), 0.0);
  EXPECT_EQ(gd({100}, {151}), 51.0 * 51.0 / (255.0 * 255.0));

  FeatureRecon::Rgb_pixel rgb;
  rgb.column = 0;
  rgb.row = 4;
  rgb.rgb = {1, 2, 3};
  const FeatureRecon::Rgb_pixel_traits rt;
  EXPECT_EQ(rt.construct_point_object()(rgb), K::Point_2(0.5, 4.5));
  EXPECT_EQ(rt.construct_feature_object()(rgb), (std::array<std::uint8_t, 3>{1, 2, 3}));
  const auto rd = rt.compute_feature_distance_object();
  EXPECT_EQ(rd({0, 0, 0}, {255, 255, 255}), 1.0);
  EXPECT_DOUBLE_EQ(rd({255, 0, 0}, {0, 0, 0}), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(rd({10, 20, 30}, {20, 0, 30}), (100.0 + 400.0) / (3 * 255.0 * 255.0));
}

TEST(CoreInternals, PropertyMapTraitsAndPointTraits) {
  struct Item {
    double x, y, f;
  };
  const auto traits = FeatureRecon::make_property_map_traits<K, 2, Item>(
      [](const Item& i) { return K::Point_2(i.x, i.y); }, [](const Item& i) { return i.f; },
      [](double a, double b) { return (a - b) * (a - b); });
  const Item item{1, 2, 3};
  EXPECT_EQ(traits.construct_point_object()(item), K::Point_2(1, 2));
  EXPECT_EQ(traits.construct_feature_object()(item), 3.0);
  const auto d = traits.compute_feature_distance_object();
  EXPECT_EQ(d(1.0, 4.0), 9.0);
  // NaN: -1 (not a distance); overflow to infinity: the largest double.
  EXPECT_EQ(d(std::numeric_limits<double>::quiet_NaN(), 1.0), -1.0);
  EXPECT_EQ(d(-1e300, 1e300), std::numeric_limits<double>::max());

  const FeatureRecon::Point_traits<K::Point_3> pt;
  EXPECT_EQ(pt.compute_feature_distance_object()({}, {}), 0.0);
  EXPECT_EQ(pt.construct_point_object()(K::Point_3(1, 2, 3)), K::Point_3(1, 2, 3));
  static_assert(std::is_same<FeatureRecon::Default_traits_t<std::vector<K::Point_2>>,
                             FeatureRecon::Point_traits<K::Point_2>>::value);
  static_assert(std::is_same<FeatureRecon::Default_traits_t<std::vector<std::pair<K::Point_3, K::Vector_3>>>,
                             FeatureRecon::Point_with_normal_traits<K>>::value);
  static_assert(std::is_same<FeatureRecon::Default_traits_t<std::vector<FeatureRecon::Rgb_pixel>>,
                             FeatureRecon::Rgb_pixel_traits>::value);

  const FeatureRecon::Point_coordinate_traits<K::Point_3> p3;
  const K::Point_3 p(1.5, -2, 7);
  ASSERT_EQ(p3.dimension(p), 3u);
  EXPECT_EQ(p3.coordinate(p, 0), 1.5);
  EXPECT_EQ(p3.coordinate(p, 1), -2.0);
  EXPECT_EQ(p3.coordinate(p, 2), 7.0);
  const FeatureRecon::Point_coordinate_traits<std::vector<double>> pv;
  const std::vector<double> v{4, 5, 6, 7};
  ASSERT_EQ(pv.dimension(v), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(pv.coordinate(v, i), v[i]);
  const FeatureRecon::Point_coordinate_traits<std::array<float, 2>> pa;
  EXPECT_EQ(pa.dimension({0.5f, 8}), 2u);
  EXPECT_EQ(pa.coordinate({0.5f, 8}, 1), 8.0);
  static_assert(FeatureRecon::internal::Is_point_coordinate_traits<
                FeatureRecon::Point_coordinate_traits<K::Point_3>>::value);
}

// ---- the tests' own helpers (test_utilities.h)
// -------------------------------------------------------------

// throws_with() holds only for an exception of the given type whose message contains the part; it says what
// happened otherwise. thrown_message() gives the message or "no exception".
TEST(TestUtilities, ThrowsWithFailsUnlessTheMessageContainsThePart) {
  using FeatureRecon::test::thrown_message;
  using FeatureRecon::test::throws_with;
  auto refuse = [] { throw std::invalid_argument("f: x[3] is NaN"); };
  EXPECT_TRUE(throws_with<std::invalid_argument>(refuse, "x[3]"));
  EXPECT_TRUE(throws_with<std::logic_error>(refuse, ""));  // a base class catches it
  const ::testing::AssertionResult other = throws_with<std::invalid_argument>(refuse, "x[4]");
  EXPECT_FALSE(other);
  EXPECT_STREQ(other.message(), "the message \"f: x[3] is NaN\" does not contain \"x[4]\"");
  const ::testing::AssertionResult none = throws_with<std::invalid_argument>([] {}, "x[3]");
  EXPECT_FALSE(none);
  EXPECT_STREQ(none.message(), "no exception; expected one whose message contains \"x[3]\"");
  EXPECT_THROW((void)throws_with<std::invalid_argument>([] { throw std::runtime_error("r"); }, "r"),
               std::runtime_error);  // another type is not caught
  EXPECT_EQ(thrown_message<std::invalid_argument>(refuse), "f: x[3] is NaN");
  EXPECT_EQ(thrown_message<std::invalid_argument>([] {}), "no exception");
  EXPECT_THROW((void)thrown_message<std::invalid_argument>([] { throw std::runtime_error("r"); }),
               std::runtime_error);
}

// contains() quotes the text and the part both ways (EXPECT_FALSE prints the success message), the text cut
// after 2,000 characters with the count of the rest.
TEST(TestUtilities, ContainsQuotesTheTextAndThePart) {
  using FeatureRecon::test::contains;
  EXPECT_TRUE(contains("a <circle/>", "<circle"));
  EXPECT_TRUE(contains("abc", ""));
  EXPECT_STREQ(contains("a <circle/>", "<circle").message(), "\"a <circle/>\" contains \"<circle\"");
  const ::testing::AssertionResult missing = contains("f: x[3] is NaN", "x[4]");
  EXPECT_FALSE(missing);
  EXPECT_STREQ(missing.message(), "\"f: x[3] is NaN\" does not contain \"x[4]\"");
  EXPECT_FALSE(contains("", "a"));
  const std::string long_text = std::string(2000, 'a') + "bcd";
  EXPECT_TRUE(contains(long_text, "bcd"));  // found beyond the quoted part
  EXPECT_EQ(std::string(contains(long_text, "e").message()),
            "\"" + std::string(2000, 'a') + "\" (and 3 characters more) does not contain \"e\"");
  EXPECT_EQ(std::string(contains(std::string(2000, 'a'), "e").message()),
            "\"" + std::string(2000, 'a') + "\" does not contain \"e\"");
}

}  // namespace

// The shared union-find against components found by a breadth-first search: every set is named by its
// smallest element whatever the order of the unions, unite() says whether it joined two sets, and reset()
// starts over.
TEST(CoreInternals, UnionFindNamesEachSetByItsSmallestElement) {
  std::mt19937_64 rng(31);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 1 + rng() % 60, m = rng() % (2 * n);
    std::vector<std::array<std::uint32_t, 2>> edges(m);
    for (auto& e : edges) e = {std::uint32_t(rng() % n), std::uint32_t(rng() % n)};
    std::vector<std::vector<std::uint32_t>> adjacent(n);
    for (const auto& e : edges) {
      adjacent[e[0]].push_back(e[1]);
      adjacent[e[1]].push_back(e[0]);
    }
    std::vector<std::uint32_t> smallest(n, std::uint32_t(n));  // by breadth-first search from 0, 1, ...
    std::size_t components = 0;
    for (std::uint32_t s = 0; s < n; ++s) {
      if (smallest[s] != n) continue;
      ++components;
      std::vector<std::uint32_t> queue{s};
      smallest[s] = s;
      for (std::size_t q = 0; q < queue.size(); ++q)
        for (const std::uint32_t w : adjacent[queue[q]])
          if (smallest[w] == n) {
            smallest[w] = s;
            queue.push_back(w);
          }
    }
    FeatureRecon::internal::Union_find<std::uint32_t> sets(n + 5);
    sets.unite(0, std::uint32_t(n + 4));  // joined before the reset: forgotten
    sets.reset(n);
    ASSERT_EQ(sets.size(), n);
    std::size_t joins = 0;
    for (const auto& e : edges) joins += sets.unite(e[0], e[1]);
    EXPECT_EQ(n - joins, components);
    EXPECT_EQ(sets.labels(), smallest);
    for (const auto& e : edges) EXPECT_FALSE(sets.unite(e[1], e[0]));
    // Signed indices and the large-array allocator.
    FeatureRecon::internal::Union_find<std::int32_t,
                                       FeatureRecon::internal::Large_array_allocator<std::int32_t>>
        signed_sets(n);
    for (std::size_t k = m; k-- > 0;) signed_sets.unite(std::int32_t(edges[k][1]), std::int32_t(edges[k][0]));
    for (std::uint32_t v = 0; v < n; ++v)
      ASSERT_EQ(signed_sets.find(std::int32_t(v)), std::int32_t(smallest[v]));
    signed_sets.release();
    EXPECT_EQ(signed_sets.size(), 0u);
  }
}
