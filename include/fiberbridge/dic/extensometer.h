#pragma once
// The virtual extensometer of the seed (section 2.2, after Lindhagen and Berglund): two material
// points above and below the initial notch root, on the crack plane's normal through it, half the
// gauge length from the plane; delta_root is the difference of their displacements normal to the
// plane. Each point's displacement is a local least-squares plane fit v = a + b ds + c dn of the
// valid points nearest to it on its own side of the crack (a fit across the crack would smear the
// opening into both points), points within half a spacing of the plane left out (their subsets
// straddle the crack).
#include "fiberbridge/dic/geometry.h"

#include <cmath>
#include <string>

namespace fiberbridge::dic {

struct ExtensometerReading {
  bool ok = false;
  double opening = NAN; ///< [m] v(upper) - v(lower): delta_root
  double sd = NAN;      ///< [m] one standard deviation, from the two fits' residuals
  double upper = NAN, lower = NAN;
  int n_upper = 0, n_lower = 0; ///< points in each fit
  std::string note;
};

/// `points_per_fit` nearest valid points (at least 4, within 3 spacings) on each side.
ExtensometerReading read_extensometer(const PlaneFrame& frame, double gauge_length, double spacing,
                                      int points_per_fit = 9);

} // namespace fiberbridge::dic
