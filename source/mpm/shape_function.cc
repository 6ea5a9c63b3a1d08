#include "fiberbridge/mpm/shape_function.h"

#include <cmath>

namespace fiberbridge::mpm {

AxisWeights linear_weights(double xp, double origin, double cell) {
  AxisWeights w;
  w.first = static_cast<int>(std::floor((xp - origin) / cell));
  const double t = (xp - origin) / cell - w.first;
  w.S[0] = 1 - t;
  w.S[1] = t;
  w.dS[0] = -1 / cell;
  w.dS[1] = 1 / cell;
  return w;
}

} // namespace fiberbridge::mpm
