// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// The samplers of discrete domains as the commands choose them: elimination, darts at a radius, darts at a
// count.
#ifndef FEATURERECON_CLI_DISCRETE_SAMPLERS_H
#define FEATURERECON_CLI_DISCRETE_SAMPLERS_H

#include <FeatureRecon/sampling/bilateral_dart_throwing.h>
#include <FeatureRecon/sampling/weighted_sample_elimination.h>

#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "cli/cli_common.h"

namespace FeatureRecon {
namespace cli {

/// What `sample` and `sample-image` ask of the samplers on discrete domains (points, pixels).
struct Sampler_request {
  std::string method;     ///< elimination or darts (sample-image also: continuous, run by itself)
  std::size_t count = 0;  ///< 0: not given
  double radius = 0;      ///< 0: not given
  double sigma_position = 1, sigma_feature = std::numeric_limits<double>::infinity();
  std::uint64_t seed = 0;
  bool periodic = false;
  std::vector<double> period;  ///< with periodic: the torus's periods (empty: the unit torus)
};

/// Runs the sampler `request` names on `items`; returns the kept indices and sets `used_radius`.
template <class Items, class Traits>
std::vector<std::size_t> run_sampler(const Items& items, const Traits& traits, const Sampler_request& request,
                                     Progress& progress, double& used_radius) {
  std::vector<std::size_t> kept;
  if (request.method == "elimination") {
    sampling::Elimination_options o;
    o.sigma_position = request.sigma_position;
    o.sigma_feature = request.sigma_feature;
    o.max_radius = request.radius;
    o.seed = request.seed;
    o.periodic = request.periodic;
    o.period = request.period;
    o.progress = std::ref(progress);
    try {
      used_radius =
          sampling::weighted_sample_elimination(items, request.count, std::back_inserter(kept), o, traits)
              .radius;
    } catch (const std::invalid_argument& e) {
      // The neighbour-list limit that a given radius hit is the command's argument: named as such (exit 2).
      if (request.radius > 0 && std::string(e.what()).find("max_neighbor_entries") != std::string::npos)
        throw Usage_error(
            "--radius " + json_number(request.radius) +
            " is too large for these items: give a smaller one, or none for the automatic radius (" +
            e.what() + ")");
      throw;
    }
  } else if (request.radius > 0) {
    sampling::Dart_throwing_options o;
    o.sigma_position = request.sigma_position;
    o.sigma_feature = request.sigma_feature;
    o.seed = request.seed;
    o.periodic = request.periodic;
    o.period = request.period;
    o.progress = std::ref(progress);
    o.max_accepted = request.count;  // with --count: the first M in the visiting order
    used_radius =
        sampling::bilateral_dart_throwing(items, request.radius, std::back_inserter(kept), o, traits).radius;
  } else {
    sampling::Dart_throwing_count_options o;
    o.darts.sigma_position = request.sigma_position;
    o.darts.sigma_feature = request.sigma_feature;
    o.darts.seed = request.seed;
    o.darts.periodic = request.periodic;
    o.darts.period = request.period;
    o.darts.progress = std::ref(progress);
    used_radius =
        sampling::bilateral_dart_throwing_count(items, request.count, std::back_inserter(kept), o, traits)
            .radius;
  }
  return kept;
}

}  // namespace cli
}  // namespace FeatureRecon

#endif  // FEATURERECON_CLI_DISCRETE_SAMPLERS_H
