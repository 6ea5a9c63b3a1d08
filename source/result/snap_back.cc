#include "fiberbridge/result/rcurve.h"

namespace fiberbridge::result {

std::vector<SnapBack> find_snap_backs(const std::vector<RCurvePoint>& rows) {
  std::vector<SnapBack> found;
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    const double top = rows[i].load_point_opening;
    if (!(rows[i + 1].load_point_opening < top))
      continue;
    std::size_t j = i + 1, low = i + 1;
    while (j < rows.size() && rows[j].load_point_opening < top) {
      if (rows[j].load_point_opening < rows[low].load_point_opening)
        low = j;
      ++j;
    }
    found.push_back({i, low, j});
    // Row j (back at the earlier maximum, or the end) is where the next one may start.
    i = j - 1;
  }
  return found;
}

} // namespace fiberbridge::result
