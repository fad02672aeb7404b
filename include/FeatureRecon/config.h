// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_CONFIG_H
#define FEATURERECON_CONFIG_H

#include <FeatureRecon/version.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>

namespace FeatureRecon {

/// Progress callback shared by every options struct: called with the fraction done in [0, 1];
/// returning false asks the algorithm to stop early (its result then says `interrupted`). The last call, with
/// 1, reports that the work is done: its answer is ignored and the result is complete (a stop asked there has
/// nothing left to save).
using Progress_callback = std::function<bool(double)>;

/// The value of an option that has a rule of its own (a `std::optional` field of an options struct; the
/// skeleton subsystem's): `options.delta = FeatureRecon::automatic;` asks for the rule the field documents.
/// Every such option means the same by its values: unset (`automatic`, the same as `std::nullopt`; beware
/// that `options.delta = {}` unsets it too) for the rule, a value for itself, 0 for off where a value can
/// turn the stage off (no simplification, no repair, no merging, no linking); a negative value is refused
/// (std::invalid_argument naming the option). The sampling options read 0 as automatic for lengths and
/// counts that cannot be 0 (Sampling_options::max_radius, domain_measure, ...), as their fields say.
inline constexpr std::nullopt_t automatic = std::nullopt;

/// Outcome of an algorithm run.
enum class Status {
  success,  ///< the run completed on non-degenerate input
  /// the run completed; the input was empty or lower-dimensional (documented per algorithm)
  degenerate_input,
  interrupted  ///< the progress callback returned false; the result is partial
};

/// The name of a status as written in the source: "success", "degenerate_input" or "interrupted".
inline const char* to_string(Status s) {
  switch (s) {
    case Status::success:
      return "success";
    case Status::degenerate_input:
      return "degenerate_input";
    case Status::interrupted:
      return "interrupted";
  }
  return "unknown";
}

/// Writes to_string(s).
inline std::ostream& operator<<(std::ostream& os, Status s) { return os << to_string(s); }

namespace internal {
/// Calls `progress` if set; returns false when the caller asked to stop.
inline bool report_progress(const Progress_callback& progress, double fraction) {
  return !progress || progress(fraction);
}
}  // namespace internal

}  // namespace FeatureRecon

#endif  // FEATURERECON_CONFIG_H
