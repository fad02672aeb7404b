// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_ASSERTIONS_H
#define FEATURERECON_ASSERTIONS_H

#include <cmath>
#include <optional>
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

/// Checks an option that has a rule of its own (see FeatureRecon::automatic): unset passes; a value must be
/// > 0, or >= 0 when `off` says what 0 means; it must be finite unless `infinity_allowed`; NaN never
/// passes. The message names the option, its range, its rule and its off value: "name must be finite and >=
/// 0 (FeatureRecon::automatic: rule; 0: off), got value".
inline void check_optional_length(const char* function, const std::optional<double>& value, const char* name,
                                  const char* rule, const char* off = nullptr,
                                  bool infinity_allowed = false) {
  if (!value) return;
  const double v = *value;
  if ((off != nullptr ? v >= 0 : v > 0) && (infinity_allowed || std::isfinite(v))) return;
  throw_invalid_argument(function, name, " must be ", infinity_allowed ? "" : "finite and ",
                         off != nullptr ? ">= 0" : "> 0", " (FeatureRecon::automatic: ", rule,
                         off != nullptr ? "; 0: " : "", off != nullptr ? off : "", "), got ", v);
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
