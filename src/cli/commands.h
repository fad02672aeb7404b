// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SRC_CLI_COMMANDS_H
#define FEATURERECON_SRC_CLI_COMMANDS_H

#include <string>
#include <vector>

namespace FeatureRecon {
namespace cli {

/// A subcommand of `featurerecon`: its name, one-line summary, --help text and entry point.
struct Command {
  const char* name;
  const char* summary;
  const char* help;
  int (*run)(const std::vector<std::string>& args);  ///< returns the exit status; throws on errors
};

/// Every subcommand, in the order `featurerecon --help` lists them.
const std::vector<Command>& commands();

int run_rips(const std::vector<std::string>& args);
int run_reeb(const std::vector<std::string>& args);
int run_evaluate_map(const std::vector<std::string>& args);
int run_synthetic_city(const std::vector<std::string>& args);
int run_skeleton(const std::vector<std::string>& args);
int run_sample(const std::vector<std::string>& args);
int run_sample_stats(const std::vector<std::string>& args);
int run_sample_image(const std::vector<std::string>& args);
int run_stipple(const std::vector<std::string>& args);
int run_bilateral_filter(const std::vector<std::string>& args);

}  // namespace cli
}  // namespace FeatureRecon

#endif  // FEATURERECON_SRC_CLI_COMMANDS_H
