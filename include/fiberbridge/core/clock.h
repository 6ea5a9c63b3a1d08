#pragma once
// The wall time of a piece of work, in one place for every library (the models' wall_time_s, the
// studies' and the campaign's seconds, the Python module's compute_s).
#include <chrono>

namespace fiberbridge {

/// Seconds since `t0` on the steady clock.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace fiberbridge
