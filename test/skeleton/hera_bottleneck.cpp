// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#include "hera_bottleneck.h"

#include <hera/bottleneck/bottleneck.h>

namespace FeatureRecon {
namespace test {
double hera_bottleneck(std::vector<std::pair<double, double>> a, std::vector<std::pair<double, double>> b) {
  return hera::bottleneckDistExact(a, b);
}
}  // namespace test
}  // namespace FeatureRecon
