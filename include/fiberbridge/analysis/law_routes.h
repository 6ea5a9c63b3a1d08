#pragma once
// The three routes from a record with a measured notch-root opening to the bridging law, on one
// grid (issue 12, part 3; docs/design.md section 6): the paper's Eq. 5/6 and the old
// sigma = dR/d delta, both from R(delta_root) (analysis/inverse.h), and the law identified by
// fitting a specimen model to the load-opening and crack-length records (identify/identify.h).
// Seed Eq. 4, dR/d delta = (sigma - delta sigma')/2, says what the old route gives: half the
// law where it is flat, and more than half where it softens (-delta sigma' > 0).
#include "fiberbridge/analysis/inverse.h"
#include "fiberbridge/law/traction_law.h"

#include <cmath>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// One route's law on the common grid and how it compares with the reference law.
struct RouteLaw {
  std::string name;           ///< "eq6", "dRdd", "identified" or "input"
  std::vector<double> sigma;  ///< on LawRoutes::delta [Pa]
  double peak = NAN;          ///< largest sigma on the grid [Pa]
  double delta_at_peak = NAN; ///< [m]
  double area = NAN;          ///< trapezoid over the grid [J/m^2] (= J_c; seed: not a judge)
  double peak_ratio = NAN;    ///< peak / the reference's peak
  double area_ratio = NAN;    ///< area / the reference's area
  /// RMS of (sigma - reference sigma) over the grid up to the larger of the two critical
  /// openings, divided by the reference's peak.
  double rms_rel = NAN;
};

struct LawRoutes {
  std::vector<double> delta;    ///< common grid from 0 past the largest critical opening [m]
  std::vector<RouteLaw> routes; ///< eq6, dRdd, identified, then input when given
  std::string reference;        ///< the route the ratios refer to: "input", else "eq6"
  /// Eq. 4's prediction of the old route's peak over the reference's: max over the grid of
  /// (sigma - delta sigma')/2 of the reference law, over its peak (NaN for the Eq. 6 reference,
  /// whose slope is not smooth enough to differentiate).
  double dRdd_peak_ratio_eq4 = NAN;
};

/// The routes on a grid of n_grid points over [0, 1.05 max critical opening] (Eq. 6 and dR/d
/// delta interpolated linearly from the extraction grid, zero beyond its delta_c). `input` may
/// be null (a real record: the law is not known); then Eq. 6 is the reference.
LawRoutes compare_law_routes(const ExtractedLaws& extracted, const law::TractionLaw& identified,
                             const law::TractionLaw* input, int n_grid = 2001);

} // namespace fiberbridge::analysis
