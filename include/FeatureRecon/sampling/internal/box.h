// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SAMPLING_INTERNAL_BOX_H
#define FEATURERECON_SAMPLING_INTERNAL_BOX_H

#include <FeatureRecon/assertions.h>

#include <array>
#include <cmath>
#include <cstddef>

namespace FeatureRecon {
namespace sampling {
namespace internal {

/// \cond
/// Checks a 2D domain {x0, y0, x1, y1}: finite and within +-1e100 as the samplers' items, x0 <= x1 and
/// y0 <= y1 (throws std::invalid_argument naming fn).
inline const std::array<double, 4>& check_box(const std::array<double, 4>& box, const char* fn) {
  for (std::size_t k = 0; k < 4; ++k) {
    if (!std::isfinite(box[k]))
      FeatureRecon::internal::throw_invalid_argument(fn, "box[", k, "] is not finite (", box[k], ")");
    if (!(std::fabs(box[k]) <= 1e100))  // widths, areas and squared distances must stay finite
      FeatureRecon::internal::throw_invalid_argument(
          fn, "box[", k, "] = ", box[k],
          " lies beyond +-1e100 (widths and areas would overflow); "
          "scale the domain");
  }
  if (!(box[0] <= box[2] && box[1] <= box[3]))
    FeatureRecon::internal::throw_invalid_argument(fn,
                                                   "box must be {x0, y0, x1, y1} with x0 <= x1 and y0 <= y1");
  return box;
}
/// \endcond

}  // namespace internal
}  // namespace sampling
}  // namespace FeatureRecon

#endif  // FEATURERECON_SAMPLING_INTERNAL_BOX_H
