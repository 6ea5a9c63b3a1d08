#include "fiberbridge/specimen/large_displacement.h"

namespace fiberbridge::specimen {

double large_displacement_F(double d, double a, double l1) {
  return 1 - 0.3 * (d / a) * (d / a) - 1.5 * (d * l1 / (a * a));
}

double end_block_N(double d, double a, double l1, double l2) {
  const double r = l2 / a;
  return 1 - r * r * r - 9.0 / 8.0 * (1 - r * r) * d * l1 / (a * a) -
         9.0 / 35.0 * (d / a) * (d / a);
}

} // namespace fiberbridge::specimen
