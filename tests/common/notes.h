#pragma once
// A run's notes, as the tests read them.
#include "fiberbridge/result/rcurve.h"

#include <string>

namespace fiberbridge::test_notes {

/// True when one of the run's notes starts with `start`.
inline bool has_note(const result::SimulationResult& r, const std::string& start) {
  for (const auto& n : r.notes)
    if (n.rfind(start, 0) == 0)
      return true;
  return false;
}

} // namespace fiberbridge::test_notes
