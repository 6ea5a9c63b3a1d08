#pragma once
// The paper's crack-tip rule (seed section 2.2, Fig. 2): along the crack plane, the strain normal
// to it reaches a threshold (1 %) at the tip; the crack grows as that point shifts between images.
// Here: the strain on the plane is interpolated from the points nearest to it, one station per
// column of points; the tip is where the run of stations at or above the threshold that starts at
// the notch root ends. What the rule's tip is in terms of the cohesive model's tip (the front of
// the bridging zone) and how it moves with the threshold and the strain window:
// docs/design.md section 6, "DIC frames in" and docs/dic_tip_rule.md.
#include "fiberbridge/dic/geometry.h"

#include <cmath>
#include <string>
#include <vector>

namespace fiberbridge::dic {

/// The crack-normal strain on the crack plane, one station per column of points, ordered by s.
/// A station whose points near the plane all failed has eyy NaN (correlation is lost where the
/// crack has opened).
struct PlaneProfile {
  std::vector<double> s;   ///< [m] from the notch root along the growth direction
  std::vector<double> eyy; ///< fraction; NaN: every point of the station failed
};

/// Stations from the points within 1.5 point spacings of the plane, grouped into columns (a gap in
/// s over half a spacing starts a new column); in each column the nearest valid point above and
/// below the plane are interpolated linearly to n = 0 (one alone is used when it lies within half
/// a spacing of the plane).
PlaneProfile crack_plane_profile(const PlaneFrame& frame, double spacing);

struct TipRule {
  double threshold = 0.01;
  /// A single station below the threshold inside the open run (noise, a bad subset) is bridged
  /// over; two in a row end the run.
  int bridged_dips = 1;
};

struct TipReading {
  bool found = false;       ///< false: no valid station on the plane (note says why)
  bool beyond_view = false; ///< the open run reaches the last station: the tip left the view
  double s = NAN;           ///< [m] the crossing, >= 0 (0: not open to the threshold at the root)
  double sd = NAN;          ///< [m] one standard deviation (spacing and noise)
  double noise = NAN;       ///< strain noise estimated ahead of the tip (fraction)
  double slope = NAN;       ///< [1/m] d eyy / d s at the crossing
  std::string note;
};

/// Applies the rule to one frame's profile. The uncertainty combines the gap between the two
/// stations that bracket the crossing (uniform within it: gap/sqrt(12)) and the strain noise over
/// the profile's slope there; the noise is the robust scatter of the profile's second differences
/// ahead of the tip (1.4826 MAD / sqrt(6) for white noise).
TipReading locate_tip(const PlaneProfile& profile, const TipRule& rule, double spacing);

} // namespace fiberbridge::dic
