// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_ASSERTIONS_H
#define FEATURERECON_ASSERTIONS_H

#include <sstream>
#include <stdexcept>
#include <string>

namespace FeatureRecon {

/// Thrown when an internal precondition or assertion fails (checks active unless NDEBUG,
/// or always with FEATURERECON_DEBUG).
class Precondition_error : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace internal {
[[noreturn]] inline void precondition_fail(const char* kind, const char* expr, const char* file, int line) {
  std::ostringstream os;
  os << "FeatureRecon " << kind << " violated: " << expr << " (" << file << ":" << line << ")";
  throw Precondition_error(os.str());
}

/// Builds the message of a checked-argument error: "function: text".
template <class... Args>
std::string message(const char* function, const Args&... args) {
  std::ostringstream os;
  os << function << ": ";
  (os << ... << args);
  return os.str();
}

/// Throws std::invalid_argument with a message that starts with the function name.
template <class... Args>
[[noreturn]] void throw_invalid_argument(const char* function, const Args&... args) {
  throw std::invalid_argument(message(function, args...));
}
}  // namespace internal
}  // namespace FeatureRecon

#if !defined(NDEBUG) || defined(FEATURERECON_DEBUG)
#define FEATURERECON_precondition(EXPR)                                                                  \
  do {                                                                                                   \
    if (!(EXPR)) ::FeatureRecon::internal::precondition_fail("precondition", #EXPR, __FILE__, __LINE__); \
  } while (0)
#define FEATURERECON_assertion(EXPR)                                                                  \
  do {                                                                                                \
    if (!(EXPR)) ::FeatureRecon::internal::precondition_fail("assertion", #EXPR, __FILE__, __LINE__); \
  } while (0)
#else
#define FEATURERECON_precondition(EXPR) \
  do {                                  \
  } while (0)
#define FEATURERECON_assertion(EXPR) \
  do {                               \
  } while (0)
#endif

#endif  // FEATURERECON_ASSERTIONS_H
