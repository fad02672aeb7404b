// Test helpers shared by the subsystems' tests.
#ifndef FEATURERECON_TEST_TEST_UTILITIES_H
#define FEATURERECON_TEST_TEST_UTILITIES_H

#include <gtest/gtest.h>

#include <cstddef>
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

/// Whether `text` contains `part`; either way the result quotes the text (its first 2,000 characters) and the
/// part, so both `EXPECT_TRUE(contains(message, "x[3]"))` and `EXPECT_FALSE(contains(svg, "<circle"))` fail
/// readably.
inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  const std::size_t shown = 2000;
  const std::string quoted =
      "\"" + text.substr(0, shown) + "\"" +
      (text.size() > shown ? " (and " + std::to_string(text.size() - shown) + " characters more)"
                           : std::string());
  if (text.find(part) != std::string::npos)
    return ::testing::AssertionSuccess() << quoted << " contains \"" << part << "\"";
  return ::testing::AssertionFailure() << quoted << " does not contain \"" << part << "\"";
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
