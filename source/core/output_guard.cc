#include "fiberbridge/core/output_guard.h"

#include <atomic>

namespace fiberbridge {

namespace {
std::atomic<bool> enabled{true};
}

void set_output_enabled(bool e) {
  enabled = e;
}
bool output_enabled() {
  return enabled;
}

} // namespace fiberbridge
