#pragma once
// Errors that reach the user. The CLI prints what() as one line on stderr and exits non-zero,
// so every message names the file, line or key and says what was expected.
#include <stdexcept>
#include <string>

namespace fiberbridge {

/// Bad input: a file, a column, a parameter or a combination of them that cannot be used.
class InputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A computation that could not reach a trustworthy result (no convergence, no steady state...).
class ComputationError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Thrown by a caller's progress hook to stop a run (the Python module on Ctrl-C, or when its
/// progress callback raises). Deliberately not a std::exception: the items that recover from a
/// failed case (a study level, a campaign group, a chain-study case, identify's misfit) catch
/// std::exception, and must not take a stop for a failed computation; it unwinds the whole run.
struct RunInterrupted {};

} // namespace fiberbridge
