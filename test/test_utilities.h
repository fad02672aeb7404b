// Test helpers shared by the subsystems' tests.
#ifndef FEATURERECON_TEST_TEST_UTILITIES_H
#define FEATURERECON_TEST_TEST_UTILITIES_H

#include <gtest/gtest.h>

#include <string>
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

/// Whether `call()` throws an `Exception` whose message contains `part`; the failure says what happened
/// instead (no exception, or the message). `EXPECT_TRUE(throws_with<std::invalid_argument>([&] { f(x); },
/// "x[3]"))`. An exception of another type is not caught: it fails the test as gtest reports it.
template <class Exception, class Call>
::testing::AssertionResult throws_with(Call&& call, const std::string& part) {
  try {
    call();
  } catch (const Exception& e) {
    if (std::string(e.what()).find(part) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "the message \"" << e.what() << "\" does not contain \"" << part << "\"";
  }
  return ::testing::AssertionFailure()
         << "no exception; expected one whose message contains \"" << part << "\"";
}

/// The message of the `Exception` that `call()` throws, or "no exception" when it returns (an exception of
/// another type is not caught).
template <class Exception, class Call>
std::string thrown_message(Call&& call) {
  try {
    call();
  } catch (const Exception& e) {
    return e.what();
  }
  return "no exception";
}

}  // namespace test
}  // namespace FeatureRecon

#endif  // FEATURERECON_TEST_TEST_UTILITIES_H
