// Test helpers shared by the subsystems' tests.
#ifndef FEATURERECON_TEST_TEST_UTILITIES_H
#define FEATURERECON_TEST_TEST_UTILITIES_H

#include <vector>

namespace FeatureRecon {
namespace test {

/// A progress callback that records every fraction it hears in `seen` and never stops the work.
inline auto recording_progress(std::vector<double>& seen) {
  return [&seen](double t) {
    seen.push_back(t);
    return true;
  };
}

}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_TEST_UTILITIES_H
